$name Two-hand control

! id_pluto:00=000034AD4AE2
! type_pluto:00=A20,is3
! I0.0=LeftHand
! I0.1=RightHand
! Q0.2=PressValve
! M0.1=Late                    ; A hand has been on for 500 ms
! M0.2=Ready                   ; Both hands were released since the last stroke
! pgm_pluto:00

! I0.0,a_pulse
! I0.1,b_pulse

S0.0_0

Late = (LeftHand + RightHand) * TON(0s50)
S(Ready) = /LeftHand * /RightHand
PressValve = LeftHand * RightHand * (Ready * /Late + PressValve)
R(Ready) = PressValve + Late   ; One stroke per release, and none when the
                               ; hands came more than 500 ms apart
