; Source: 000_f98263f7f3abf510.txt Part 2 section 1.1 (Addressing of Pluto AS-i slave inputs and outputs)
; Table rows: AS-i inputs (Safe) ASi0.1 .. ASi0.31; non-safe standard slave
; inputs ASi0.x.1 .. ASi0.x.4; non-safe B-slave inputs ASi0.xB.1 .. ASi0.xB.4;
; outputs ASq0.x.y and ASq0.xB.y. The table has no code; lines added.
; One slave address cannot be both a safe slave and a non-safe one (Part 1,
; 10.2), so slaves 1 and 31 are used as safe inputs, slave 2 as a non-safe
; standard slave and slave 30 as a non-safe A/B slave pair, as the AS-i
; Options records say.
! id_pluto_ASi:00=000000000000
;@asi_slave ASi0.1 type="safe_input" model="General" param="F" profile="S-0.B.F" id1="F" monitoring="channel"
;@asi_slave ASi0.2 type="nonsafe_std" param="F" profile="S-7.0.F" id1="F"
;@asi_slave ASi0.30 type="nonsafe_ab" param="F" profile="S-7.A.F" id1="F"
;@asi_slave ASi0.30B type="nonsafe_ab" param="F" profile="S-7.A.F" id1="F"
;@asi_slave ASi0.31 type="safe_input" model="General" param="F" profile="S-0.B.F" id1="F" monitoring="channel"
! pgm_pluto:00
S0.0_0
M0.1 = ASi0.1 * ASi0.31                         ; AS-i inputs (Safe)
M0.2 = ASi0.2.1 + ASi0.2.4                      ; AS-i inputs Nonsafe standard slaves
M0.3 = ASi0.30.1 + ASi0.30.4                    ; AS-i inputs Nonsafe A-slave
M0.4 = ASi0.30B.1 + ASi0.30B.4                  ; AS-i inputs Nonsafe B-slaves
ASq0.2.1 = M0.1                                 ; AS-i outputs Nonsafe standard slaves
ASq0.2.4 = M0.2
ASq0.30.1 = M0.3                                ; AS-i output Nonsafe A-slave
ASq0.30B.3 = M0.4                               ; AS-i outputs Nonsafe B-slaves
