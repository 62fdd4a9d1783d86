// The paper's scenario on a system simulated from localisation.xml, which `rtcoord profile save` wrote
// from the fixture system (scripts/fixtures). The laser breaks for good after 3 s; the coordinator
// cannot reset it, so it replaces the laser-based localiser by one on odometry and the gyro.
system("localisation.xml")
coordinator("localisation.coord.kts")

expect(within = 2.seconds) { component("laser_localise0").state() == ACTIVE }
at(3.seconds) { breakDown("laser0") }
expect(within = 5.seconds) { component("odo_localise0").state() == ACTIVE }
expect(within = 1.seconds) { component("laser_localise0").state() == INACTIVE }
expect { component("laser0").state() == ERROR }
expectLog("laser0 could not be reset")
expectNoRestartsOf("odometry0")
