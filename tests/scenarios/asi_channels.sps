; The channel monitoring of AS-i safe input slaves (manual Part 1, 7.1.4.2):
; one slave for each of the five kinds, its input copied to a memory.
! id_pluto_ASi:00=000000000000
;@asi_slave ASi0.1 type="safe_input" model="General" param="F" profile="S-0.B.F" id1="F" monitoring="none"
;@asi_slave ASi0.2 type="safe_input" model="General" param="F" profile="S-0.B.F" id1="F" monitoring="channel"
;@asi_slave ASi0.3 type="safe_input" model="General" param="F" profile="S-0.B.F" id1="F" monitoring="channel_debounce" time_limit_ms="200"
;@asi_slave ASi0.4 type="safe_input" model="General" param="F" profile="S-0.B.F" id1="F" monitoring="simultaneous" time_limit_ms="100"
;@asi_slave ASi0.5 type="safe_input" model="General" param="F" profile="S-0.B.F" id1="F" monitoring="simultaneous_debounce" time_limit_ms="200"
! type_pluto:00=ASi,is3
! pgm_pluto:00
! ASi0.1=Plain
! ASi0.2=Door
! ASi0.3=Gate
! ASi0.4=Guard
! ASi0.5=Hatch
! M0.1=PlainOn
! M0.2=DoorOn
! M0.3=GateOn
! M0.4=GuardOn
! M0.5=HatchOn
S0.0_0
PlainOn = Plain
DoorOn = Door
GateOn = Gate
GuardOn = Guard
HatchOn = Hatch
