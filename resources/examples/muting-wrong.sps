$name Muting, deliberately wrong

! id_pluto:00=000034AD4AE3
! type_pluto:00=A20,is3
! I0.0=LightCurtain             ; Closed when the light curtain is clear
! I0.1=MuteA                    ; Muting sensors: both see the pallet
! I0.2=MuteB
! I0.12=EStop
! Q0.2=Conveyor
! M0.0=Muting
! pgm_pluto:00

! I0.0,a_pulse
! I0.1,a_pulse
! I0.2,b_pulse
! I0.12,a_pulse

S0.0_0

Muting = MuteA + MuteB         ; WRONG: one sensor mutes the light curtain;
                               ; it takes both (MuteA * MuteB)
Conveyor = EStop * (LightCurtain + Muting)
