// Found by `rtcoord test --explore` in supervision.test.kts, run 51:67, shrunk from 2 fault(s) to 1; replay it with `rtcoord test --explore --replay 51:67 supervision.test.kts`.
// While the coordinator has the fault, this test fails as the exploration did:
//   supervision.test.kts:40:5: expected component("laser_localise0").state() == ACTIVE || component("odo_localise0").state() == ACTIVE within 25s, but it did not hold

// The supervisor of supervision.coord.kts on the system simulated from localisation.xml. A laser whose
// execution fails once is restarted with the localiser that depends on it (rest-for-one), the odometry
// declared before it left alone; a laser that stays broken ends in the escalation, which localises from
// odometry and the gyro instead.
system("localisation.xml")
coordinator("supervision.coord.kts")

// What `rtcoord test --explore` searches: the last scenario, with faults on the laser and the two
// localisers, the master manager (which creates the odometry localiser on escalation) and the name
// server, in its first 6 s. Out of scope: odometry, which the invariant says the supervisor never
// stops, the gyro, and the slave manager, whose process hosts every component.
explore {
    scenarios("whatever happens to the laser and its localiser, a localiser runs in the end")
    components("laser0", "laser_localise0", "odo_localise0")
    managers("manager")
    window(0.seconds, 6.seconds)
}

// Rest-for-one: the odometry, declared before the laser, is never stopped.
never { component("odometry0").state() != ACTIVE }

scenario("whatever happens to the laser and its localiser, a localiser runs in the end") {
    meanwhile {
        at(0.seconds) { breakDown("laser_localise0") }
    }
    at(8.seconds) { }
    expect(within = 25.seconds) { components("*_localise?").any { it.state() == ACTIVE } }
}
