// The paper's switch as modes of the whole system, on the system simulated from localisation.xml: the
// laser breaks for good, the machine goes to degraded/odometry and tracks on odometry and the gyro.
system("localisation.xml")
coordinator("modes.coord.kts")

expectMode("localisation", "laser")
at(2.seconds) { breakDown("laser0") }
expectMode("localisation", "odometry", within = 10.seconds)
expectMode("localisation", "degraded/odometry/tracking", within = 10.seconds)
expect { component("odo_localise0").state() == ACTIVE }
expect { component("laser_localise0").state() == INACTIVE }
