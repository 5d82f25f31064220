; Source: 000_f98263f7f3abf510.txt Part 2 section 4.1.2 (Registers, comparison examples)
; "\geq" of the converted text is ">=".
! id_pluto:00=000000000000
! pgm_pluto:00
S0.0_0
Q0.10 = (R0.98 >= 4)
M0.10 = (R0.22 = R0.35) * I0.4
(R0.9++) = (R0.12 > R0.14)
