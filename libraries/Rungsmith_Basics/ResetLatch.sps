$name ResetLatch
;@project description="Timing example of ResetLatch (Rungsmith_Basics): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="ResetLatch"
! type_pluto:00=A20,is3

! I0.0=Enable
! I0.1=Reset
! Q0.0=Out
! Q0.1=ResetLamp

! pgm_pluto:00
! I0.0,static
! I0.1,static

S0.0_0
;@block ResetLatch Enable="Enable" Reset="Reset" Out="Out" ResetLamp="ResetLamp"
;@end
