// A laser that stays ACTIVE but stops publishing, on the system simulated from localisation.xml: the
// coordinator notices the silence on the data, not in any state, and switches to odometry and the gyro.
system("localisation.xml")
coordinator("frozen-laser.coord.kts")

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
