; Source: 000_f98263f7f3abf510.txt Part 2 section 4.1.2 ("Assignment of register (with instruction set 3)",
; column "Syntax for Registers")
; Every form of the column, in table order; where a row gives two spellings
; ("... or ...") both are written. Followed by the notes' system memories and
; register: SM_DivByZero (SM_12), SM_Overflow (SM_11), SR_Remain (SR_2).
! id_pluto:00=000000000000
! type_pluto:00=A20,is3
! pgm_pluto:00
S0.0_0
(R0.100++)                      ; Increment by 1
(R0.100--)                      ; Decrement by 1
(R0.100 += 77)                  ; Add constant
(R0.100 -= 77)                  ; Subtract constant
(R0.100 = 1)                    ; Assign with absolute value = 1
(R0.100 = R0.102)               ; Assign with other reg. value
(R0.100 *= 2)                   ; Multiply with constant
(R0.100 /= 2)                   ; Divide by constant
(R0.100 += R0.102)              ; Addition with other register
(R0.100=R0.100+R0.102)          ; Addition with other register (second spelling)
(R0.100=R0.102+R0.104)          ; Addition, result in a third register
(R0.100 -= R0.102)              ; Subtract with other register
(R0.100=R0.100-R0.102)          ; Subtract with other register (second spelling)
(R0.100=R0.102-R0.104)          ; Subtract, result in a third register
(R0.100 *= R0.102)              ; Multiply with other register
(R0.100=R0.100*R0.102)          ; Multiply with other register (second spelling)
(R0.100=R0.102*R0.104)          ; Multiply, result in a third register
(R0.100 /= R0.102)              ; Divide by other register
(R0.100=R0.100/R0.102)          ; Divide by other register (second spelling)
(R0.100=R0.102/R0.104)          ; Divide, result in a third register

; Notes after the table (added lines)
M0.11 = SM0.11                  ; SM_Overflow
M0.12 = SM0.12                  ; SM_DivByZero
M0.13 = (SR0.2 > 0)             ; SR_Remain, remainder after division
