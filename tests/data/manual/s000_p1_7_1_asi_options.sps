; Source: 000_f98263f7f3abf510.txt Part 1 section 7.1 (AS-i Options page)
; The page's tables as records: the working modes of 7.1.2, the safe input
; slave of 7.1.4.2 (ASi0.1 Safe Input General F S-0.B.F ID1=F, Channel
; monitoring), a URAX model, which monitors its own channels, a slave with
; "Simultaneously" and its time limit, an A/B pair (7.1.4.4), a standard
; slave (S-7.0, 4 inputs and 4 outputs) and a safe output (7.1.4.7).
; Lines added: a little code that uses them.
$name Conveyor AS-i
! id_pluto_ASi:00=000000000000
;@asi 00 mode="monitor_slave" address="9"
;@asi_slave ASi0.1 type="safe_input" model="General" param="F" profile="S-0.B.F" id1="F" monitoring="channel"
;@asi_slave ASi0.2 type="safe_input" model="URAX-A1R" param="F" monitoring="none"
;@asi_slave ASi0.3 type="safe_input" model="General" param="F" profile="S-0.B.F" id1="F" monitoring="simultaneous" time_limit_ms="250"
;@asi_slave ASi0.4 type="nonsafe_ab" param="F" profile="S-7.A.F" id1="F"
;@asi_slave ASi0.4B type="nonsafe_ab" param="F" profile="S-7.A.F" id1="F"
;@asi_slave ASi0.5 type="nonsafe_std" param="3" profile="S-7.0.F" id1="F"
;@asi_slave ASi0.6 type="safe_output" param="F"
! type_pluto:00=ASi,is3
! pgm_pluto:00
S0.0_0
M0.1 = ASi0.1 * ASi0.2 * ASi0.3
M0.2 = ASi0.4.1 + ASi0.4B.1 + ASi0.5.4
