; The CAN bus cycle time (manual Part 1, 5.2): unit 1 sends its variables
; every 50 ms instead of every scan, so unit 0 sees its input up to 50 ms
; later; unit 2 keeps the default.
! id_pluto:00=000000000000
! id_pluto:01=000000000001
;@unit 01 can_cycle_ms="50"
! id_pluto:02=000000000002
! type_pluto:00=A20,is3
! type_pluto:01=A20,is3
! type_pluto:02=A20,is3
! pgm_pluto:00
! Q0.14,static
! Q0.15,static
S0.0_0
Q0.14 = I1.0
Q0.15 = I2.0
! pgm_pluto:01
! I1.0,static
S1.0_0
! pgm_pluto:02
! I2.0,static
S2.0_0
