; Source: 000_f98263f7f3abf510.txt Part 2 section 3.2 (Jump)
; "Example of a sequence in text form" (sequence 1): the converted table put
; each step on one line; split back into header and statements.
; Then the three forms of the jump table (sequence 2, added, with stand-in
; conditions; the last one unconditional, "The jump can be either condition
; or unconditional").
! id_pluto:00=000000000000
! pgm_pluto:00
S0.0_0                          ; added: main PLC code (empty)
S0.1_00                         ; Pluto 0, sequence 1, step 0
Q0.1 = I0.2                     ; Q0.1 is operated by I0.2
J(+1) = Q0.10*M0.7              ; Jump to the next step (step 1) when output Q0.10 and M0.7 is HIGH.
S0.1_01                         ; Pluto 0, sequence 1, step 1
S(Q0.2) = I0.3                  ; Output Q0.2 is set HIGH by I0.3
J(10) = M0.10                   ; Jump to step 10 when M0.10 is HIGH.
S0.1_10                         ; Pluto 0, sequence 1, step 10
R(Q0.2) = I0.4                  ; Output Q0.2 is set LOW by I0.4
J(0) = GM0.0                    ; Jump to step 0 when GM0.0 is HIGH.

; Jump table (added sequence 2)
S0.2_0
J(01) = I0.5                    ; Absolute: to step 1
S0.2_1
J(+1) = I0.6                    ; Relative: one step forward
S0.2_2
J(-1)                           ; Relative: one step backward (unconditional)
