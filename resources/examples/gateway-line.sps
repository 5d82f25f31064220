$name Gateway line
;@project description="A conveyor cell with an HMI on the simulated Ethernet gateway: Pluto 0 reports the emergency stop and its error code, Pluto 1 takes the HMI's start and speed"
;@gateway 0 type="GATE-E1" cycle_ms="48" timeout_ms="2000" to_pluto="0" expected="0-1"
;@gateway_area 0 0 pluto="0" io_type="100"
;@gateway_area 0 1 pluto="0" io_type="1"

! id_pluto_Double:00=000034AD4AE1
;@unit 00 description="Cell cabinet"
;@var I0.0 description="Emergency stop, channel A"
;@var I0.1 description="Emergency stop, channel B"
;@var I0.12 description="Reset push button"
;@var Q0.2 description="Conveyor contactor K1"
! type_pluto:00=B46,is3
! id_pluto:01=00003C19E2F0
;@unit 01 description="Conveyor drive"
;@var Q1.10 description="Drive enable"
;@var R1.0 description="Speed set by the HMI"
;@ext_comm 01 0 gateway="0" packet="0" timeout_ms="500"
! type_pluto:01=A20,is3
! I0.0=EStopA
! I0.1=EStopB
! I0.12=ResetButton
! Q0.2=ContactorK1
! M0.0=SafetyOK
! R0.5=StopCount
! Q1.10=DriveEnable
! M1.0=HmiValid
! M1.1=HmiStart
! R1.0=HmiSpeed

! pgm_pluto:00
! I0.0,static
! I0.1,static
! I0.12,a_pulse
! Q0.10,a_pulse
S0.0_0
;@network comment="Both channels of the emergency stop closed, reset given"
SafetyOK = EStopA * EStopB * (ResetButton + SafetyOK)
;@network comment="The conveyor contactor and the bus follow the safety circuit"
ContactorK1 = SafetyOK
GM0.0 = SafetyOK
;@network comment="Count the stops"
(StopCount++) = N(SafetyOK)
;@network comment="The error code to the gateway ten times a second (additional data area 0)"
;@block ToGateway_ErrorCode Send="SM0.4" Q="M0.10" lib="Ext01_1" version="1.0"
;@system ToGateway_ErrorCode Send="SM0.4" Q="M0.10"
;@end
;@network comment="The safety state and the stop count to the gateway (user block 1, area 1)"
;@block ToGateway_User_C Send="SM0.4" No="1" Reg_0="StopCount" Bit_0="SafetyOK" Bit_1="ContactorK1" Q="M0.11" lib="Ext01_1" version="1.0" #pin.Bit_2="M0.599" #pin.Bit_3="M0.598" #pin.Bit_4="M0.597" #pin.Bit_5="M0.596" #pin.Bit_6="M0.595" #pin.Bit_7="M0.594" #pin.Bit_8="M0.593" #pin.Bit_9="M0.592" #pin.Bit_10="M0.591" #pin.Bit_11="M0.590" #pin.Bit_12="M0.589" #pin.Bit_13="M0.588" #pin.Bit_14="M0.587" #pin.Bit_15="M0.586"
;@system ToGateway_User_C No="1" Send="SM0.4" Reg_0="StopCount" Bit_0="SafetyOK" Bit_1="ContactorK1" Bit_2="M0.599" Bit_3="M0.598" Bit_4="M0.597" Bit_5="M0.596" Bit_6="M0.595" Bit_7="M0.594" Bit_8="M0.593" Bit_9="M0.592" Bit_10="M0.591" Bit_11="M0.590" Bit_12="M0.589" Bit_13="M0.588" Bit_14="M0.587" Bit_15="M0.586" Q="M0.11"
;@end

! pgm_pluto:01
! Q1.10,static
S1.0_0
;@network comment="Data to Pluto packet 0 from the HMI: bit 0 start, register 0 the speed"
;@block ExtVarBlock BlockNo="0" Valid="HmiValid" Bit_0="HmiStart" Reg_0="HmiSpeed" lib="Ext01" version="1.0" #pin.Bit_1="M1.599" #pin.Bit_2="M1.598" #pin.Bit_3="M1.597" #pin.Bit_4="M1.596" #pin.Bit_5="M1.595" #pin.Bit_6="M1.594" #pin.Bit_7="M1.593" #pin.Bit_8="M1.592" #pin.Bit_9="M1.591" #pin.Bit_10="M1.590" #pin.Bit_11="M1.589" #pin.Bit_12="M1.588" #pin.Bit_13="M1.587" #pin.Bit_14="M1.586" #pin.Bit_15="M1.585" #pin.Reg_1="R1.149"
;@system ExtVarBlock BlockNo="0" Valid="HmiValid" Bit_0="HmiStart" Bit_1="M1.599" Bit_2="M1.598" Bit_3="M1.597" Bit_4="M1.596" Bit_5="M1.595" Bit_6="M1.594" Bit_7="M1.593" Bit_8="M1.592" Bit_9="M1.591" Bit_10="M1.590" Bit_11="M1.589" Bit_12="M1.588" Bit_13="M1.587" Bit_14="M1.586" Bit_15="M1.585" Reg_0="HmiSpeed" Reg_1="R1.149"
;@end
;@network comment="The drive runs while the HMI asks, its data is valid and the cell is safe"
DriveEnable = HmiValid * HmiStart * GM0.0
