; Source: 001_6bd47eebc93f036b.txt section 2.4 (Latch function)
; Table: SET/Latch on S(Q0.1), RESET/Latch off R(Q0.1) (covered by the example).
! id_pluto:05=000000000000
! pgm_pluto:05
S5.0_0
S(Q5.17) = I5.2
R(Q5.17) = I5.3
