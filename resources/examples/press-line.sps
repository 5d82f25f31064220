$name Press line
;@project description="Two presses with light curtains, one emergency stop circuit" include_source="yes"

! id_pluto_Double:00=000034AD4AE1
;@unit 00 description="Main cabinet" remanent="R100-R103"
;@var I0.0 description="Emergency stop, channel A"
;@var I0.1 description="Emergency stop, channel B"
;@var I0.2 description="Light curtain press 1, OSSD"
;@var I0.3 description="Light curtain press 2, OSSD"
;@var I0.12 description="Reset push button with lamp"
;@var Q0.2 description="Main contactor K1"
;@var Q0.3 description="Main contactor K2"
;@var M0.0 description="Safety circuit closed"
;@var R0.10 description="Cycle counter" export="yes"
! type_pluto:00=B46,is3
! id_pluto:01=00003C19E2F0
;@unit 01 description="Press 2 cabinet"
! type_pluto:01=A20,is3
! I0.0=EStopA
! I0.1=EStopB
! I0.2=CurtainPress1
! I0.3=CurtainPress2
! I0.12=ResetButton
! Q0.2=ContactorK1
! Q0.3=ContactorK2

! pgm_pluto:00

! Q0.10,a_pulse                ; dynamic A signal for the inputs
! Q0.11,b_pulse                ; dynamic B signal for the inputs
! I0.0,a_pulse,non_inv
! I0.1,b_pulse,non_inv
! I0.2,static
! I0.3,static
! IQ0.12,a_pulse

! M0.0=SafetyOK
! R0.10=CycleCount

S0.0_0                         ; main sequence
SafetyOK = EStopA * EStopB * CurtainPress1 * CurtainPress2
ContactorK1 = SafetyOK * (P(ResetButton) + ContactorK1)
ContactorK2 = ContactorK1
Q0.12 = /ContactorK1           ; reset lamp lit while the contactors are off
(CycleCount++) = P(ContactorK1)

! pgm_pluto:01

! Q1.10,a_pulse
! I1.0,a_pulse
! I1.1,a_pulse

S1.0_0
Q1.2 = I1.0 * I1.1 * ContactorK1
Q1.3 = Q1.2
