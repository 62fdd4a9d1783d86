// Found by `rtcoord test --explore` in frozen-laser.test.kts, run 51:66, shrunk from 3 fault(s) to 2; replay it with `rtcoord test --explore --replay 51:66 frozen-laser.test.kts`.
// Kept as a regression test: without the master the switch cannot create the odometry localiser. It
// fails and says so, and as it creates before it stops anything, the laser localiser runs on. It failed
// before as:
//   frozen-laser.coord.kts:13: rule laser0.rtc:laser silent for 500ms failed: UnreachableException: /127.0.0.1:34649/vm.host_cxt/manager.mgr: unreachable (cannot connect to 127.0.0.1:41885)

// A laser that stays ACTIVE but stops publishing, on the system simulated from localisation.xml: the
// coordinator notices the silence on the data, not in any state, and switches to odometry and the gyro.
system("localisation.xml")
coordinator("frozen-laser.coord.kts")

// What `rtcoord test --explore` searches: the last scenario, with faults on the laser's data (freeze,
// repair, lost connectors, a hung execution), on the two localisers, the master manager (which creates
// the odometry localiser) and the name server, in its first 6 s. Out of scope: a laser that leaves
// ACTIVE (the invariant's promise is that the coordinator never moves it: fail, breakDown and exit
// would break it by themselves), odometry and the gyro, and the slave manager, whose process hosts
// every component.
explore {
    scenarios("whatever the laser's data does, a localiser runs in the end")
    components("laser0", "laser_localise0", "odo_localise0")
    managers("manager")
    exclude { fail("laser0"); breakDown("laser0"); exit("laser0") }
    window(0.seconds, 6.seconds)
}

// The coordinator reads the laser's data and never touches the laser itself.
never { component("laser0").state() != ACTIVE }

scenario("whatever the laser's data does, a localiser runs in the end") {
    meanwhile {
        at(0.seconds) { killManager("manager") }
        at(0.seconds) { hang("laser0") }
    }
    expectHandlerFailure("manager.mgr", within = 8.seconds)
    at(8.seconds) { }
    expect(within = 5.seconds) { components("*_localise?").any { it.state() == ACTIVE } }
}
