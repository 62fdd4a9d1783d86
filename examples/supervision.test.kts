// The supervisor of supervision.coord.kts on the system simulated from localisation.xml. A laser whose
// execution fails once is reset with the localiser that depends on it (rest-for-one), the odometry
// declared before it left alone; a laser that stays broken ends in the escalation, which localises from
// odometry and the gyro instead.
system("localisation.xml")
coordinator("supervision.coord.kts")

at(2.seconds) { fail("laser0") }
expectLog("laser0.rtc entered ERROR", within = 5.seconds)
expectLog("restForOne: restarting", within = 5.seconds)
expect(within = 5.seconds) { component("laser0").state() == ACTIVE && component("laser_localise0").state() == ACTIVE }
at(4.seconds) { breakDown("laser0") }
expectLog("the laser cannot be restarted", within = 20.seconds)
expect(within = 5.seconds) { component("odo_localise0").state() == ACTIVE }
expect { component("laser_localise0").state() == INACTIVE }
expectNoRestartsOf("odometry0")
