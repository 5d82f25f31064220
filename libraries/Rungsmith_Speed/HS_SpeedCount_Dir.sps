$name HS_SpeedCount_Dir
;@project description="Timing example of HS_SpeedCount_Dir (Rungsmith_Speed): one instance, every pin bound to a name equal to the pin's."

! id_pluto_Double:00=000000000000
;@unit 00 description="HS_SpeedCount_Dir"
! type_pluto:00=D45,is3

! IA0.0=Input_A
! IA0.1=Input_B
! Q0.0=Valid
! R0.0=EdgePer10ms
! R0.1=PulsePerSec

! pgm_pluto:00
! IA0.0,counter_updown
! IA0.1,counter_updown

S0.0_0
;@block HS_SpeedCount_Dir Input_A="Input_A" Input_B="Input_B" Valid="Valid" EdgePer10ms="EdgePer10ms" PulsePerSec="PulsePerSec"
;@end
