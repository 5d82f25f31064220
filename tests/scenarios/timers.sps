; The timer examples of the manuals (short manual 2.6, Part 2 section 1.7).
! id_pluto:00=000000000000
! type_pluto:00=A20,is3
! pgm_pluto:00
S0.0_0
Q0.10 = I0.2 * TON(5s10)       ; on-delay
Q0.12 = I0.4 * TPS(3s5)        ; pulse
Q0.11 = I0.3 * TON(2s5) * I0.0 ; I0.0 does not affect the timer
Q0.13 = I0.5 * TOF(1s00)       ; off-delay
M0.1 = I0.6 * /T(2s5)          ; old spelling, negated: a 2.5 s pulse
