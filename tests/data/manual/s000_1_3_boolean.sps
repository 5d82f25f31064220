; Source: 000_f98263f7f3abf510.txt Part 2 section 1.3 (Boolean instructions)
; The four text-form examples of the section, in order. All write Q0.1;
; the last line wins (language.md, scan semantics).
; I1.0 is an input of unit 1, so unit 1 is declared (no code for it).
! id_pluto:00=000000000000
! id_pluto:01=000000000000
! pgm_pluto:00
S0.0_0
Q0.1 = I0.0 + I0.2 * I1.0; Start up
; (semicolon) defines start of program comments.

; Example with negation:
Q0.1 = /I0.0 + I0.2 * I1.0

; AND before OR:
Q0.1 = I0.0 + I0.2 * I1.0 * I0.1

; Example with use of brackets
Q0.1 = (I0.0 + I0.2 * I1.0) * I0.1
