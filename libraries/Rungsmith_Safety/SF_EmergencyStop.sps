$name SF_EmergencyStop
;@project description="Timing example of SF_EmergencyStop (Rungsmith_Safety): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="SF_EmergencyStop"
! type_pluto:00=A20,is3

! I0.0=Activate
! I0.1=S_EStopIn
! I0.2=S_StartReset
! I0.3=S_AutoReset
! I0.4=Reset
! Q0.0=S_EStopOut
! M0.0=Ready
! M0.1=Error
! R0.0=DiagCode

! pgm_pluto:00
! I0.0,static
! I0.1,static
! I0.2,static
! I0.3,static
! I0.4,static

S0.0_0
;@block SF_EmergencyStop Activate="Activate" S_EStopIn="S_EStopIn" S_StartReset="S_StartReset" S_AutoReset="S_AutoReset" Reset="Reset" Ready="Ready" S_EStopOut="S_EStopOut" Error="Error" DiagCode="DiagCode"
;@end
