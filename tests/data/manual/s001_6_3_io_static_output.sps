; Source: 001_6bd47eebc93f036b.txt section 6.3 (Declaration of I/O, non failsafe outputs)
! id_pluto:00=000000000000
! pgm_pluto:00
! Q0.10,static
S0.0_0
