; Latch (short manual 2.4), toggle (2.5) and edges (2.3, Part 2 1.4.1).
! id_pluto:04=000000000000
! id_pluto:05=000000000000
! id_pluto:10=000000000000
! type_pluto:10=A20,is3
! pgm_pluto:04
S4.0_0
T(Q4.2) = P(I4.1)
! pgm_pluto:05
S5.0_0
S(Q5.17) = I5.2
R(Q5.17) = I5.3
! pgm_pluto:10
S10.0_0
Q10.3 = P(I10.2) * P(/I10.3)
M10.0 = /P(I10.0) * /N(I10.2)
