; Source: 000_f98263f7f3abf510.txt Part 2 section 3.1 (Sequences, addressing)
; Example: S0.1_22 = start of step 22 in sequence 1 on PLUTO no: 0.
; Table: 1-9/0-254, Sn.1_00 - Sn.9_254.
; Added: the main PLC code S0.0_0 (empty), step 0 of sequence 1 with a jump
; to 22, and sequence 9 with steps 0 and 254 for the ends of the range.
! id_pluto:00=000000000000
! pgm_pluto:00
S0.0_0                          ; added: main PLC code (empty)
S0.1_00                         ; added: step 0 of sequence 1
J(22) = I0.0                    ; added
S0.1_22                         ; Start of step 22 in sequence 1 on PLUTO no: 0.
S0.9_0                          ; added: step 0 of sequence 9
J(254) = I0.1                   ; added
S0.9_254                        ; added: last step of the range
