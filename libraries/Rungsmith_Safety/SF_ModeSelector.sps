$name SF_ModeSelector
;@project description="Timing example of SF_ModeSelector (Rungsmith_Safety): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="SF_ModeSelector"
! type_pluto:00=A20,is3

! I0.0=Activate
! I0.1=S_Mode0
! I0.2=S_Mode1
! I0.3=S_Mode2
! I0.4=S_Unlock
! I0.5=S_SetMode
! I0.6=Reset
! M0.0=Ready
! Q0.0=S_Mode0Sel
! Q0.1=S_Mode1Sel
! Q0.2=S_Mode2Sel
! M0.1=S_AnyModeSel
! M0.2=Error
! R0.0=DiagCode

! pgm_pluto:00
! I0.0,static
! I0.1,static
! I0.2,static
! I0.3,static
! I0.4,static
! I0.5,static
! I0.6,static

S0.0_0
;@block SF_ModeSelector Activate="Activate" S_Mode0="S_Mode0" S_Mode1="S_Mode1" S_Mode2="S_Mode2" S_Unlock="S_Unlock" S_SetMode="S_SetMode" ModeMonitorTime="2s00" Reset="Reset" Ready="Ready" S_Mode0Sel="S_Mode0Sel" S_Mode1Sel="S_Mode1Sel" S_Mode2Sel="S_Mode2Sel" S_AnyModeSel="S_AnyModeSel" Error="Error" DiagCode="DiagCode"
;@end
