; Source: 000_f98263f7f3abf510.txt Part 2 sections 4.1.3 and 4.2 (System registers, analogue inputs table)
; The example (unit 0), followed by one line per row of the system register
; table (added lines; SR_.10 is written, the read-only ones are compared into
; memories). The table is split by family, so the rows are placed in units of
; those families: unit 0 A20, unit 1 B46 (double family), unit 2 Pluto AS-i,
; unit 3 B42 AS-i. The table in 4.2 (SR_40 .. SR_46 per model) names the same
; registers.
! id_pluto:00=000000000000
! id_pluto_Double:01=000000000000
! id_pluto_ASi:02=000000000000
! id_pluto_B42_ASi:03=000000000000

! pgm_pluto:00
S0.0_0
Q0.12 = (SR0.40 < 180) * SM0.5

; For all Pluto models
M0.2 = (SR0.2 > 0)              ; SR_Remain          Remain part after division
M0.8 = (SR0.8 > 0)              ; SR_ExecFreeTime    PLC cycle time left to be used (us)
M0.9 = (SR0.9 > 0)              ; SR_ExecTime        PLC execution time in us
(SR0.10 = 201) = I0.1           ; SR_PlutoDisplay    W  Pluto display figure. For user error: 200+no
M0.11 = (SR0.11 > 0)            ; SR_ErrorCode       Error code
M0.12 = (SR0.12 > 0)            ; SR_ErrorLog1       Last error code
M0.13 = (SR0.13 > 0)            ; SR_ErrorLog2       2:nd last error code
M0.14 = (SR0.14 > 0)            ; SR_ErrorLog3       3:rd last error code
M0.40 = (SR0.40 > 0)            ; SR_SupplVolt       Supply voltage (x10 Volt)
; A20, B20, D20, S20, B22
M0.41 = (SR0.41 > 0)            ; SR_I5_Volt         Voltage analogue input I5 (x10 volt)
M0.42 = (SR0.42 > 0)            ; SR_Q16_Current     Current (mA) output no.Q16
M0.43 = (SR0.43 > 0)            ; SR_Q17_Current     Current (mA) output no.Q17

! pgm_pluto:01
S1.0_0
; B46, S46, D45
M1.41 = (SR1.41 > 0)            ; SR_I5_Volt         Voltage at analogue input I5 (x10 volt)
M1.45 = (SR1.45 > 0)            ; SR_I6_Volt         Voltage at analogue input I6 (x10 volt)
M1.46 = (SR1.46 > 0)            ; SR_I7_Volt         Voltage at analogue input I7 (x10 volt)

! pgm_pluto:02
S2.0_0
; Pluto AS-i
M2.15 = (SR2.15 > 0)            ; SR_ASi_Slave_Missing  First AS-i slave missing. B slave encoded as no+32
M2.16 = (SR2.16 > 0)            ; SR_ASi_Slave_Chanf    First AS-i slave channel fault. B slave encoded as no+32
M2.41 = (SR2.41 > 0)            ; SR_IQ11_Volt       Voltage analogue input IQ11 (x10 volt)
M2.44 = (SR2.44 > 0)            ; SR_IQ10_Volt       Voltage at analogue input IQ10 (x10 volt)
M2.45 = (SR2.45 > 0)            ; SR_IQ12_Volt       Voltage at analogue input IQ12 (x10 volt)
M2.46 = (SR2.46 > 0)            ; SR_IQ13_Volt       Voltage at analogue input IQ13 (x10 volt)

! pgm_pluto:03
S3.0_0
; B42 AS-i
M3.15 = (SR3.15 > 0)            ; SR_ASi_Slave_Missing  First AS-i slave missing. B slave encoded as no+32
M3.16 = (SR3.16 > 0)            ; SR_ASi_Slave_Chanf    First AS-i slave channel fault. B slave encoded as no+32
M3.41 = (SR3.41 > 0)            ; SR_I1_Volt         Voltage at analogue input I1 (x10 volt)
M3.45 = (SR3.45 > 0)            ; SR_I2_Volt         Voltage at analogue input I2 (x10 volt)
M3.46 = (SR3.46 > 0)            ; SR_I3_Volt         Voltage at analogue input I3 (x10 volt)
