$name Safety cell
;@project description="A press with an emergency stop, a two-hand control and contactor monitoring; a conveyor with a guard and a muted light curtain. Built from the Rungsmith_Safety blocks."

! id_pluto:00=000034AD4AE1
;@unit 00 description="Press"
! type_pluto:00=A20,is3
! id_pluto:01=000034AD4AE2
;@unit 01 description="Conveyor"
! type_pluto:01=A20,is3

! I0.0=EStop
! I0.1=ResetButton
! I0.2=TwoHandLeft
! I0.3=TwoHandRight
! I0.4=K1Feedback
! I0.5=K2Feedback
! I0.6=StrokeRequest
! Q0.0=K1
! Q0.1=K2
! M0.0=EStopOk
! M0.1=TwoHandOk
! M0.2=PressRun
! M0.3=ContactorsOn
! R0.0=EStopDiag
! R0.1=EDMDiag

! I1.0=GuardSwitch1
! I1.1=GuardSwitch2
! I1.2=LightCurtain
! I1.3=MutingEnable
! I1.4=ConveyorReset
! I1.5=MutingSensor1
! I1.6=MutingSensor2
! I1.7=MutingLampOk
! Q1.0=ConveyorDrive
! M1.0=GuardClosed
! M1.1=CurtainOk

! pgm_pluto:00
! Q0.10,a_pulse                ; dynamic A signal
! Q0.11,b_pulse                ; dynamic B signal
! I0.0,a_pulse,non_inv
! I0.1,static
! I0.2,static
! I0.3,static
! I0.4,static
! I0.5,static
! I0.6,static

S0.0_0                         ; press
;@block SF_EmergencyStop S_EStopIn="EStop" Reset="ResetButton" S_EStopOut="EStopOk" DiagCode="EStopDiag"
;@end
;@block SF_TwoHandControlTypeII S_Button1="TwoHandLeft" S_Button2="TwoHandRight" S_TwoHandOut="TwoHandOk"
;@end
PressRun = EStopOk * TwoHandOk * StrokeRequest
;@block SF_EDM S_OutControl="PressRun" S_EDM1="K1Feedback" S_EDM2="K2Feedback" MonitoringTime="0s20" Reset="ResetButton" S_EDM_Out="ContactorsOn" DiagCode="EDMDiag"
;@end
K1 = ContactorsOn
K2 = ContactorsOn

! pgm_pluto:01
! I1.0,static
! I1.1,static
! I1.2,static
! I1.3,static
! I1.4,static
! I1.5,static
! I1.6,static
! I1.7,static

S1.0_0                         ; conveyor
;@block SF_GuardMonitoring S_GuardSwitch1="GuardSwitch1" S_GuardSwitch2="GuardSwitch2" DiscrepancyTime="0s50" Reset="ConveyorReset" S_GuardMonitoring="GuardClosed"
;@end
;@block SF_MutingPar_2Sensor S_AOPD_In="LightCurtain" S_MutingSwitch11="MutingSensor1" S_MutingSwitch12="MutingSensor2" S_MutingLamp="MutingLampOk" DiscTimeEntry="0s50" MaxMutingTime="30s00" MutingEnable="MutingEnable" Reset="ConveyorReset" S_AOPD_Out="CurtainOk"
;@end
ConveyorDrive = GuardClosed * CurtainOk
