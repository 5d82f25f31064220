$name ReadVoltage
;@project description="Timing example of ReadVoltage (Analog01): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="ReadVoltage"
! type_pluto:00=D20,is3

! IA0.0=Input
! Q0.0=Q
! R0.0=Voltage
! R0.1=Scaled_Value

! pgm_pluto:00
! IA0.0,voltage

S0.0_0
;@block ReadVoltage Input="Input" Value_0V="0" Value_10V="1000" Q="Q" Voltage="Voltage" Scaled_Value="Scaled_Value"
;@end
