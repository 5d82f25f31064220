; The analogue half of the manual's speed monitoring example (Part 1, 9.2):
; a frequency converter's 4-20 mA output on IA0.1 of a D45, read with
; ReadCurrent of the Analog01 library and scaled so that 20 mA is 488, the
; photocell's pulses per second at full speed; 4 mA is 0 speed, so a wire
; break (0 mA) reads -122, which the speed comparison sees as a fault.
! id_pluto_Double:00=000000000000
! type_pluto:00=D45,is3
! R0.10=Speed_Freq_Conv
! M0.1=FreqConvOk
! pgm_pluto:00
! IA0.1,current
S0.0_0
;@block ReadCurrent Input="IA0.1" Value_4mA="0" Value_20mA="488" Q="FreqConvOk" Scaled_Value="Speed_Freq_Conv"
;@end
