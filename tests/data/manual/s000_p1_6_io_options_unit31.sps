; Source: 000_f98263f7f3abf510.txt Part 1 section 6 (I/O Options page of Pluto 31)
; GUI table written as declarations.
! id_pluto:31=000000000000
! pgm_pluto:31
! I31.0,static                  ; Input Static
! I31.1,a_pulse,non_inv         ; Input A_Pulse Non_Inv
! I31.2,a_pulse,non_inv         ; Input A_Pulse Non_Inv
! Q31.10,a_pulse                ; IQ31.10 Output A_Pulse
! I31.12,a_pulse                ; IQ31.12 Input A_Pulse
! I31.13,a_pulse                ; IQ31.13 Input A_Pulse
! IQ31.14,a_pulse               ; IQ31.14 Light button A_Pulse
! Q31.17,static                 ; IQ31.17 Output Static
S31.0_0
