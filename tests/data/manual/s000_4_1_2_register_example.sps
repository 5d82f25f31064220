; Source: 000_f98263f7f3abf510.txt Part 2 section 4.1.2 (Registers, assignment example)
; The manual's example has three lines in one picture. The third writes R1.34,
; a register of unit 1, and uses input I1.3 of unit 1: a unit may not write
; another unit's variable, so that line is placed in a code section for
; unit 1 (added pgm_pluto:01 and S1.0_0).
! id_pluto:00=000000000000
! id_pluto:01=000000000000
! pgm_pluto:00
S0.0_0
(R0.100+=2)
(R0.20=R0.23)
! pgm_pluto:01
S1.0_0
(R1.34+=R1.35) = P(I1.3)
