$name SF_OutControl
;@project description="Timing example of SF_OutControl (Rungsmith_Safety): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="SF_OutControl"
! type_pluto:00=A20,is3

! I0.0=Activate
! I0.1=S_SafeControl
! I0.2=ProcessControl
! I0.3=StaticControl
! I0.4=S_StartReset
! I0.5=S_AutoReset
! I0.6=Reset
! M0.0=Ready
! Q0.0=S_OutControl
! M0.1=Error
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
;@block SF_OutControl Activate="Activate" S_SafeControl="S_SafeControl" ProcessControl="ProcessControl" StaticControl="StaticControl" S_StartReset="S_StartReset" S_AutoReset="S_AutoReset" Reset="Reset" Ready="Ready" S_OutControl="S_OutControl" Error="Error" DiagCode="DiagCode"
;@end
