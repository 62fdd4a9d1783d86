// Found by `rtcoord test --explore` in modes.test.kts, run 51:12, shrunk from 2 fault(s) to 2; replay it with `rtcoord test --explore --replay 51:12 modes.test.kts`.
// While the coordinator has the fault, this test fails as the exploration did:
//   modes.test.kts:37:5: expected components("*_localise?").any { it.state() == ACTIVE } within 10s, but it did not hold

// The paper's switch as modes of the whole system, on the system simulated from localisation.xml: when
// the laser fails, the machine goes to degraded/odometry and tracks on odometry and the gyro.
system("localisation.xml")
coordinator("modes.coord.kts")

// What `rtcoord test --explore` searches: the last scenario, with faults on the laser, the two
// localisers, the master manager (which creates the odometry localiser) and the name server, in its
// first 6 s. Out of scope: odometry and the gyro, which both modes need, and the slave manager, whose
// process hosts every component.
explore {
    scenarios("whatever happens to the laser and the localisers, one localiser runs in the end")
    components("laser0", "laser_localise0", "odo_localise0")
    managers("manager")
    window(0.seconds, 6.seconds)
}

// A network's components stop before others start: two localisers never run at once.
never { component("laser_localise0").state() == ACTIVE && component("odo_localise0").state() == ACTIVE }
expectMode("localisation", "laser")

scenario("whatever happens to the laser and the localisers, one localiser runs in the end") {
    meanwhile {
        at(0.seconds) { exit("laser0") }
        at(0.seconds) { fail("laser_localise0") }
    }
    at(8.seconds) { }
    expect(within = 10.seconds) { components("*_localise?").any { it.state() == ACTIVE } }
}
