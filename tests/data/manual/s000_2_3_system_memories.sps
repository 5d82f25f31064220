; Source: 000_f98263f7f3abf510.txt Part 2 section 2.3 (System memories (SM))
; The example, followed by one line per row of the system memory table
; (added lines; each address is read into a memory). SM_.84 (SM_PlutoB) is
; for the A20 family only and is read in unit 0 (A20); SM_.15 (SM_PlutoB) is
; for B46, D45, AS-i and B42 AS-i only and is read in unit 1 (B46, double
; family). SM_.100 .. SM_.131 = SM_Pluto0_Present .. SM_Pluto31_Present.
! id_pluto:00=000000000000
! id_pluto_Double:01=000000000000
! pgm_pluto:00
S0.0_0
Q0.10 = M0.1 * SM0.2; Flashing indicator

; System memory table (added lines)
M0.20 = SM0.0                   ; SM_StepNew
M0.21 = SM0.1                   ; SM_Ditto
M0.22 = SM0.2                   ; SM_Flash
M0.23 = SM0.3                   ; SM_1Hz
M0.24 = SM0.4                   ; SM_10Hz
M0.25 = SM0.5                   ; SM_FastFlash
M0.26 = SM0.6                   ; SM_DoubleFlash
M0.29 = SM0.9                   ; SM_SysInit
M0.31 = SM0.11                  ; SM_Overflow
M0.32 = SM0.12                  ; SM_DivByZero
M0.39 = SM0.39                  ; SM_Button
M0.84 = SM0.84                  ; SM_PlutoB (A20 family only)
M0.100 = SM0.100                ; SM_Pluto0_Present
M0.131 = SM0.131                ; SM_Pluto31_Present
! pgm_pluto:01
S1.0_0
M1.15 = SM1.15                  ; SM_PlutoB (B46, D45, AS-i and B42 AS-i only)
