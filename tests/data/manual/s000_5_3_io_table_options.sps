; Source: 000_f98263f7f3abf510.txt Part 2 section 5.3 (Declaration of I/O, option tables)
; Added: one declaration per option of the tables (the same tables are in
; 001 section 6.3), each on its own terminal:
; inputs I_.0 - I_.17: a_pulse b_pulse c_pulse [non_inv] [no_filt], or static [no_filt];
; dynamic outputs Q_.10 - Q_.17: a_pulse b_pulse c_pulse; non failsafe outputs: static;
; illuminated push buttons IQ_.10 - IQ_.17: a_pulse b_pulse c_pulse.
! id_pluto:00=000000000000
! pgm_pluto:00
! I0.0,a_pulse
! I0.1,b_pulse
! I0.2,c_pulse
! I0.3,a_pulse,non_inv
! I0.4,b_pulse,non_inv,no_filt
! I0.5,c_pulse,non_inv
! I0.6,static
! I0.7,static,no_filt
! I0.17,static                  ; *) I_.10-I_.17,static does not fulfil cat. 4 as stand-alone input
! Q0.10,a_pulse
! Q0.11,b_pulse
! Q0.12,c_pulse
! Q0.13,static
! IQ0.14,a_pulse
! IQ0.15,b_pulse
! IQ0.16,c_pulse
S0.0_0
