// bounded-restart.coord.kts with a limit of two, on the system simulated from localisation.xml: the
// gyro's failures are restarted up to the limit; past it, or when a reset fails, the gyro is left in
// ERROR for a person to look at.
system("localisation.xml")
coordinator("bounded-restart.coord.kts", "2")

// What `rtcoord test --explore` searches: the last scenario, with any fault on the gyro and the name
// server in its first 6 s. Out of scope: the laser and odometry, which the invariant says the
// coordinator never touches (a fault on them breaks the invariant, not the coordinator), and the
// managers (the slave's process hosts every component; the coordinator creates nothing).
explore {
    scenarios("whatever happens to the gyro, the rest runs on")
    components("gyro0")
    exclude { killManager() }
    window(0.seconds, 6.seconds)
}

// The coordinator looks after the gyro alone.
never { component("laser0").state() != ACTIVE || component("odometry0").state() != ACTIVE }

scenario("two failures are restarted, the third is left in ERROR") {
    at(1.seconds) { fail("gyro0") }
    expectLog("gyro0 failed: restart 1 of 2", within = 3.seconds)
    expect(within = 3.seconds) { component("gyro0").state() == ACTIVE }
    at(4.seconds) { fail("gyro0") }
    expectLog("gyro0 failed: restart 2 of 2", within = 3.seconds)
    expect(within = 3.seconds) { component("gyro0").state() == ACTIVE }
    at(7.seconds) { fail("gyro0") }
    expectLog("gyro0 failed 3 times: leaving it in ERROR", within = 3.seconds)
    expect { component("gyro0").state() == ERROR }
}

scenario("a gyro that cannot be reset is left in ERROR at once") {
    at(1.seconds) { breakDown("gyro0") }
    expectLog("gyro0 cannot be reset: leaving it in ERROR", within = 10.seconds)
    expect { component("gyro0").state() == ERROR }
}

scenario("whatever happens to the gyro, the rest runs on") {
    at(8.seconds) { }
    expect { component("laser_localise0").state() == ACTIVE }
}
