// Found by `rtcoord test --explore` in supervision.test.kts, run 51:302, shrunk from 2 fault(s) to 2; replay it with `rtcoord test --explore --replay 51:302 supervision.test.kts`.
// Kept as a regression test: the supervisor gives up on a laser localiser broken for good, and without
// the master its escalation cannot create the odometry localiser: it fails and says so. It failed
// before as:
//   supervision.coord.kts:37: escalation handler of supervisor(odometry0.rtc, laser0.rtc, laser_localise0.rtc) failed: NotFoundException: manager.mgr: no such manager on 127.0.0.1:46393

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
        at(0.seconds) { killManager("manager") }
        at(0.seconds) { breakDown("laser_localise0") }
    }
    expectLog("the laser localiser cannot be restarted", within = 25.seconds)
    expectHandlerFailure("manager.mgr")
}
