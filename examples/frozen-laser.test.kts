// A laser that stays ACTIVE but stops publishing, on the system simulated from localisation.xml: the
// coordinator notices the silence on the data, not in any state, and switches to odometry and the gyro.
system("localisation.xml")
coordinator("frozen-laser.coord.kts")

at(2.seconds) { freeze("laser0") }
expectLog("laser0 sent no scan for 500 ms while ACTIVE", within = 3.seconds)
expect(within = 5.seconds) { component("odo_localise0").state() == ACTIVE }
expect { component("laser0").state() == ACTIVE }
expectNoRestartsOf("laser0")
