$name SF_EDM
;@project description="Timing example of SF_EDM (Rungsmith_Safety): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="SF_EDM"
! type_pluto:00=A20,is3

! I0.0=Activate
! I0.1=S_OutControl
! I0.2=S_EDM1
! I0.3=S_EDM2
! I0.4=S_StartReset
! I0.5=Reset
! M0.0=Ready
! Q0.0=S_EDM_Out
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
;@block SF_EDM Activate="Activate" S_OutControl="S_OutControl" S_EDM1="S_EDM1" S_EDM2="S_EDM2" MonitoringTime="0s30" S_StartReset="S_StartReset" Reset="Reset" Ready="Ready" S_EDM_Out="S_EDM_Out" Error="Error" DiagCode="DiagCode"
;@end
