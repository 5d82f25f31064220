; Source: 000_f98263f7f3abf510.txt Part 2 section 4.1.2 (instruction set 3 table, note)
; "NOTE: It is possible to "mix" R and DR in assignments  Ex: (DR0.100 *= R0.102)"
; In its own file: it uses R0.102 directly, which must not appear together
; with DR0.102 (see s000_4_1_2_mixed_divide.sps).
! id_pluto:00=000000000000
! type_pluto:00=A20,is3
! pgm_pluto:00
S0.0_0
(DR0.100 *= R0.102)
