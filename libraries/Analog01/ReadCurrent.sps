$name ReadCurrent
;@project description="Timing example of ReadCurrent (Analog01): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="ReadCurrent"
! type_pluto:00=D20,is3

! IA0.0=Input
! Q0.0=Q
! R0.0=Current
! R0.1=Scaled_Value

! pgm_pluto:00
! IA0.0,current

S0.0_0
;@block ReadCurrent Input="Input" Value_4mA="0" Value_20mA="1000" Q="Q" Current="Current" Scaled_Value="Scaled_Value"
;@end
