$name DRegisterValid
;@project description="Timing example of DRegisterValid (Rungsmith_System): one instance on unit 0, every pin bound to a name equal to the pin's; unit 1 exports the double register it reads."

! id_pluto:00=000000000000
;@unit 00 description="DRegisterValid"
! type_pluto:00=A20,is3
! id_pluto:01=000000000001
;@unit 01 description="Exports Input"
! type_pluto:01=A20,is3
;@var DR1.0 export="yes"

! DR1.0=Input
! Q0.0=Valid
! DR0.0=Value

! pgm_pluto:00

S0.0_0
;@block DRegisterValid Input="Input" Valid="Valid" Value="Value"
;@end

! pgm_pluto:01

S1.0_0
