// A laser that stays ACTIVE but stops publishing looks healthy to every state rule. This coordinator
// watches the laser's data itself: when no scan comes for 500 ms while the laser is ACTIVE, it switches
// to the localiser that uses odometry and the gyro, as the paper does when the laser fails. The laser is
// left ACTIVE for a person to look at; it may be a cable, not the component.
val manager = manager()
var switched = false

on(port("laser0.rtc:laser")).silentFor(500.milliseconds) {
    if (switched) return@silentFor
    switched = true
    log("laser0 sent no scan for 500 ms while ACTIVE: switching to odometry")
    component("laser_localise0.rtc").run { disconnectAll(); deactivate() }
    val localiser = manager.create("odo_localise")
    connect("odometry0.rtc:odo", localiser.port("odo"))
    connect("gyro0.rtc:gyro", localiser.port("gyro"))
    localiser.activate()
}
