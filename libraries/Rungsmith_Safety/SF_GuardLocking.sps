$name SF_GuardLocking
;@project description="Timing example of SF_GuardLocking (Rungsmith_Safety): one instance, every pin bound to a name equal to the pin's."

! id_pluto:00=000000000000
;@unit 00 description="SF_GuardLocking"
! type_pluto:00=A20,is3

! I0.0=Activate
! I0.1=S_GuardMonitoring
! I0.2=S_SafetyActive
! I0.3=S_GuardLock
! I0.4=UnlockRequest
! I0.5=S_StartReset
! I0.6=S_AutoReset
! I0.7=Reset
! M0.0=Ready
! Q0.0=S_GuardLocked
! Q0.1=S_UnlockGuard
! M0.1=Error
! R0.0=DiagCode

! pgm_pluto:00
! I0.0,static
! I0.1,static
! I0.2,static
! I0.3,static
! I0.4,static
! I0.5,static
! I0.6,static
! I0.7,static

S0.0_0
;@block SF_GuardLocking Activate="Activate" S_GuardMonitoring="S_GuardMonitoring" S_SafetyActive="S_SafetyActive" S_GuardLock="S_GuardLock" UnlockRequest="UnlockRequest" S_StartReset="S_StartReset" S_AutoReset="S_AutoReset" Reset="Reset" Ready="Ready" S_GuardLocked="S_GuardLocked" S_UnlockGuard="S_UnlockGuard" Error="Error" DiagCode="DiagCode"
;@end
