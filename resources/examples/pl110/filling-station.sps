$target PL110
$name Filling station
! I1=Start                     ; green button, N.O.
! I2=Stop                      ; red button, N.C.: 1 while not pressed
! I3=Full                      ; level switch in the can
! I4=CanPresent                ; a can stands under the nozzle
! I5=Acknowledge
! Q1=Pump
! Q2=BatchDone                 ; lamp: ten cans filled
! Q3=Alarm                     ; lamp: a can took too long
! M1=Running
! VW10=Filled                  ; cans filled in this batch
! T1=Overrun
! C1=Batch

INIT
(Filled = 0)
MAIN
; The station runs from Start until Stop or an alarm.
Running = Start * Stop * /Alarm + Running * Stop * /Alarm
Pump = Running * CanPresent * /Full * /BatchDone
; A can that is not full after 8 s stops the station.
TON(Overrun, 100ms, 80) = Pump
Alarm = Overrun + Alarm * /Acknowledge
; Ten full cans make a batch; Acknowledge starts the next one.
MUP(Batch, UP, 10) = Full * CanPresent
MUP(Batch, RESET, 10) = Acknowledge * BatchDone
(Filled = Batch)
BatchDone = Batch
