// bounded-restart.coord.kts with a limit of two, on the system simulated from localisation.xml: the
// gyro's first two failures are restarted; the third is left in ERROR for a person to look at.
system("localisation.xml")
coordinator("bounded-restart.coord.kts", "2")

at(1.seconds) { fail("gyro0") }
expectLog("gyro0 failed: restart 1 of 2", within = 3.seconds)
expect(within = 3.seconds) { component("gyro0").state() == ACTIVE }
at(4.seconds) { fail("gyro0") }
expectLog("gyro0 failed: restart 2 of 2", within = 3.seconds)
expect(within = 3.seconds) { component("gyro0").state() == ACTIVE }
at(7.seconds) { fail("gyro0") }
expectLog("gyro0 failed 3 times: leaving it in ERROR", within = 3.seconds)
expect { component("gyro0").state() == ERROR }
