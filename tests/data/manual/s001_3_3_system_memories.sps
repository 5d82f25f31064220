; Source: 001_6bd47eebc93f036b.txt section 3.3 (System memories (SM))
; The example, followed by one line per row of the system memory table
; (added: each address is read into a memory, the writable one is written).
! id_pluto:00=000000000000
! pgm_pluto:00
S0.0_0
Q0.10 = M0.1 * SM0.2  ;Flashing indicator

; System memory table (added lines)
M0.20 = SM0.0                   ; SM_StepNew       R
M0.21 = SM0.1                   ; SM_Ditto         R
M0.22 = SM0.2                   ; SM_Flash         R
M0.23 = SM0.3                   ; SM_1Hz           R
M0.24 = SM0.4                   ; SM_10Hz          R
M0.25 = SM0.5                   ; SM_FastFlash     R
M0.26 = SM0.6                   ; SM_DoubleFlash   R
M0.29 = SM0.9                   ; SM_SysInit       R
SM0.10 = I0.1                   ; SM_TimerFreeze   W (freezes the next timer in the code)
M0.39 = SM0.39                  ; SM_Button        R
