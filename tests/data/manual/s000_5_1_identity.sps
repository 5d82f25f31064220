; Source: 000_f98263f7f3abf510.txt Part 2 section 5.1 (Identity, station number and Pluto family)
; Both examples (station 0 with identifier ffff00007FA3, station 23 without
; identifier), then one unit of each other family syntax (added, without
; identifier): id_pluto_Double (double family), id_pluto_ASi (Pluto AS-i),
; id_pluto_B42_ASi (Pluto B42 AS-i). Added: an empty code section per unit.
! id_pluto:00=ffff00007FA3
! id_pluto:23=000000000000
! id_pluto_Double:01=000000000000
! id_pluto_ASi:02=000000000000
! id_pluto_B42_ASi:03=000000000000
! pgm_pluto:00
S0.0_0
! pgm_pluto:23
S23.0_0
! pgm_pluto:01
S1.0_0
! pgm_pluto:02
S2.0_0
! pgm_pluto:03
S3.0_0
