$name SF_GuardMonitoring
;@project description="Timing example of SF_GuardMonitoring (Rungsmith_Safety): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="SF_GuardMonitoring"
! type_pluto:00=A20,is3

! I0.0=Activate
! I0.1=S_GuardSwitch1
! I0.2=S_GuardSwitch2
! I0.3=S_StartReset
! I0.4=S_AutoReset
! I0.5=Reset
! M0.0=Ready
! Q0.0=S_GuardMonitoring
! M0.1=Error
! R0.0=DiagCode

! pgm_pluto:00
! I0.0,static
! I0.1,static
! I0.2,static
! I0.3,static
! I0.4,static
! I0.5,static

S0.0_0
;@block SF_GuardMonitoring Activate="Activate" S_GuardSwitch1="S_GuardSwitch1" S_GuardSwitch2="S_GuardSwitch2" DiscrepancyTime="0s50" S_StartReset="S_StartReset" S_AutoReset="S_AutoReset" Reset="Reset" Ready="Ready" S_GuardMonitoring="S_GuardMonitoring" Error="Error" DiagCode="DiagCode"
;@end
