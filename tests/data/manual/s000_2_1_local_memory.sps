; Source: 000_f98263f7f3abf510.txt Part 2 section 2.1 (Local memories (M))
; Table: M_.0 - M_.599 (Pluto AS-i with instruction set 2: M_.0 - M_.149)
! id_pluto:07=000000000000
! pgm_pluto:07
S7.0_0
M7.1 = I7.15
