; Source: 000_f98263f7f3abf510.txt Part 2 section 1.4.1 (Inverted edge detection, instruction set 3)
; The example was a picture; reconstructed from its description: "M0.0 is
; normally high. By a positive edge on I0.0 or negative edge on I0.2, M0.0 is
; 0 during one PLC cycle." (Not P_Edge and Not N_Edge in series.)
! id_pluto:00=000000000000
! type_pluto:00=A20,is3
! pgm_pluto:00
S0.0_0
M0.0 = /P(I0.0) * /N(I0.2)
