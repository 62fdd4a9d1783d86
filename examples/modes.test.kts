// The paper's switch as modes of the whole system, on the system simulated from localisation.xml: when
// the laser fails, the machine goes to degraded/odometry and tracks on odometry and the gyro.
system("localisation.xml")
coordinator("modes.coord.kts")

// What `rtcoord test --explore` searches: the last scenario, with faults on the laser, the two
// localisers and the name server, in its first 6 s. Out of scope: odometry and the gyro, which both
// modes need, and the slave manager, whose process hosts every component. The master manager's death
// is out of scope too: without it the odometry mode cannot create its localiser, so its entry fails,
// says so, and the machine goes to degraded/safe, which the kept test modes.found-51-185.test.kts
// checks.
explore {
    scenarios("whatever happens to the laser and the localisers, one localiser runs in the end")
    components("laser0", "laser_localise0", "odo_localise0")
    exclude { killManager() }
    window(0.seconds, 6.seconds)
}

// A network's components stop before others start: two localisers never run at once.
never { component("laser_localise0").state() == ACTIVE && component("odo_localise0").state() == ACTIVE }
expectMode("localisation", "laser")

scenario("the laser breaks for good: degraded, tracking on odometry") {
    at(2.seconds) { breakDown("laser0") }
    expectMode("localisation", "odometry", within = 10.seconds)
    expectMode("localisation", "degraded/odometry/tracking", within = 10.seconds)
    expect { component("odo_localise0").state() == ACTIVE }
    expect { component("laser_localise0").state() == INACTIVE }
}

scenario("a laser fault a reset cures: degraded, the laser reset on entry") {
    at(1.seconds) { fail("laser0") }
    expectMode("localisation", "degraded/odometry/tracking", within = 10.seconds)
    expect { component("laser0").state() == INACTIVE && component("odo_localise0").state() == ACTIVE }
}

scenario("whatever happens to the laser and the localisers, one localiser runs in the end") {
    at(8.seconds) { }
    expect(within = 10.seconds) { components("*_localise?").any { it.state() == ACTIVE } }
}
