// Keeps the localisation pipeline running. The odometry and the laser feed the laser localiser, which
// is declared after them because it depends on them: when the laser fails, the laser and the localiser
// restart together (restForOne) and the odometry is left alone. A component in ERROR is reset; one that
// died is re-created through its manager, connected as it was and put back in its configuration set.
// Past LIMIT restarts a minute (the first argument, 3 by default) the supervisor gives up and stops the
// localiser for a person to look at.
val limit = args.firstOrNull()?.toInt() ?: 3

supervise(component("odometry0.rtc"), component("laser0.rtc"), component("laser_localise0.rtc")) {
    strategy = restForOne
    maxRestarts = limit within 60.seconds
    backoff = exponential(200.milliseconds, max = 10.seconds)
    onEscalation { escalation ->
        log("giving up: ${escalation.reason}")
        component("laser_localise0.rtc").deactivate()
    }
}
