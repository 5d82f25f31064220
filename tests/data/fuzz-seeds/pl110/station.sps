$target PL110
$name Filling station
! I1=Start                     ; green button
! I2=Stop
! Q1=Pump
! VW10=Batches
INIT
(VW10 = 0)
MAIN
Pump = Start * /Stop + Pump * /Stop
TON(T1, 100ms, 50) = Pump      ; 5 s of pumping
MUP(C1, UP, 10) = T1 * P
MUP(C1, RESET, 10) = I3
(VW10 = C1)
Q2 = C1 + (VW10>=5) * SM0.3
B1 = I4 * NOT
SBIT(V3.4) = I5 * N
(VD20 = VD20 + VW10) = P
TOFF(T2, 10ms, VW0) = I6
TONR(T3, 1s, AI1) = I7
MDOWN(C2, DOWN, 3) = I8
(VW11 = VW10 << 2)
