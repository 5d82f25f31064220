; Source: 000_f98263f7f3abf510.txt Part 2 section 1.7 (Timers TON and TPS)
! id_pluto:00=000000000000
! pgm_pluto:00
S0.0_0
Q0.10 = I0.2 * TON(5s10)
Q0.12 = I0.4 * TPS(3s5)
Q0.11 = I0.3 * TON(2s5) * I0.0
