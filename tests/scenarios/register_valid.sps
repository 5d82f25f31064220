; RegisterValid (manual Part 1, 10.2.1): unit 0 stops a motor of unit 1 by
; a speed it exports; 0 means stand-still, but 0 is also what an exported
; register reads without communication, so the stand-still lamp needs the
; speed to be valid too.
! id_pluto:00=000000000000
;@var R0.5 export="yes"
! id_pluto:01=000000000001
! type_pluto:00=A20,is3
! type_pluto:01=A20,is3
! R0.5=Speed
! pgm_pluto:00
! I0.0,static
S0.0_0
(Speed = 120) = I0.0
(Speed = 0) = /I0.0
! pgm_pluto:01
S1.0_0
;@block RegisterValid Input="Speed" Valid="M1.1" Value="R1.3"
;@end
M1.2 = M1.1 * (R1.3 = 0)
