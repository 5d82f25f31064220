; Source: 000_f98263f7f3abf510.txt Part 2 section 5.4 (Symbolic names)
; Global names are declared before the first pgm_pluto, local ones after the
; unit's I/O declarations. The manual declares the name MuteSensor2 twice
; (Q0.1 and GM0.1); the GM0.1 one is renamed MuteSensor2_GM here.
! id_pluto:00=000000000000
! I0.0=MuteSensor1           ; Symbolic names global variables
! Q0.1=MuteSensor2
! GM0.1=MuteSensor2_GM       ; renamed from MuteSensor2 (duplicate in the manual)

! pgm_pluto:00
! Q0.14=IndReset             ; Symbolic names local variables
! M0.0=MutingActive
! R0.0=Counter1
S0.0_0
