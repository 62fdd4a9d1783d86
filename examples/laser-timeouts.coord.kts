// A laser usually says it is failing before it fails: its driver logs scan timeouts. This coordinator
// hears the laser's log records (run it with --logs-listen, where the components' rtc.conf sends them)
// and, at the third timeout within ten seconds, switches to the localiser that uses odometry and the
// gyro, as the paper does once the laser has failed. The laser is left running for a person to look at.
val manager = manager()
var switched = false

on(component("laser0.rtc")).logged(WARN, matching = Regex("timeout"), atLeast = 3, within = 10.seconds) { record ->
    if (switched) return@logged
    switched = true
    log("laser0 logged repeated timeouts (${record.message}): switching to odometry before it fails")
    component("laser_localise0.rtc").run { disconnectAll(); deactivate() }
    val localiser = manager.create("odo_localise")
    connect("odometry0.rtc:odo", localiser.port("odo"))
    connect("gyro0.rtc:gyro", localiser.port("gyro"))
    localiser.activate()
}
