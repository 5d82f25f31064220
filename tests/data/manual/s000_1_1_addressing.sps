; Source: 000_f98263f7f3abf510.txt Part 2 section 1.1 (Addressing of bit-operands)
; Example: Q10.1 = addressing of output 1 on PLUTO no. 10.
; "Following alternatives are also accepted: Q10.01 or Q10.0001 or Q10.1"
; The operand alone is written as an unconditional coil; the alternative
; spellings are read into memories (added).
! id_pluto:10=000000000000
! pgm_pluto:10
S10.0_0
Q10.1                           ; Addressing of output 1 on PLUTO no. 10
M10.1 = Q10.01                  ; alternative spelling (added M10.1)
M10.2 = Q10.0001                ; alternative spelling (added M10.2)
