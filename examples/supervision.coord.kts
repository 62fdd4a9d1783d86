// Keeps the localisation pipeline running. The odometry and the laser feed the laser localiser, which
// is declared after them because it depends on them: when the laser fails, the laser and the localiser
// restart together (restForOne) and the odometry is left alone. A component in ERROR is reset; one that
// died is re-created through its manager, connected as it was and put back in its configuration set;
// one re-created meanwhile by someone else (`rtmgr -c`, during a back-off) is followed, not created twice.
// Past LIMIT restarts a minute (the first argument, 3 by default) the supervisor gives up and stops the
// laser localiser. A laser or a laser localiser that stays broken (its resets keep failing) ends there
// too: the localisation then goes on from odometry and the gyro, as in the paper, with a localiser
// created for it (exploring found the broken laser localiser, which the supervisor gave up on alone).
val limit = args.firstOrNull()?.toInt() ?: 3

/** The state of the component [name], or null when it is gone (exited, or its process died). */
suspend fun Reaction.stateOf(name: String): LifeCycle? =
    try {
        component(name).state()
    } catch (gone: NotFoundException) {
        null
    } catch (dead: UnreachableException) {
        null
    }

supervise(component("odometry0.rtc"), component("laser0.rtc"), component("laser_localise0.rtc")) {
    strategy = restForOne
    maxRestarts = limit within 60.seconds
    backoff = exponential(200.milliseconds, max = 10.seconds)
    onEscalation { escalation ->
        log("giving up: ${escalation.reason}")
        val laserLocaliser = component("laser_localise0.rtc")
        attempt { laserLocaliser.disconnectAll() }
        // rest-for-one has left it stopped already when the laser could not be started; gone, it runs no more.
        if (stateOf("laser_localise0.rtc") == ACTIVE) laserLocaliser.deactivate()
        // The odometry localiser needs odometry: without it, nothing localises.
        if (escalation.component.endsWith("/odometry0.rtc")) return@onEscalation
        val which = if (escalation.component.endsWith("/laser0.rtc")) "the laser" else "the laser localiser"
        log("$which cannot be restarted: localising from odometry and the gyro")
        if (stateOf("odo_localise0.rtc") != null) return@onEscalation
        val localiser = manager().create("odo_localise")
        connect("odometry0.rtc:odo", localiser.port("odo"))
        connect("gyro0.rtc:gyro", localiser.port("gyro"))
        localiser.activate()
    }
}
