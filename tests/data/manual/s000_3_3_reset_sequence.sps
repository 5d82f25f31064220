; Source: 000_f98263f7f3abf510.txt Part 2 section 3.3 (Reset sequence)
; Table: Reset sequence R(S0.1) (ladder symbol lost).
; The example is a fragment (step 5 of sequence 1). Added: main PLC code
; S0.0_0 (empty), step 0 of sequence 1 with J(5) = I0.0, and sequence 2
; step 0 (the sequence being reset).
! id_pluto:00=000000000000
! pgm_pluto:00
S0.0_0                          ; added
S0.1_0                          ; added
J(5) = I0.0                     ; added
S0.1_05
R(S0.2) = I0.7
S0.2_0                          ; added
