; Source: 000_f98263f7f3abf510.txt Part 2 section 1.7 (Timers: TOF example and timer table, instruction set 3)
; The TOF example, then one line per row of the timer table (added lines,
; M0.1..M0.7): TON (nnSnn) / old T (nnSnn), TPS (nnSnn) / old IT (nnSnn),
; TOF (nnSnn), each over the range 0.01 - 655.35 s.
! id_pluto:00=000000000000
! type_pluto:00=A20,is3
! pgm_pluto:00
S0.0_0
Q0.13 = I0.5 * TOF(1s00)

; Timer table (added lines)
M0.1 = I0.0 * TON(0s01)         ; TON, shortest time
M0.2 = I0.1 * T(655s35)         ; old syntax of TON, longest time
M0.3 = I0.2 * TPS(10S50)        ; TPS, upper-case S as in "nnSnn"
M0.4 = I0.3 * IT(1s00)          ; old syntax of TPS
M0.5 = I0.4 * TOF(655s35)       ; TOF
M0.6 = I0.6 * /TON(2s50)        ; negated timer
M0.7 = I0.7 * TON(R0.5)         ; time from a register (hundredths of a second), see Part 1 3.10
