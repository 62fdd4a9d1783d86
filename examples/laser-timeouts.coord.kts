// A laser usually says it is failing before it fails: its driver logs scan timeouts. This coordinator
// hears the laser's log records (run it with --logs-listen, where the components' rtc.conf sends them)
// and, at the third timeout within ten seconds, switches to the localiser that uses odometry and the
// gyro, as the paper does once the laser has failed. The laser is left running for a person to look at.
// As localisation.coord.kts does, it also replaces a localiser that fails or exits by itself, and stops
// the laser localiser only as far as it still runs: exploring found both.
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock

val manager = manager()

// Rules' handlers run side by side: the laser and its localiser failing together must not create two.
val switching = Mutex()

// The odometry localiser, once created: odo_localise0, or odo_localise1 when it was created again while
// the manager still held the name of one that exited, as OpenRTM-aist names them.
var odometryLocaliser: ComponentRef? = null

/** The state of [component], or null when it is gone (exited, or its process died). */
suspend fun stateOf(component: ComponentRef?): LifeCycle? =
    try {
        component?.state()
    } catch (gone: NotFoundException) {
        null
    } catch (dead: UnreachableException) {
        null
    }

/**
 * Localises from odometry and the gyro, unless that runs already. The new localiser is created before the
 * laser localiser stops, so a manager that cannot create it leaves that one running; a switch that fails
 * later is taken back. A laser localiser in ERROR (OpenRTM-aist refuses to deactivate it there) or gone
 * runs no more, so only an ACTIVE one is stopped. An odometry localiser that failed is reset, and if it
 * cannot be, the laser localiser takes over again; one that is gone is created again.
 */
suspend fun Reaction.localiseFromOdometry() = switching.withLock {
    val state = stateOf(odometryLocaliser)
    if (state == ACTIVE) return@withLock
    if (state == ERROR && !attempt { odometryLocaliser!!.reset() }) return@withLock localiseFromLaser()
    // Taken back under the lock (the failure has left it), unless another rule has switched meanwhile.
    onFailure { failure ->
        switching.withLock {
            if (stateOf(odometryLocaliser) == ACTIVE) return@withLock
            log("the switch to odometry failed (${failure.cause.message}): back to the laser localiser")
            failure.undo()
        }
    }
    val localiser = odometryLocaliser.takeIf { state != null } ?: manager.create("odo_localise")
    odometryLocaliser = localiser
    val laserLocaliser = component("laser_localise0.rtc")
    // A hung one cannot stop (its execution never returns), and one may exit meanwhile: the switch goes on.
    if (stateOf(laserLocaliser) == ACTIVE && !attempt { laserLocaliser.run { disconnectAll(); deactivate() } })
        log("laser_localise0 could not be stopped: the switch goes on without it")
    if (state == null) {
        try {
            connect("odometry0.rtc:odo", localiser.port("odo"))
            connect("gyro0.rtc:gyro", localiser.port("gyro"))
        } catch (failure: RtcException) {
            // One that exited as it was being connected is replaced by the rule for exits, once this switch is over.
            if (stateOf(localiser) != null) throw failure
            log("$localiser exited as it was being connected: it is replaced")
            return@withLock
        }
    }
    // One that fails as it starts is reset and started again, once; one broken for good hands back.
    if (!attempt { localiser.activate() } && !attempt { localiser.run { reset(); activate() } }) localiseFromLaser()
}

/** Back to the laser localiser, connected again, when the odometry one is broken for good and the laser runs. */
suspend fun Reaction.localiseFromLaser() {
    val laserLocaliser = component("laser_localise0.rtc")
    if (stateOf(component("laser0.rtc")) != ACTIVE || stateOf(laserLocaliser) != INACTIVE) {
        warn("the odometry localiser is broken, and the laser or its localiser cannot run: no localiser runs")
        return
    }
    log("the odometry localiser is broken: back to the laser localiser")
    attempt { odometryLocaliser?.disconnectAll() }
    if (laserLocaliser.port("laser").peers().isEmpty()) connect("laser0.rtc:laser", laserLocaliser.port("laser"))
    if (laserLocaliser.port("odo").peers().isEmpty()) connect("odometry0.rtc:odo", laserLocaliser.port("odo"))
    laserLocaliser.activate()
}

on(component("laser0.rtc")).logged(WARN, matching = Regex("timeout"), atLeast = 3, within = 10.seconds) { record ->
    if (stateOf(odometryLocaliser) == ACTIVE) return@logged
    log("laser0 logged repeated timeouts (${record.message}): switching to odometry before it fails")
    localiseFromOdometry()
}

// A localiser that fails or exits by itself: the odometry one replaces the laser one, and itself.
on(component("*_localise*")).state(ERROR, includeCurrent = true) { failure ->
    log("${failure.path.name} failed: localising from odometry")
    localiseFromOdometry()
}
on(component("*_localise*")).finalized { exit ->
    log("${exit.path.name} exited: localising from odometry")
    localiseFromOdometry()
}
