; Source: 000_f98263f7f3abf510.txt Part 2 section 4.1.2 (Double registers: column "Syntax for Double
; Registers" of the instruction set 3 assignment table and of the comparison table)
; Every form given for double registers ("Not possible for Double Registers":
; /= with a constant or a register; the division row is in
; s000_4_1_2_mixed_divide.sps). R0.100 .. R0.105 are not used directly here,
; because DR0.100 .. DR0.104 are. Comparisons are used in coils (added M0.1..M0.10).
! id_pluto:00=000000000000
! type_pluto:00=A20,is3
! pgm_pluto:00
S0.0_0
; Assignment (Syntax for Double Registers)
(DR0.100++)                     ; Increment by 1
(DR0.100--)                     ; Decrement by 1
(DR0.100 += 77)                 ; Add constant
(DR0.100 -= 77)                 ; Subtract constant
(DR0.100 = 1)                   ; Assign with absolute value = 1
(DR0.100 = DR0.102)             ; Assign with other reg. value
(DR0.100 *= 2)                  ; Multiply with constant
(DR0.100 += DR0.102)            ; Addition with other register
(DR0.100=DR0.100+DR0.102)       ; Addition with other register (second spelling)
(DR0.100=DR0.102+DR0.104)       ; Addition, result in a third register
(DR0.100 -= DR0.102)            ; Subtract with other register
(DR0.100=DR0.100-DR0.102)       ; Subtract with other register (second spelling)
(DR0.100=DR0.102-DR0.104)       ; Subtract, result in a third register
(DR0.100 *= DR0.102)            ; Multiply with other register
(DR0.100=DR0.100*DR0.102)       ; Multiply with other register (second spelling)
(DR0.100=DR0.102*DR0.104)       ; Multiply, result in a third register

; Comparison (Syntax for DoubleRegisters)
M0.1 = (DR0.100=1)              ; Equal to (constant)
M0.2 = (DR0.100>1)              ; Greater than
M0.3 = (DR0.100<1)              ; Less than
M0.4 = (DR0.100>=1)             ; Greater than or Equal to
M0.5 = (DR0.100<=1)             ; Less than or Equal to
M0.6 = (DR0.100=DR0.102)        ; Equal (two registers)
M0.7 = (DR0.100>DR0.102)        ; Greater than
M0.8 = (DR0.100< DR0.102)       ; Less than
M0.9 = (DR0.100>= DR0.102)      ; Greater than or Equal to
M0.10 = (DR0.100<= DR0.102)     ; Less than or Equal to
