// bounded-restart.coord.kts with a limit of two, on the system simulated from localisation.xml: the
// gyro's failures are restarted up to the limit; past it, or when a reset fails, the gyro is left in
// ERROR for a person to look at.
system("localisation.xml")
coordinator("bounded-restart.coord.kts", "2")

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
