; Source: 000_f98263f7f3abf510.txt Part 2 section 4.2 (Use of analogue values)
; Monitoring of the current in output Q16 (SR0.42, Pluto A20 only).
! id_pluto:00=000000000000
! pgm_pluto:00
S0.0_0
M0.100 = (SR0.42 > 180)
M0.101 = M0.100 * (SR0.42 < 400) * (P(M0.100) + M0.101)
