; Source: 000_f98263f7f3abf510.txt Part 2 section 5.3 (Declaration of I/O, non failsafe outputs)
! id_pluto:00=000000000000
! pgm_pluto:00
! Q0.10,static
S0.0_0
