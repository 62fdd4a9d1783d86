// Found by `rtcoord test --explore` in laser-timeouts.test.kts, run 51:0, shrunk from 2 fault(s) to 2; replay it with `rtcoord test --explore --replay 51:0 laser-timeouts.test.kts`.
// While the coordinator has the fault, this test fails as the exploration did:
//   laser-timeouts.test.kts:4:1: rule 'laser0.rtc logs at WARN or above matching /timeout/, 3 times within 10s' failed: OperationFailedException: /127.0.0.1:40053/vm.host_cxt/odo_localise0.rtc: activate failed: RTC_ERROR (the component went to ERROR in context 0)

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
        at(3240.milliseconds) { fail("odo_localise0") }
        at(3240.milliseconds) { restartNaming() }
    }
    at(1.seconds) { log("laser0", WARN, "scan timeout") }
    at(2.seconds) { log("laser0", WARN, "scan timeout") }
    at(3.seconds) { log("laser0", ERROR, "scan timeout, retrying") }
    at(8.seconds) { }
    expect(within = 5.seconds) { components("*_localise?").any { it.state() == ACTIVE } }
}
