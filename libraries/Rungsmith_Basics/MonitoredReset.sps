$name MonitoredReset
;@project description="Timing example of MonitoredReset (Rungsmith_Basics): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="MonitoredReset"
! type_pluto:00=A20,is3

! I0.0=Enable
! I0.1=Reset
! I0.2=Feedback
! Q0.0=Out
! Q0.1=ResetLamp

! pgm_pluto:00
! I0.0,static
! I0.1,static
! I0.2,static

S0.0_0
;@block MonitoredReset Enable="Enable" Reset="Reset" Feedback="Feedback" Out="Out" ResetLamp="ResetLamp"
;@end
