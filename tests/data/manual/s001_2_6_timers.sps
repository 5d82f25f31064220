; Source: 001_6bd47eebc93f036b.txt section 2.6 (Timers, old spelling T = TON)
; Table: T(nnSnn), 0,01 - 655,35 s, "s" is the decimal sign.
; Note: the manual's text for the second example says "After a delay of 3,5 s"
; while its code says 2s5; the code is kept as printed.
! id_pluto:00=000000000000
! pgm_pluto:00
S0.0_0
Q0.10 = I0.2 * T(5s10)
Q0.12 = I0.4 * /T(2s5)
Q0.11 = I0.3 * T(2s5) * I0.0
