$name RegisterValid
;@project description="Timing example of RegisterValid (Rungsmith_System): one instance on unit 0, every pin bound to a name equal to the pin's; unit 1 exports the register it reads."

! id_pluto:00=000000000000
;@unit 00 description="RegisterValid"
! type_pluto:00=A20,is3
! id_pluto:01=000000000001
;@unit 01 description="Exports Input"
! type_pluto:01=A20,is3
;@var R1.0 export="yes"

! R1.0=Input
! Q0.0=Valid
! R0.0=Value

! pgm_pluto:00

S0.0_0
;@block RegisterValid Input="Input" Valid="Valid" Value="Value"
;@end

! pgm_pluto:01

S1.0_0
