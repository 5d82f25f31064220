; Source: 000_f98263f7f3abf510.txt Part 1 section 9 (Counter inputs Pluto D45)
; GUI table: IA0.0 Counter input, Up. The table also shows the shape Up/Down
; for IA0.2 (type still Undefined); it is declared here to cover the option.
; Text form of the options per language.md. The function blocks
; HS_SpeedCount_Up / HS_SpeedCount_Dir have no text form in the manual.
; D45 is in the "double" family, hence id_pluto_Double.
! id_pluto_Double:00=000000000000
! type_pluto:00=D45,is2
! pgm_pluto:00
! IA0.0,counter_up
! IA0.2,counter_updown          ; shape Up/Down (type Undefined in the table)
S0.0_0
