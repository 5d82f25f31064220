$name EquivalentInputs
;@project description="Timing example of EquivalentInputs (Rungsmith_Basics): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="EquivalentInputs"
! type_pluto:00=A20,is3

! I0.0=Channel1
! I0.1=Channel2
! Q0.0=Out
! M0.0=Fault

! pgm_pluto:00
! I0.0,static
! I0.1,static

S0.0_0
;@block EquivalentInputs Channel1="Channel1" Channel2="Channel2" DiscrepancyTime="0s50" Out="Out" Fault="Fault"
;@end
