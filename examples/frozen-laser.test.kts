// A laser that stays ACTIVE but stops publishing, on the system simulated from localisation.xml: the
// coordinator notices the silence on the data, not in any state, and switches to odometry and the gyro.
system("localisation.xml")
coordinator("frozen-laser.coord.kts")

// What `rtcoord test --explore` searches: the last scenario, with faults on the laser's data (freeze,
// repair, lost connectors, a hung execution), on the two localisers and the name server, in its first
// 6 s. Out of scope: a laser that leaves
// ACTIVE (the invariant's promise is that the coordinator never moves it: fail, breakDown and exit
// would break it by themselves), odometry and the gyro, and the slave manager, whose process hosts
// every component.
// The master manager's death is out of scope too: without it the switch cannot create the odometry
// localiser, so it fails, says so and leaves the laser localiser running, which the kept test
// frozen-laser.found-51-66.test.kts checks.
explore {
    scenarios("whatever the laser's data does, a localiser runs in the end")
    components("laser0", "laser_localise0", "odo_localise0")
    exclude { fail("laser0"); breakDown("laser0"); exit("laser0"); killManager() }
    window(0.seconds, 6.seconds)
}

// The coordinator reads the laser's data and never touches the laser itself.
never { component("laser0").state() != ACTIVE }

scenario("the laser goes silent while ACTIVE: odometry takes over, once") {
    at(2.seconds) { freeze("laser0") }
    expectLog("laser0 sent no scan for 500 ms while ACTIVE", within = 3.seconds)
    expect(within = 5.seconds) { component("odo_localise0").state() == ACTIVE }
    expectNoRestartsOf("laser0")
}

scenario("the gyro fails but the laser publishes: no switch") {
    never { component("odo_localise0").exists() }
    at(1.seconds) { fail("gyro0") }
    expect { component("gyro0").state() == ERROR }
    at(3.seconds) { repair("gyro0") }
    expect { component("laser_localise0").state() == ACTIVE }
}

scenario("whatever the laser's data does, a localiser runs in the end") {
    at(8.seconds) { }
    expect(within = 5.seconds) { components("*_localise?").any { it.state() == ACTIVE } }
}
