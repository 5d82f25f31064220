; Source: 000_f98263f7f3abf510.txt Part 2 section 5.3 (Declaration of I/O, example list)
; Comments as printed (the last one, "Input is supplied with dynamic A
; signal." for a static output, is the manual's).
! id_pluto:00=000000000000
! pgm_pluto:00
! i0.1,a_pulse ; Input is supplied with dynamic A signal via inverter.
! i0.2,a_pulse,non_inv ; Input is supplied with dynamic A signal.
! i0.3,static ; Input is supplied with +24V.
! q0.10,a_pulse ; Output generates dynamic A signal for supply of inputs.
! q0.11,static ; Input is supplied with dynamic A signal.
S0.0_0
