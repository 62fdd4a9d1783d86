// Found by `rtcoord test --explore` in laser-timeouts.test.kts, run 51:15, shrunk from 3 fault(s) to 1; replay it with `rtcoord test --explore --replay 51:15 laser-timeouts.test.kts`.
// While the coordinator has the fault, this test fails as the exploration did:
//   laser-timeouts.test.kts:47:5: expected components("*_localise?").any { it.state() == ACTIVE } within 5s, but it did not hold

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

scenario("three timeouts, whatever happens meanwhile: a localiser runs in the end") {
    meanwhile {
        at(3400.milliseconds) { breakDown("odo_localise0") }
    }
    at(1.seconds) { log("laser0", WARN, "scan timeout") }
    at(2.seconds) { log("laser0", WARN, "scan timeout") }
    at(3.seconds) { log("laser0", ERROR, "scan timeout, retrying") }
    at(8.seconds) { }
    expect(within = 5.seconds) { components("*_localise?").any { it.state() == ACTIVE } }
}
