; Source: 000_f98263f7f3abf510.txt Part 1 sections 3.8 - 3.13 (tutorial: I/O options, naming, last network)
; The tutorial is GUI only. Its I/O Options table (3.8) and Variables table
; (3.9) written as declarations, and its last network (3.13: "Contactor_B" works
; exactly as "Contactor_A") as code. The networks with the function blocks
; Mute2 and ResetT have no text form in the manual and are left out.
; The Variables table names Q0.2/Q0.3 "Contact_A"/"Contact_B", while the
; symbol list and the text of 3.13 say Contactor_A/Contactor_B; the latter is used.
! id_pluto:00=000000000000
! I0.0=MuteSensor1
! I0.1=MuteSensor2
! I0.2=ContMonitor
! I0.12=EStopButton
! I0.13=LightBeamSensor
! I0.14=ResetButton
! Q0.2=Contactor_A
! Q0.3=Contactor_B

! pgm_pluto:00
! i0.0,static                   ; I0.0 Input Static
! i0.1,a_pulse,non_inv          ; I0.1 Input A_Pulse Non_Inv
! i0.2,a_pulse,non_inv          ; I0.2 Input A_Pulse Non_Inv
! q0.10,a_pulse                 ; IQ0.10 Output A_Pulse
! i0.12,a_pulse                 ; IQ0.12 Input A_Pulse
! i0.13,a_pulse                 ; IQ0.13 Input A_Pulse
! iq0.14,a_pulse                ; IQ0.14 Light button A_Pulse
S0.0_0
Contactor_B = Contactor_A
