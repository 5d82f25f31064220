; Source: 000_f98263f7f3abf510.txt Part 2 sections 4.1.1 and 4.1.1.1 (Double registers, half double registers)
; Table: DR0.0 - DR0.148, only even numbers. DR1.4 = R1.5 (high word) and
; R1.4 (low word). "If for example DR0.4 is used in a program the registers
; R0.4 and R0.5 cannot be addressed directly but instead by DR0.4.Lo (=R0.4)
; and DR0.4.Hi (=R0.5)." The variables page (picture) names DR0.4 "Example",
; whose halves are "Example.Lo" and "Example.Hi".
; The statements are added to use each of these forms.
! id_pluto:00=000000000000
! type_pluto:00=A20,is3
! pgm_pluto:00
! DR0.4=Example
S0.0_0
(DR0.0 = 0)                     ; first double register (R0.0 : R0.1)
(DR0.148 = 0)                   ; last double register (R0.148 : R0.149)
(DR0.4.Lo = 1)                  ; = R0.4
(DR0.4.Hi = 2)                  ; = R0.5
(Example.Lo = 3)                ; = DR0.4.Lo
(Example.Hi = 4)                ; = DR0.4.Hi
M0.1 = (Example > 0)
M0.2 = (DR0.4 > 0)
