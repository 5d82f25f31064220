; Source: 001_6bd47eebc93f036b.txt section 2.5 (Toggle function)
; Table: Toggle state T(Q0.1) (covered by the example).
! id_pluto:04=000000000000
! pgm_pluto:04
S4.0_0
T(Q4.2) = P(I4.1)
