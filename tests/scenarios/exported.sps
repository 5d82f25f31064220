; Exported variables (manual Part 1, 10.2.1): unit 1 exports a memory and a
; register; unit 0 reads them over the bus as if they were global.
! id_pluto:00=000000000000
! id_pluto:01=000000000001
;@var M1.3 export="yes"
;@var R1.7 export="yes"
! type_pluto:00=A20,is3
! type_pluto:01=A20,is3
! pgm_pluto:00
S0.0_0
M0.10 = M1.3
M0.11 = (R1.7 > 5)
! pgm_pluto:01
! I1.0,static
! I1.1,static
S1.0_0
M1.3 = I1.0
(R1.7 = 9) = I1.1
(R1.7 = 0) = /I1.1
