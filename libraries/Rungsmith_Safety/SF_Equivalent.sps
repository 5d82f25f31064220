$name SF_Equivalent
;@project description="Timing example of SF_Equivalent (Rungsmith_Safety): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="SF_Equivalent"
! type_pluto:00=A20,is3

! I0.0=Activate
! I0.1=S_ChannelA
! I0.2=S_ChannelB
! M0.0=Ready
! Q0.0=S_EquivalentOut
! M0.1=Error
! R0.0=DiagCode

! pgm_pluto:00
! I0.0,static
! I0.1,static
! I0.2,static

S0.0_0
;@block SF_Equivalent Activate="Activate" S_ChannelA="S_ChannelA" S_ChannelB="S_ChannelB" DiscrepancyTime="0s50" Ready="Ready" S_EquivalentOut="S_EquivalentOut" Error="Error" DiagCode="DiagCode"
;@end
