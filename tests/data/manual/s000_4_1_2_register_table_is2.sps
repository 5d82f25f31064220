; Source: 000_f98263f7f3abf510.txt Part 2 section 4.1.2 (Registers: "Assignment of register (with
; Instruction set 2)" table and the register column of the comparison table)
; Assignments stand alone (unconditional); comparisons are operands, so each
; is used in a coil (added M0.1..M0.10). "– =" of the converted text is "-=".
! id_pluto:00=000000000000
! pgm_pluto:00
S0.0_0
; Assignment of register (with Instruction set 2)
(R0.100++)                      ; Increment by 1
(R0.100--)                      ; Decrement by 1
(R0.100 += 77)                  ; Add constant
(R0.100 -= 77)                  ; Subtract constant
(R0.100 = 1)                    ; Assign with absolute value = 1
(R0.100 += R0.102)              ; Addition with other register (R0.100 = R0.100 + R0.102)
(R0.100 -= R0.102)              ; Subtract with other register (R0.100 = R0.100 - R0.102)
(R0.100 = R0.102)               ; Assign with other reg. value

; Comparison of register (Syntax for Registers)
M0.1 = (R0.100=1)               ; Equal to (constant)
M0.2 = (R0.100>1)               ; Greater than
M0.3 = (R0.100<1)               ; Less than
M0.4 = (R0.100>=1)              ; Greater than or Equal to
M0.5 = (R0.100<=1)              ; Less than or Equal to
M0.6 = (R0.100=R0.101)          ; Equal (two registers)
M0.7 = (R0.100>R0.101)          ; Greater than
M0.8 = (R0.100< R0.101)         ; Less than
M0.9 = (R0.100>= R0.101)        ; Greater than or Equal to
M0.10 = (R0.100<= R0.101)       ; Less than or Equal to
