; Source: 001_6bd47eebc93f036b.txt section 2.3 (Edge detection)
; Output 3 on PLUTO no. 10 is set HIGH when positive edge is detected on
; input 2 on PLUTO no. 10 (and a positive edge of the inverted input 3).
; The syntax table of P/N edges was a picture (lost).
! id_pluto:10=000000000000
! pgm_pluto:10
S10.0_0
Q10.3 = P(I10.2) * P(/I10.3)
