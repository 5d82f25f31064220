; Source: 001_6bd47eebc93f036b.txt section 6.1 (Identity, station number)
; Both examples: station 0 with identifier ffff00007FA3, station 23 without
; identifier. Added: an empty code section for each unit.
! id_pluto:00=ffff00007FA3
! id_pluto:23=000000000000
! pgm_pluto:00
S0.0_0
! pgm_pluto:23
S23.0_0
