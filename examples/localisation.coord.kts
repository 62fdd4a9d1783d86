// The paper's coordinator: when the laser fails, replace the laser-based localiser by one that uses
// odometry and the gyro, created through the manager, connected and activated.
val manager = manager()

on(component("laser0.rtc")).state(ERROR) {
    reset()
    component("laser_localise0.rtc").run { disconnectAll(); deactivate() }
    val localiser = manager.create("odo_localise")
    connect("odometry0.rtc:odo", localiser.port("odo"))
    connect("gyro0.rtc:gyro", localiser.port("gyro"))
    localiser.activate()
}
