; Source: 001_6bd47eebc93f036b.txt section 5.1.2 (Registers, operations: assignment and comparison tables)
; Every syntax form of the two tables. Assignments stand alone (unconditional);
; comparisons are operands, so each is used in a coil (added M0.1..M0.10).
; "(R0.100 – = 77)" in the converted text is written "-=".
! id_pluto:00=000000000000
! pgm_pluto:00
S0.0_0
; Assignment of register
(R0.100++)                      ; Increment by 1
(R0.100--)                      ; Decrement by 1
(R0.100 += 77)                  ; Add constant
(R0.100 -= 77)                  ; Subtract konstant
(R0.100 = 1)                    ; Assign with absolute value = 1
(R0.100 += R0.101)              ; Addition with other register (R0.100 = R0.100 + R0.101)
(R0.100 -= R0.101)              ; Subtract with other register (R0.100 = R0.100 - R0.101)
(R0.100 = R0.101)               ; Assign with other reg. value

; Comparison of register
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
