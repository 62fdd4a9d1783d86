// The paper's coordinator: when the laser fails, replace the laser-based localiser by one that uses
// odometry and the gyro, created through the manager, connected and activated. The laser is reset if it
// can be; a laser that stays broken cannot, and the switch goes on without it. A switch that fails (the
// manager refuses to create the new localiser, or the switch fails half way) leaves or brings back the
// laser localiser, connected as before, so some localiser runs. A laser already in ERROR when the
// coordinator starts (it was restarted after the fault) is handled the same way: includeCurrent.
//
// Exploring the paper's story (`rtcoord test --explore localisation.test.kts`) found what it leaves out,
// and the rules below the first handle it: a localiser that fails or exits by itself is replaced too,
// and the switch stops the laser localiser only as far as it still runs.
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

on(component("laser0.rtc")).state(ERROR, includeCurrent = true) {
    // A reset that fails looks like a slow one until its deadline: a second is enough for a laser.
    if (!attempt { reset(deadline = 1.seconds) }) log("laser0 could not be reset: switching to odometry without it")
    // A switch that fails is taken back (below), and the laser, reset, runs again.
    onFailure { attempt { activate() } }
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
