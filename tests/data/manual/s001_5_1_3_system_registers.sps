; Source: 001_6bd47eebc93f036b.txt section 5.1.3 (System registers)
; The example, followed by one line per row of the system register table
; (added: SR0.10 is written, the read-only ones are compared into memories).
! id_pluto:00=000000000000
! pgm_pluto:00
S0.0_0
Q0.12 = (SR0.40 < 180) * SM0.5

; System register table (added lines)
(SR0.10 = 201) = I0.1           ; SR_PlutoDisplay   W  Display figure
M0.40 = (SR0.40 > 0)            ; SR_SupplVolt      R  Supply voltage, 10 x Volt
M0.41 = (SR0.41 > 0)            ; SR_I5_Volt        R  Voltage analogue input I5, 10 x Volt
M0.42 = (SR0.42 > 0)            ; SR_Q16_Current    R  Current (mA) output no.Q16
M0.43 = (SR0.43 > 0)            ; SR_Q17_Current    R  Current (mA) output no.Q17
