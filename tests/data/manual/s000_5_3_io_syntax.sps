; Source: 000_f98263f7f3abf510.txt Part 2 section 5.3 (Declaration of I/O, syntax examples)
; The examples after "Syntax:" for inputs, dynamic outputs and the illuminated
; push button. "! Q0.10,static" (non failsafe outputs) declares the same
; output as "! Q0.10,a_pulse", so it is in s000_5_3_io_static_output.sps.
! id_pluto:00=000000000000
! pgm_pluto:00
! I0.5,c_pulse,non_inv,no_filt
! Q0.10,a_pulse
! IQ0.12,a_pulse
S0.0_0
