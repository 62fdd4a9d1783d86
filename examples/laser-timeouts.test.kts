// The laser's driver logs timeouts before the laser fails, on the system simulated from localisation.xml:
// the coordinator switches to odometry and the gyro on the third within ten seconds, and not before.
system("localisation.xml")
coordinator("laser-timeouts.coord.kts")

// What `rtcoord test --explore` searches: the last scenario (three timeouts logged, so the switch
// happens), with faults on the two localisers and the name server, in its first 6 s. Out of scope: the
// laser, which the invariant says the coordinator never touches, odometry and the gyro, and the slave
// manager, whose process hosts every component.
// The master manager's death is out of scope too: without it the switch cannot create the odometry
// localiser, so it fails, says so and leaves the laser localiser running, which the kept test
// laser-timeouts.found-51-20.test.kts checks.
explore {
    scenarios("three timeouts, whatever happens meanwhile: a localiser runs in the end")
    components("laser_localise0", "odo_localise0")
    exclude { killManager() }
    window(0.seconds, 6.seconds)
}

// It acts on what the laser says, never on the laser itself.
never { component("laser0").state() != ACTIVE }

scenario("three timeouts: odometry takes over before the laser fails") {
    at(1.seconds) { log("laser0", WARN, "scan timeout") }
    at(2.seconds) { log("laser0", WARN, "scan timeout") }
    expect { component("laser_localise0").state() == ACTIVE }
    at(3.seconds) { log("laser0", ERROR, "scan timeout, retrying") }
    expectLog("laser0 logged repeated timeouts", within = 3.seconds)
    expect(within = 5.seconds) { component("odo_localise0").state() == ACTIVE }
}

scenario("other warnings, timeouts below WARN and the gyro's: no switch") {
    never { component("odo_localise0").exists() }
    at(1.seconds) { log("laser0", WARN, "intensity low") }
    at(2.seconds) { log("laser0", WARN, "scan timeout") }
    at(3.seconds) { log("laser0", INFO, "scan timeout") }
    at(4.seconds) { log("gyro0", WARN, "scan timeout") }
    at(5.seconds) { log("laser0", WARN, "scan timeout") }
    expect { component("laser_localise0").state() == ACTIVE }
}

scenario("three timeouts, whatever happens meanwhile: a localiser runs in the end") {
    at(1.seconds) { log("laser0", WARN, "scan timeout") }
    at(2.seconds) { log("laser0", WARN, "scan timeout") }
    at(3.seconds) { log("laser0", ERROR, "scan timeout, retrying") }
    at(8.seconds) { }
    expect(within = 5.seconds) { components("*_localise?").any { it.state() == ACTIVE } }
}
