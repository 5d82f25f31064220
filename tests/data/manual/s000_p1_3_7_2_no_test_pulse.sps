; Source: 000_f98263f7f3abf510.txt Part 1 section 3.7.2 (Disabling of test pulses)
; The manual shows this only as the I/O Options page (Q0.2 No_Test_Pulse
; ticked, Q0.3 not); the text form is the one fixed in language.md.
! id_pluto:00=000000000000
! pgm_pluto:00
! Q0.2,no_test_pulse
S0.0_0
