; Source: 000_f98263f7f3abf510.txt Part 2 sections 1.1 and 1.2 (Register bits, instruction set 3)
; 1.2: "In this example bit0 and bit1 in register R100 in Pluto 0 is set. The
; value in R100 will be 3". The ladder picture (with its condition) was lost;
; the two Set coils are written with the stand-in condition I0.0.
; 1.1 table: R0.0.0 ... R0.0.15 ... R0.149.0 ... R0.149.15 (added line reading
; the ends of the range).
! id_pluto:00=000000000000
! type_pluto:00=A20,is3
! pgm_pluto:00
S0.0_0
S(R0.100.0) = I0.0              ; set bit 0 of R100 (condition: stand-in)
S(R0.100.1) = I0.0              ; set bit 1 of R100 (condition: stand-in)
M0.1 = R0.0.0 + R0.0.15 + R0.149.0 + R0.149.15  ; added: table range
