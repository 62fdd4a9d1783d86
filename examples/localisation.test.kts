// The paper's coordinator on a system simulated from localisation.xml, which `rtcoord profile save`
// wrote from the fixture system (scripts/fixtures). When the laser fails the coordinator replaces the
// laser-based localiser by one on odometry and the gyro, whether or not the laser can be reset.
system("localisation.xml")
coordinator("localisation.coord.kts")

// What `rtcoord test --explore` searches (docs/testing.md, "Exploring faults"): the last scenario, with
// faults on the laser, the localisers and the name server, in its first 6 s.
// Out of scope: odometry and the gyro, which the invariant says the switch never touches (a fault on
// them breaks the invariant, not the coordinator), and the slave manager, whose process hosts every
// component (killing it ends the system, which no coordinator can mend).
// The master manager's death is out of scope too: without it the switch cannot create the odometry
// localiser, so it fails, says so and takes the switch back (ExamplesTest checks it on the fixtures).
explore {
    scenarios("whatever happens to the laser and the localisers, a localiser runs in the end")
    components("laser0", "laser_localise0", "odo_localise0")
    exclude { killManager() }
    window(0.seconds, 6.seconds)
}

// What the new localiser needs is never touched by the switch.
always { component("odometry0").state() == ACTIVE && component("gyro0").state() == ACTIVE }
expect(within = 2.seconds) { component("laser_localise0").state() == ACTIVE }

scenario("the laser breaks for good: odometry takes over without it") {
    at(3.seconds) { breakDown("laser0") }
    expect(within = 5.seconds) { component("odo_localise0").state() == ACTIVE }
    expect(within = 1.seconds) { component("laser_localise0").state() == INACTIVE }
    expect { component("laser0").state() == ERROR }
    expectLog("laser0 could not be reset")
    expectNoRestartsOf("odometry0")
}

scenario("a laser fault a reset cures: the laser is reset, odometry takes over") {
    at(1.seconds) { fail("laser0") }
    expect(within = 5.seconds) { component("odo_localise0").state() == ACTIVE }
    expect { component("laser0").state() == INACTIVE && component("laser_localise0").state() == INACTIVE }
}

scenario("whatever happens to the laser and the localisers, a localiser runs in the end") {
    at(8.seconds) { }
    expect(within = 5.seconds) { components("*_localise?").any { it.state() == ACTIVE } }
}
