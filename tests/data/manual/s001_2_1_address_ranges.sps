; Source: 001_6bd47eebc93f036b.txt section 2.1 (Addressing of bit-operands, address table)
; Table: Inputs I0.0 - I0.17 ... I31.0 - I31.17, Outputs Q0.0 - Q0.17 ...,
; Memories M0.0 - M0.599 ..., Global memories GM0.0 - GM0.11 ...
; The table has no code; these lines (added) use the first and last address
; of each row. Only global variables (I, Q_.0..3, GM) of units 1 and 31 are read.
! id_pluto:00=000000000000
! id_pluto:01=000000000000
! id_pluto:31=000000000000
! pgm_pluto:00
S0.0_0
M0.0 = I0.0 + I0.17 + I1.0 + I1.17 + I31.0 + I31.17
M0.1 = Q0.0 + Q0.17 + Q1.0 + Q31.0
M0.599 = GM0.0 + GM0.11 + GM1.0 + GM31.11
Q0.17 = M0.0 * M0.1 * M0.599
GM0.11 = M0.0
