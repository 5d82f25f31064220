; The jump example of Part 2 section 3.2 and the sequence reset of 3.3.
! id_pluto:00=000000000000
! pgm_pluto:00
S0.0_0
S0.1_00
Q0.1 = I0.2
J(+1) = Q0.10*M0.7
S0.1_01
S(Q0.2) = I0.3
J(10) = M0.10
S0.1_10
R(Q0.2) = I0.4
J(0) = GM0.0
S0.2_0
R(S0.1) = I0.7
