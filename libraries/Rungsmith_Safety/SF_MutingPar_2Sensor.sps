$name SF_MutingPar_2Sensor
;@project description="Timing example of SF_MutingPar_2Sensor (Rungsmith_Safety): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="SF_MutingPar_2Sensor"
! type_pluto:00=A20,is3

! I0.0=Activate
! I0.1=S_AOPD_In
! I0.2=S_MutingSwitch11
! I0.3=S_MutingSwitch12
! I0.4=S_MutingLamp
! I0.5=MutingEnable
! I0.6=S_StartReset
! I0.7=Reset
! M0.0=Ready
! Q0.0=S_AOPD_Out
! Q0.1=S_MutingActive
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
! I0.7,static

S0.0_0
;@block SF_MutingPar_2Sensor Activate="Activate" S_AOPD_In="S_AOPD_In" S_MutingSwitch11="S_MutingSwitch11" S_MutingSwitch12="S_MutingSwitch12" S_MutingLamp="S_MutingLamp" DiscTimeEntry="0s50" MaxMutingTime="2s00" MutingEnable="MutingEnable" S_StartReset="S_StartReset" Reset="Reset" Ready="Ready" S_AOPD_Out="S_AOPD_Out" S_MutingActive="S_MutingActive" Error="Error" DiagCode="DiagCode"
;@end
