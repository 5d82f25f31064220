; The manual's speed monitoring example (Part 1, 9.2): one motion watched by
; a photocell and by a frequency converter's analogue output, on a D45.
; The photocell gives 20 pulses a revolution on counter input IA0.0, read
; with HS_SpeedCount_Up: 488 pulses a second at full speed (24.4
; revolutions a second). The converter's 4-20 mA output on IA0.1 is read with
; ReadCurrent of the Analog01 library and scaled so that 20 mA is 488 too;
; 4 mA is 0 speed, so a wire break (0 mA) reads -122. SpeedMon1 compares the
; two: they may differ by 20 (MaxDiff), by more for 0.5 s (DiffDelay), and
; the speed is safely low below 150.
! id_pluto_Double:00=000000000000
! type_pluto:00=D45,is3
! R0.10=Speed_Freq_Conv
! R0.11=Speed_Photocell
! R0.12=ValidSpeed
! M0.1=FreqConvOk
! M0.2=PhotocellOk
! Q0.0=SpeedValid
! Q0.1=StandStill
! Q0.2=SafeLowSpeed
! pgm_pluto:00
! IA0.0,counter_up
! IA0.1,current
S0.0_0
;@block HS_SpeedCount_Up Input="IA0.0" Valid="PhotocellOk" PulsePerSec="Speed_Photocell"
;@end
;@block ReadCurrent Input="IA0.1" Value_4mA="0" Value_20mA="488" Q="FreqConvOk" Scaled_Value="Speed_Freq_Conv"
;@end
;@block SpeedMon1 Speed="Speed_Photocell" CompSpeed="Speed_Freq_Conv" MaxDiff="20" DiffDelay="0s50" LowSpeedLim="150" SpeedValid="SpeedValid" ValidSpeed="ValidSpeed" StandStill="StandStill" SafeLowSpeed="SafeLowSpeed"
;@end
