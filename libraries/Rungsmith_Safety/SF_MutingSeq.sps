$name SF_MutingSeq
;@project description="Timing example of SF_MutingSeq (Rungsmith_Safety): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="SF_MutingSeq"
! type_pluto:00=A20,is3

! I0.0=Activate
! I0.1=S_AOPD_In
! I0.2=MutingSwitch11
! I0.3=MutingSwitch12
! I0.4=MutingSwitch21
! I0.5=MutingSwitch22
! I0.6=S_MutingLamp
! I0.7=MutingEnable
! I0.10=Reset
! M0.0=Ready
! Q0.0=S_AOPD_Out
! Q0.1=S_MutingActive
! M0.1=Error
! R0.0=DiagCode

! pgm_pluto:00
! I0.0,static
! I0.1,static
! I0.2,static
! I0.3,static
! I0.4,static
! I0.5,static
! I0.6,static
! I0.7,static
; Reset is the ninth input, on I0.10: a static input there is no category 4
; stand-alone input, so it reads a dynamic A pulse from IQ0.16. S_StartReset
; stays open (0), keeping the diagram to 14 pins.
! Q0.16,a_pulse
! I0.10,a_pulse

S0.0_0
;@block SF_MutingSeq Activate="Activate" S_AOPD_In="S_AOPD_In" MutingSwitch11="MutingSwitch11" MutingSwitch12="MutingSwitch12" MutingSwitch21="MutingSwitch21" MutingSwitch22="MutingSwitch22" S_MutingLamp="S_MutingLamp" MaxMutingTime="1s50" MutingEnable="MutingEnable" Reset="Reset" Ready="Ready" S_AOPD_Out="S_AOPD_Out" S_MutingActive="S_MutingActive" Error="Error" DiagCode="DiagCode"
;@end
