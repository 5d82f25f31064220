$name SF_TwoHandControlTypeII
;@project description="Timing example of SF_TwoHandControlTypeII (Rungsmith_Safety): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="SF_TwoHandControlTypeII"
! type_pluto:00=A20,is3

! I0.0=Activate
! I0.1=S_Button1
! I0.2=S_Button2
! M0.0=Ready
! Q0.0=S_TwoHandOut
! M0.1=Error
! R0.0=DiagCode

! pgm_pluto:00
! I0.0,static
! I0.1,static
! I0.2,static

S0.0_0
;@block SF_TwoHandControlTypeII Activate="Activate" S_Button1="S_Button1" S_Button2="S_Button2" Ready="Ready" S_TwoHandOut="S_TwoHandOut" Error="Error" DiagCode="DiagCode"
;@end
