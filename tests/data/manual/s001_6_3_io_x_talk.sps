; Source: 001_6bd47eebc93f036b.txt section 6.3 (Declaration of I/O, special function cross talk)
; Syntax: ! I[no],[pulse type],x_talk   (I_.10 - I_.17; a_pulse, b_pulse, c_pulse)
! id_pluto:00=000000000000
! pgm_pluto:00
! I0.12,a_pulse,x_talk
S0.0_0
