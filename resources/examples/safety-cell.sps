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
;@block SF_EmergencyStop S_EStopIn="EStop" Reset="ResetButton" S_EStopOut="EStopOk" DiagCode="EStopDiag" lib="Rungsmith_Safety" version="1.0" #pin.Activate="M0.599" #pin.S_StartReset="M0.598" #pin.S_AutoReset="M0.597" #pin.Ready="M0.596" #pin.Error="M0.595" #state="R0.149" #next="R0.148" #resetEdge="M0.594"
S(M0.599) = /M0.599
; R_TRIGatReset: the rising edge of Reset, every scan, first
M0.594 = P(ResetButton)
(R0.148 = R0.149)
; 0000 -> 8001
(R0.148 = -32767) = (R0.149=0)
; 8001: not S_StartReset -> 8002, S_StartReset and not S_EStopIn -> 8004, S_EStopIn and S_StartReset -> 8000
(R0.148 = -32768) = (R0.149=-32767) * EStop * M0.598
(R0.148 = -32764) = (R0.149=-32767) * M0.598 * /EStop
(R0.148 = -32766) = (R0.149=-32767) * /M0.598
; 8002: S_EStopIn -> 8003
(R0.148 = -32765) = (R0.149=-32766) * EStop
; 8003: Reset and no edge -> C001, not S_EStopIn -> 8002, edge -> 8000
(R0.148 = -32768) = (R0.149=-32765) * M0.594
(R0.148 = -32766) = (R0.149=-32765) * /EStop
(R0.148 = -16383) = (R0.149=-32765) * ResetButton * /M0.594
; C001: not Reset -> 8003
(R0.148 = -32765) = (R0.149=-16383) * /ResetButton
; 8004: S_EStopIn and not S_AutoReset -> 8005, S_EStopIn and S_AutoReset -> 8000
(R0.148 = -32768) = (R0.149=-32764) * EStop * M0.597
(R0.148 = -32763) = (R0.149=-32764) * EStop * /M0.597
; 8005: Reset and no edge -> C002, not S_EStopIn -> 8004, edge or S_AutoReset -> 8000
(R0.148 = -32768) = (R0.149=-32763) * (M0.594 + M0.597)
(R0.148 = -32764) = (R0.149=-32763) * /EStop
(R0.148 = -16382) = (R0.149=-32763) * ResetButton * /M0.594
; C002: not Reset -> 8005
(R0.148 = -32763) = (R0.149=-16382) * /ResetButton
; 8000: not S_EStopIn -> 8004
(R0.148 = -32764) = (R0.149=-32768) * /EStop
; Activate off: 0000
(R0.148 = 0) = /M0.599
(R0.149 = R0.148)
M0.596 = (R0.149<0)
EStopOk = (R0.149=-32768)
M0.595 = (R0.149=-16383) + (R0.149=-16382)
(EStopDiag = R0.149)
;@end
;@block SF_TwoHandControlTypeII S_Button1="TwoHandLeft" S_Button2="TwoHandRight" S_TwoHandOut="TwoHandOk" lib="Rungsmith_Safety" version="1.0" #pin.Activate="M0.593" #pin.Ready="M0.592" #pin.Error="M0.591" #pin.DiagCode="R0.147" #state="R0.146" #next="R0.145"
S(M0.593) = /M0.593
(R0.145 = R0.146)
; 0000 -> 8001
(R0.145 = -32767) = (R0.146=0)
; 8001: B1 and B2 -> C003, B1 -> C001, B2 -> C002, else -> 8004
(R0.145 = -32764) = (R0.146=-32767)
(R0.145 = -16382) = (R0.146=-32767) * TwoHandRight
(R0.145 = -16383) = (R0.146=-32767) * TwoHandLeft
(R0.145 = -16381) = (R0.146=-32767) * TwoHandLeft * TwoHandRight
; 8004: B1 and B2 -> 8000, B1 -> 8005, B2 -> 8006
(R0.145 = -32762) = (R0.146=-32764) * TwoHandRight
(R0.145 = -32763) = (R0.146=-32764) * TwoHandLeft
(R0.145 = -32768) = (R0.146=-32764) * TwoHandLeft * TwoHandRight
; 8005: not B1 and not B2 -> 8004, not B1 and B2 -> 8019, B1 and B2 -> 8000
(R0.145 = -32768) = (R0.146=-32763) * TwoHandLeft * TwoHandRight
(R0.145 = -32743) = (R0.146=-32763) * /TwoHandLeft * TwoHandRight
(R0.145 = -32764) = (R0.146=-32763) * /TwoHandLeft * /TwoHandRight
; 8006: not B1 and not B2 -> 8004, B1 and not B2 -> 8019, B1 and B2 -> 8000
(R0.145 = -32768) = (R0.146=-32762) * TwoHandLeft * TwoHandRight
(R0.145 = -32743) = (R0.146=-32762) * TwoHandLeft * /TwoHandRight
(R0.145 = -32764) = (R0.146=-32762) * /TwoHandLeft * /TwoHandRight
; 8007: B1 and B2 -> 8009, not B1 and B2 -> 8008, not B1 and not B2 -> 8004
(R0.145 = -32764) = (R0.146=-32761) * /TwoHandLeft * /TwoHandRight
(R0.145 = -32760) = (R0.146=-32761) * /TwoHandLeft * TwoHandRight
(R0.145 = -32759) = (R0.146=-32761) * TwoHandLeft * TwoHandRight
; 8008: B1 and B2 -> 8009, B1 and not B2 -> 8007, not B1 and not B2 -> 8004
(R0.145 = -32764) = (R0.146=-32760) * /TwoHandLeft * /TwoHandRight
(R0.145 = -32761) = (R0.146=-32760) * TwoHandLeft * /TwoHandRight
(R0.145 = -32759) = (R0.146=-32760) * TwoHandLeft * TwoHandRight
; 8009: not B1 and B2 -> 8008, B1 and not B2 -> 8007, not B1 and not B2 -> 8004
(R0.145 = -32764) = (R0.146=-32759) * /TwoHandLeft * /TwoHandRight
(R0.145 = -32761) = (R0.146=-32759) * TwoHandLeft * /TwoHandRight
(R0.145 = -32760) = (R0.146=-32759) * /TwoHandLeft * TwoHandRight
; 8019: not B1 and not B2 -> 8004
(R0.145 = -32764) = (R0.146=-32743) * /TwoHandLeft * /TwoHandRight
; 8000: B1 and not B2 -> 8007, not B1 and B2 -> 8008, not B1 and not B2 -> 8004
(R0.145 = -32764) = (R0.146=-32768) * /TwoHandLeft * /TwoHandRight
(R0.145 = -32760) = (R0.146=-32768) * /TwoHandLeft * TwoHandRight
(R0.145 = -32761) = (R0.146=-32768) * TwoHandLeft * /TwoHandRight
; C001, C002, C003: not B1 and not B2 -> 8004
(R0.145 = -32764) = ((R0.146=-16383) + (R0.146=-16382) + (R0.146=-16381)) * /TwoHandLeft * /TwoHandRight
; Activate off: 0000
(R0.145 = 0) = /M0.593
(R0.146 = R0.145)
M0.592 = (R0.146<0)
TwoHandOk = (R0.146=-32768)
M0.591 = (R0.146=-16383) + (R0.146=-16382) + (R0.146=-16381)
(R0.147 = R0.146)
;@end
PressRun = EStopOk * TwoHandOk * StrokeRequest
;@block SF_EDM S_OutControl="PressRun" S_EDM1="K1Feedback" S_EDM2="K2Feedback" MonitoringTime="0s20" Reset="ResetButton" S_EDM_Out="ContactorsOn" DiagCode="EDMDiag" lib="Rungsmith_Safety" version="1.0" #pin.Activate="M0.590" #pin.S_StartReset="M0.589" #pin.Ready="M0.588" #pin.Error="M0.587" #state="R0.144" #next="R0.143" #resetEdge="M0.586" #controlEdge="M0.585" #offElapsed="M0.584" #onElapsed="M0.583"
S(M0.590) = /M0.590
; the rising edges of Reset and S_OutControl, every scan, first
M0.586 = P(ResetButton)
M0.585 = P(PressRun)
; MonitoringTime: while the scan starts in 8810 (switched off) or in 8000 (switched on)
M0.584 = (R0.144=-30704) * TON(0s20)
M0.583 = (R0.144=-32768) * TON(0s20)
(R0.143 = R0.144)
; 0000 -> 8401
(R0.143 = -31743) = (R0.144=0)
; 8401: Reset and no edge and not S_StartReset -> C001, edge and S_OutControl edge -> C100, edge or S_StartReset -> 8810
(R0.143 = -30704) = (R0.144=-31743) * (M0.586 + M0.589)
(R0.143 = -16128) = (R0.144=-31743) * M0.586 * M0.585
(R0.143 = -16383) = (R0.144=-31743) * ResetButton * /M0.586 * /M0.589
; C001: not Reset -> 8401
(R0.143 = -31743) = (R0.144=-16383) * /ResetButton
; 8810: time and neither feedback -> C060, time and not EDM1 -> C040, time and not EDM2 -> C050,
; S_OutControl and neither -> C030, and not EDM1 -> C010, and not EDM2 -> C020, S_OutControl -> 8000
(R0.143 = -32768) = (R0.144=-30704) * PressRun
(R0.143 = -16352) = (R0.144=-30704) * PressRun * /K2Feedback
(R0.143 = -16368) = (R0.144=-30704) * PressRun * /K1Feedback
(R0.143 = -16336) = (R0.144=-30704) * PressRun * /K1Feedback * /K2Feedback
(R0.143 = -16304) = (R0.144=-30704) * M0.584 * /K2Feedback
(R0.143 = -16320) = (R0.144=-30704) * M0.584 * /K1Feedback
(R0.143 = -16288) = (R0.144=-30704) * M0.584 * /K1Feedback * /K2Feedback
; 8000: time and both feedbacks -> C090, time and EDM1 -> C070, time and EDM2 -> C080, not S_OutControl -> 8810
(R0.143 = -30704) = (R0.144=-32768) * /PressRun
(R0.143 = -16256) = (R0.144=-32768) * M0.583 * K2Feedback
(R0.143 = -16272) = (R0.144=-32768) * M0.583 * K1Feedback
(R0.143 = -16240) = (R0.144=-32768) * M0.583 * K1Feedback * K2Feedback
; C010 ... C090, C100: edge and not S_OutControl -> 8810
(R0.143 = -30704) = ((R0.144=-16368) + (R0.144=-16352) + (R0.144=-16336) + (R0.144=-16320) + (R0.144=-16304) + (R0.144=-16288) + (R0.144=-16272) + (R0.144=-16256) + (R0.144=-16240) + (R0.144=-16128)) * M0.586 * /PressRun
; Activate off: 0000
(R0.143 = 0) = /M0.590
(R0.144 = R0.143)
M0.588 = (R0.144<0)
ContactorsOn = (R0.144=-32768)
M0.587 = (R0.144=-16383) + (R0.144=-16368) + (R0.144=-16352) + (R0.144=-16336) + (R0.144=-16320) + (R0.144=-16304) + (R0.144=-16288) + (R0.144=-16272) + (R0.144=-16256) + (R0.144=-16240) + (R0.144=-16128)
(EDMDiag = R0.144)
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
;@block SF_GuardMonitoring S_GuardSwitch1="GuardSwitch1" S_GuardSwitch2="GuardSwitch2" DiscrepancyTime="0s50" Reset="ConveyorReset" S_GuardMonitoring="GuardClosed" lib="Rungsmith_Safety" version="1.0" #pin.Activate="M1.599" #pin.S_StartReset="M1.598" #pin.S_AutoReset="M1.597" #pin.Ready="M1.596" #pin.Error="M1.595" #pin.DiagCode="R1.149" #state="R1.148" #next="R1.147" #resetEdge="M1.594" #elapsed="M1.593"
S(M1.599) = /M1.599
; R_TRIGatReset: the rising edge of Reset, every scan, first
M1.594 = P(ConveyorReset)
; DiscrepancyTimer: runs while the scan starts in 8004 or 8014
M1.593 = ((R1.148=-32764) + (R1.148=-32748)) * TON(0s50)
(R1.147 = R1.148)
; 0000 -> 8001
(R1.147 = -32767) = (R1.148=0)
; 8001: not S1 or not S2 -> 8002, S1 and S2 and not S_StartReset -> 8003, S1 and S2 and S_StartReset -> 8000
(R1.147 = -32768) = (R1.148=-32767) * GuardSwitch1 * GuardSwitch2 * M1.598
(R1.147 = -32765) = (R1.148=-32767) * GuardSwitch1 * GuardSwitch2 * /M1.598
(R1.147 = -32766) = (R1.148=-32767) * (/GuardSwitch1 + /GuardSwitch2)
; 8002: not S1 and not S2 -> 8012
(R1.147 = -32750) = (R1.148=-32766) * /GuardSwitch1 * /GuardSwitch2
; 8003: Reset and no edge -> C001, not S1 or not S2 -> 8002, edge -> 8000
(R1.147 = -32768) = (R1.148=-32765) * M1.594
(R1.147 = -32766) = (R1.148=-32765) * (/GuardSwitch1 + /GuardSwitch2)
(R1.147 = -16383) = (R1.148=-32765) * ConveyorReset * /M1.594
; 8012: S1 -> 8004, S2 -> 8014
(R1.147 = -32748) = (R1.148=-32750) * GuardSwitch2
(R1.147 = -32764) = (R1.148=-32750) * GuardSwitch1
; 8004: timer -> C011, not S1 -> 8002, S2 -> 8005
(R1.147 = -32763) = (R1.148=-32764) * GuardSwitch2
(R1.147 = -32766) = (R1.148=-32764) * /GuardSwitch1
(R1.147 = -16367) = (R1.148=-32764) * M1.593
; 8014: timer -> C012, not S2 -> 8002, S1 -> 8005
(R1.147 = -32763) = (R1.148=-32748) * GuardSwitch1
(R1.147 = -32766) = (R1.148=-32748) * /GuardSwitch2
(R1.147 = -16366) = (R1.148=-32748) * M1.593
; 8005: not S1 or not S2 -> 8002, not S_AutoReset -> 8003, S_AutoReset -> 8000
(R1.147 = -32768) = (R1.148=-32763) * M1.597
(R1.147 = -32765) = (R1.148=-32763) * /M1.597
(R1.147 = -32766) = (R1.148=-32763) * (/GuardSwitch1 + /GuardSwitch2)
; 8000: not S1 or not S2 -> 8002
(R1.147 = -32766) = (R1.148=-32768) * (/GuardSwitch1 + /GuardSwitch2)
; C001: not Reset -> 8003
(R1.147 = -32765) = (R1.148=-16383) * /ConveyorReset
; C011, C012: not S1 and not S2 -> 8012
(R1.147 = -32750) = ((R1.148=-16367) + (R1.148=-16366)) * /GuardSwitch1 * /GuardSwitch2
; Activate off: 0000
(R1.147 = 0) = /M1.599
(R1.148 = R1.147)
M1.596 = (R1.148<0)
GuardClosed = (R1.148=-32768)
M1.595 = (R1.148=-16383) + (R1.148=-16367) + (R1.148=-16366)
(R1.149 = R1.148)
;@end
;@block SF_MutingPar_2Sensor S_AOPD_In="LightCurtain" S_MutingSwitch11="MutingSensor1" S_MutingSwitch12="MutingSensor2" S_MutingLamp="MutingLampOk" DiscTimeEntry="0s50" MaxMutingTime="30s00" MutingEnable="MutingEnable" Reset="ConveyorReset" S_AOPD_Out="CurtainOk" lib="Rungsmith_Safety" version="1.0" #pin.Activate="M1.592" #pin.S_StartReset="M1.591" #pin.Ready="M1.590" #pin.S_MutingActive="M1.589" #pin.Error="M1.588" #pin.DiagCode="R1.146" #state="R1.145" #next="R1.144" #resetEdge="M1.587" #rise11="M1.586" #rise12="M1.585" #discElapsed="M1.584" #mutingElapsed="M1.583"
S(M1.592) = /M1.592
; the rising edges of Reset and of both sensors, every scan, first
M1.587 = P(ConveyorReset)
M1.586 = P(MutingSensor1)
M1.585 = P(MutingSensor2)
; DiscTimeEntry: while the scan starts in 8011 or 8021; MaxMutingTime: in 8011, 8021 or 8012
M1.584 = ((R1.145=-32751) + (R1.145=-32735)) * TON(0s50)
M1.583 = ((R1.145=-32751) + (R1.145=-32735) + (R1.145=-32750)) * TON(30s00)
(R1.144 = R1.145)
; 0000 -> 8001
(R1.144 = -32767) = (R1.145=0)
; 8001: Reset and no edge and not S_StartReset -> C001, edge or S_StartReset -> 8005
(R1.144 = -32763) = (R1.145=-32767) * (M1.587 + M1.591)
(R1.144 = -16383) = (R1.145=-32767) * ConveyorReset * /M1.587 * /M1.591
; C001: not Reset -> 8001
(R1.144 = -32767) = (R1.145=-16383) * /ConveyorReset
; 8005: not AOPD -> 8002, not lamp -> C003, otherwise 8000
(R1.144 = -32768) = (R1.145=-32763)
(R1.144 = -16381) = (R1.145=-32763) * /MutingLampOk
(R1.144 = -32766) = (R1.145=-32763) * /LightCurtain
; 8000: a sensor rising without MutingEnable -> C004, not AOPD -> 8002, not lamp -> C003,
; with MutingEnable: both rising -> 8012, 11 rising with 12 free -> 8011, 12 rising with 11 free -> 8021
(R1.144 = -32735) = (R1.145=-32768) * MutingEnable * M1.585 * /MutingSensor1
(R1.144 = -32751) = (R1.145=-32768) * MutingEnable * M1.586 * /MutingSensor2
(R1.144 = -32750) = (R1.145=-32768) * MutingEnable * M1.586 * M1.585
(R1.144 = -16381) = (R1.145=-32768) * /MutingLampOk
(R1.144 = -32766) = (R1.145=-32768) * /LightCurtain
(R1.144 = -16380) = (R1.145=-32768) * (M1.586 + M1.585) * /MutingEnable
; 8011: 11 free -> C004, DiscTimeEntry -> C007, MaxMutingTime -> C006, not AOPD -> 8002, not lamp -> C003, 12 -> 8012
(R1.144 = -32750) = (R1.145=-32751) * MutingSensor2
(R1.144 = -16381) = (R1.145=-32751) * /MutingLampOk
(R1.144 = -32766) = (R1.145=-32751) * /LightCurtain
(R1.144 = -16378) = (R1.145=-32751) * M1.583
(R1.144 = -16377) = (R1.145=-32751) * M1.584
(R1.144 = -16380) = (R1.145=-32751) * /MutingSensor1
; 8021: 12 free -> C004, DiscTimeEntry -> C007, MaxMutingTime -> C006, not AOPD -> 8002, not lamp -> C003, 11 -> 8012
(R1.144 = -32750) = (R1.145=-32735) * MutingSensor1
(R1.144 = -16381) = (R1.145=-32735) * /MutingLampOk
(R1.144 = -32766) = (R1.145=-32735) * /LightCurtain
(R1.144 = -16378) = (R1.145=-32735) * M1.583
(R1.144 = -16377) = (R1.145=-32735) * M1.584
(R1.144 = -16380) = (R1.145=-32735) * /MutingSensor2
; 8012: MaxMutingTime -> C006, not lamp -> C003, a sensor free and AOPD -> 8000, a sensor free and not AOPD -> 8002
(R1.144 = -32766) = (R1.145=-32750) * (/MutingSensor1 + /MutingSensor2) * /LightCurtain
(R1.144 = -32768) = (R1.145=-32750) * (/MutingSensor1 + /MutingSensor2) * LightCurtain
(R1.144 = -16381) = (R1.145=-32750) * /MutingLampOk
(R1.144 = -16378) = (R1.145=-32750) * M1.583
; 8002: AOPD -> 8003
(R1.144 = -32765) = (R1.145=-32766) * LightCurtain
; 8003: Reset and no edge -> C002, edge -> 8005
(R1.144 = -32763) = (R1.145=-32765) * M1.587
(R1.144 = -16382) = (R1.145=-32765) * ConveyorReset * /M1.587
; C002: not Reset -> 8003
(R1.144 = -32765) = (R1.145=-16382) * /ConveyorReset
; C003: lamp -> 8003
(R1.144 = -32765) = (R1.145=-16381) * MutingLampOk
; C004, C006, C007: both sensors free -> 8003
(R1.144 = -32765) = ((R1.145=-16380) + (R1.145=-16378) + (R1.145=-16377)) * /MutingSensor1 * /MutingSensor2
; Activate off: 0000
(R1.144 = 0) = /M1.592
(R1.145 = R1.144)
M1.590 = (R1.145<0)
CurtainOk = (R1.145=-32768) + (R1.145=-32751) + (R1.145=-32735) + (R1.145=-32750)
M1.589 = (R1.145=-32750)
M1.588 = (R1.145=-16383) + (R1.145=-16382) + (R1.145=-16381) + (R1.145=-16380) + (R1.145=-16378) + (R1.145=-16377)
(R1.146 = R1.145)
;@end
ConveyorDrive = GuardClosed * CurtainOk
