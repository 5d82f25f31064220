$name HS_SpeedCount_Up
;@project description="Timing example of HS_SpeedCount_Up (Rungsmith_Speed): one instance, every pin bound to a name equal to the pin's."

! id_pluto_Double:00=000000000000
;@unit 00 description="HS_SpeedCount_Up"
! type_pluto:00=D45,is3

! IA0.0=Input
! Q0.0=Valid
! R0.0=EdgePer10ms
! R0.1=PulsePerSec

! pgm_pluto:00
! IA0.0,counter_up

S0.0_0
;@block HS_SpeedCount_Up Input="Input" Valid="Valid" EdgePer10ms="EdgePer10ms" PulsePerSec="PulsePerSec"
;@end
