$name Emergency stop with two contactors

! id_pluto:00=000034AD4AE1
! type_pluto:00=A20,is3
! I0.12=EStop                  ; Emergency stop, closed when not pressed
! IQ0.14=Reset                 ; Reset button with indicator
! I0.2=Feedback                ; Both contactors' feedback, closed when both are off
! Q0.2=ContactorK1
! Q0.3=ContactorK2
! M0.0=Run
! pgm_pluto:00

! I0.12,a_pulse
! IQ0.14,a_pulse
! I0.2,a_pulse,non_inv

S0.0_0

Run = EStop * (N(Reset) * Feedback + Run)
                               ; Start when Reset is released, and only with both
                               ; contactors seen off; the stop ends it at once.
ContactorK1 = Run
ContactorK2 = Run * TON(0s20)  ; K2 follows 200 ms after K1 (soft start)
Q0.14 = /Run                   ; The Reset lamp: ready to be reset
