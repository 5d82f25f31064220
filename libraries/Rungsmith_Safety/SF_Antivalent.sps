$name SF_Antivalent
;@project description="Timing example of SF_Antivalent (Rungsmith_Safety): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="SF_Antivalent"
! type_pluto:00=A20,is3

! I0.0=Activate
! I0.1=S_ChannelNC
! I0.2=S_ChannelNO
! M0.0=Ready
! Q0.0=S_AntivalentOut
! M0.1=Error
! R0.0=DiagCode

! pgm_pluto:00
! I0.0,static
! I0.1,static
! I0.2,static

S0.0_0
;@block SF_Antivalent Activate="Activate" S_ChannelNC="S_ChannelNC" S_ChannelNO="S_ChannelNO" DiscrepancyTime="0s50" Ready="Ready" S_AntivalentOut="S_AntivalentOut" Error="Error" DiagCode="DiagCode"
;@end
