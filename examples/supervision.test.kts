// The supervisor of supervision.coord.kts on the system simulated from localisation.xml. A laser whose
// execution fails once is restarted with the localiser that depends on it (rest-for-one), the odometry
// declared before it left alone; a laser that stays broken ends in the escalation, which localises from
// odometry and the gyro instead.
system("localisation.xml")
coordinator("supervision.coord.kts")

// What `rtcoord test --explore` searches: the last scenario, with faults on the laser, the two
// localisers and the name server, in its first 6 s. Out of scope: odometry, which the invariant says
// the supervisor never stops, the gyro, and the slave manager, whose process hosts every component.
// The master manager's death is out of scope too: without it the escalation cannot create the odometry
// localiser, so it fails and says so, which the kept test supervision.found-51-302.test.kts checks.
explore {
    scenarios("whatever happens to the laser and its localiser, a localiser runs in the end")
    components("laser0", "laser_localise0", "odo_localise0")
    exclude { killManager() }
    window(0.seconds, 6.seconds)
}

// Rest-for-one: the odometry, declared before the laser, is never stopped.
never { component("odometry0").state() != ACTIVE }

scenario("a laser that fails once is restarted with its localiser") {
    at(2.seconds) { fail("laser0") }
    expectLog("laser0.rtc entered ERROR", within = 5.seconds)
    expectLog("restForOne: restarting", within = 5.seconds)
    expect(within = 5.seconds) { component("laser0").state() == ACTIVE && component("laser_localise0").state() == ACTIVE }
    expectNoRestartsOf("odometry0")
}

scenario("a laser that stays broken ends in the escalation: odometry takes over") {
    at(2.seconds) { breakDown("laser0") }
    expectLog("the laser cannot be restarted", within = 20.seconds)
    expect(within = 5.seconds) { component("odo_localise0").state() == ACTIVE }
    expect { component("laser_localise0").state() == INACTIVE }
    expectNoRestartsOf("odometry0")
}

scenario("whatever happens to the laser and its localiser, a localiser runs in the end") {
    at(8.seconds) { }
    expect(within = 25.seconds) { components("*_localise?").any { it.state() == ACTIVE } }
}
