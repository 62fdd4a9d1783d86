// Found by `rtcoord test --explore` in localisation.test.kts, run 51:31, shrunk from 3 fault(s) to 2; replay it with `rtcoord test --explore --replay 51:31 localisation.test.kts`.
// While the coordinator has the fault, this test fails as the exploration did:
//   localisation.coord.kts:15: rule 'laser0.rtc is in or enters ERROR' failed: UnreachableException: /127.0.0.1:42031/vm.host_cxt/laser_localise0.rtc:laser: unreachable (OBJECT_NOT_EXIST: Server-side Exception: )

// The paper's coordinator on a system simulated from localisation.xml, which `rtcoord profile save`
// wrote from the fixture system (scripts/fixtures). When the laser fails the coordinator replaces the
// laser-based localiser by one on odometry and the gyro, whether or not the laser can be reset.
system("localisation.xml")
coordinator("localisation.coord.kts")

// What `rtcoord test --explore` searches (docs/testing.md, "Exploring faults"): the last scenario, with
// faults on the laser and the localisers, the master manager and the name server, in its first 6 s.
// Out of scope: odometry and the gyro, which the invariant says the switch never touches (a fault on
// them breaks the invariant, not the coordinator), and the slave manager, whose process hosts every
// component (killing it ends the system, which no coordinator can mend).
explore {
    scenarios("whatever happens to the laser and the manager, a localiser runs in the end")
    components("laser0", "laser_localise0", "odo_localise0")
    managers("manager")
    window(0.seconds, 6.seconds)
}

// What the new localiser needs is never touched by the switch.
always { component("odometry0").state() == ACTIVE && component("gyro0").state() == ACTIVE }
expect(within = 2.seconds) { component("laser_localise0").state() == ACTIVE }

scenario("whatever happens to the laser and the manager, a localiser runs in the end") {
    meanwhile {
        at(4.seconds) { breakDown("laser0") }
        at(4.seconds) { exit("laser_localise0") }
    }
    at(8.seconds) { }
    expect(within = 5.seconds) { components("*_localise?").any { it.state() == ACTIVE } }
}
