; Source: 001_6bd47eebc93f036b.txt section 3.1 (Local memories (M))
; Table: M_.0 - M_.599
! id_pluto:07=000000000000
! pgm_pluto:07
S7.0_0
M7.1 = I7.15
