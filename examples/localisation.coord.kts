// The paper's coordinator: when the laser fails, replace the laser-based localiser by one that uses
// odometry and the gyro, created through the manager, connected and activated. The laser is reset if it
// can be; a laser that stays broken cannot, and the switch goes on without it. A switch that fails half
// way (the manager refuses to create the new localiser) is taken back: the laser localiser runs again,
// connected as before, so some localiser always runs. A laser already in ERROR when the coordinator
// starts (it was restarted after the fault) is handled the same way: includeCurrent.
val manager = manager()

on(component("laser0.rtc")).state(ERROR, includeCurrent = true) {
    // A reset that fails looks like a slow one until its deadline: a second is enough for a laser.
    if (!attempt { reset(deadline = 1.seconds) }) log("laser0 could not be reset: switching to odometry without it")
    onFailure { failure ->
        log("the switch to odometry failed (${failure.cause.message}): back to the laser localiser")
        failure.undo()
        attempt { activate() }
    }
    component("laser_localise0.rtc").run { disconnectAll(); deactivate() }
    val localiser = manager.create("odo_localise")
    connect("odometry0.rtc:odo", localiser.port("odo"))
    connect("gyro0.rtc:gyro", localiser.port("gyro"))
    localiser.activate()
}
