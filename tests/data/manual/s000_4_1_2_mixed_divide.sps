; Source: 000_f98263f7f3abf510.txt Part 2 section 4.1.2 (instruction set 3 table, last row, double register column)
; "Divide by other register (and store the result in a third register):
; Only the numerator is allowed to be a Double Register. (R0.100=DR0.102/R0.104)"
; In its own file: it uses R0.100 directly, which must not appear together
; with DR0.100 (see s000_4_1_2_mixed_multiply.sps).
! id_pluto:00=000000000000
! type_pluto:00=A20,is3
! pgm_pluto:00
S0.0_0
(R0.100=DR0.102/R0.104)
