$name SF_SafetyRequest
;@project description="Timing example of SF_SafetyRequest (Rungsmith_Safety): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="SF_SafetyRequest"
! type_pluto:00=A20,is3

! I0.0=Activate
! I0.1=S_OpMode
! I0.2=S_Acknowledge
! I0.3=Reset
! M0.0=Ready
! Q0.0=S_SafetyActive
! Q0.1=S_SafetyRequest
! M0.1=Error
! R0.0=DiagCode

! pgm_pluto:00
! I0.0,static
! I0.1,static
! I0.2,static
! I0.3,static

S0.0_0
;@block SF_SafetyRequest Activate="Activate" S_OpMode="S_OpMode" S_Acknowledge="S_Acknowledge" MonitoringTime="0s50" Reset="Reset" Ready="Ready" S_SafetyActive="S_SafetyActive" S_SafetyRequest="S_SafetyRequest" Error="Error" DiagCode="DiagCode"
;@end
