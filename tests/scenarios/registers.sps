; Register examples (short manual 5.1.2, Part 2 4.1.2).
! id_pluto:00=000000000000
! id_pluto:01=000000000000
! type_pluto:00=A20,is3
! pgm_pluto:00
S0.0_0
(R0.100+=2)
(R0.20=R0.23)
Q0.10 = (R0.98>=4)
M0.10 = (R0.22=R0.35) * I0.4
(R0.9++) = (R0.12 > R0.14)
(R0.30 *= 3) = P(I0.0)
(R0.40 = R0.41 / R0.42) = I0.1
M0.11 = SM0.12
! pgm_pluto:01
S1.0_0
(R1.34+=R1.35) = P(I1.3)
