$name Example, manual

! id_pluto:00=000034AD4AE1
! pgm_pluto:00

! Q0.10,a_pulse                ; Dynamic output A

! I0.0,static                  ; Muting sensor 1
! I0.1,a_pulse,non_inv         ; Muting sensor 2
! I0.2,a_pulse,non_inv         ; Test Contactors
! I0.12,a_pulse                ; Emergency stop PB
! I0.13,a_pulse                ; JSL Lightbeam
! IQ0.14,a_pulse               ; Reset with indicator

;*****
;

S0.0_0                         ; Main sequence start

Q0.2 = I0.12 * (I0.13 + M0.0) * (P(I0.14) * I0.2 + Q0.2)
Q0.3 = Q0.2

                               ; All safety outputs active when Emergency stop(I0.12)
                               ; and JSL(I.13) or muting(M0.0) are active.
                               ; Reset(I0.14) and Test(I0.02) are also needed in the
                               ; start condition.

Q0.14 = /Q0.2                  ; Reset indication active when outputs not active

;*****
;

S0.1_0                         ; Muting Sequence
J(+1) = /I0.0 * /I0.1 * (SR0.43<100) ; Start condition: both sensors not active

S0.1_1
Q0.17 = I0.0 * I0.1 * I0.13
J(+1) = Q0.17 * (SR0.43<100)   ; Muting start when both sensors and JSL active
S0.1_2
M0.0                           ; M0.0, Memory muting active
Q0.17                          ; Indicator muting active
J(0) = /I0.0 + /I0.1           ; Muting stopped by either sensor not active
