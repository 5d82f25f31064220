; Source: 000_f98263f7f3abf510.txt Part 1 section 8 (Analogue inputs Pluto D20)
; "IA0.0 and IA0.1 are configured as Analogue input 0-10V, and IA0.2 and IA0.3
; are configured as Analogue input 4-20mA." (the page itself was a picture).
; Text form of the options per language.md. The function blocks ReadVoltage /
; ReadCurrent have no text form in the manual.
! id_pluto:00=000000000000
! type_pluto:00=D20,is2
! pgm_pluto:00
! IA0.0,voltage
! IA0.1,voltage
! IA0.2,current
! IA0.3,current
S0.0_0
