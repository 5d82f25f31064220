$name TwoSensorMuting
;@project description="Timing example of TwoSensorMuting (Rungsmith_Basics): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="TwoSensorMuting"
! type_pluto:00=A20,is3

! I0.0=Sensor1
! I0.1=Sensor2
! I0.2=Beam
! Q0.0=Muting
! M0.0=Fault

! pgm_pluto:00
! I0.0,static
! I0.1,static
! I0.2,static

S0.0_0
;@block TwoSensorMuting Sensor1="Sensor1" Sensor2="Sensor2" Beam="Beam" SyncTime="0s50" MaxTime="2s00" Muting="Muting" Fault="Fault"
;@end
