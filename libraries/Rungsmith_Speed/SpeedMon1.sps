$name SpeedMon1
;@project description="Timing example of SpeedMon1 (Rungsmith_Speed): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="SpeedMon1"
! type_pluto:00=A20,is3

! R0.0=Speed
! R0.1=CompSpeed
! Q0.0=SpeedValid
! R0.2=ValidSpeed
! Q0.1=StandStill
! Q0.2=SafeLowSpeed

! pgm_pluto:00

S0.0_0
;@block SpeedMon1 Speed="Speed" CompSpeed="CompSpeed" MaxDiff="20" DiffDelay="0s50" LowSpeedLim="150" SpeedValid="SpeedValid" ValidSpeed="ValidSpeed" StandStill="StandStill" SafeLowSpeed="SafeLowSpeed"
;@end
