@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.sim.test

import org.rtcoord.InternalRtcoordApi
import org.rtcoord.LifeCycle
import org.rtcoord.LogLevel
import org.rtcoord.dsl.script.LogLevelNames

/**
 * The faults and actions an `at(...) { }` step applies to the simulated system, by component name (`laser0` or
 * `laser0.rtc`).
 */
@TestDsl
public interface Faults {
    /** The component breaks: it goes to ERROR and every reset fails until [repair]. */
    public fun breakDown(component: String)

    /** The component's next execution fails: it goes to ERROR; a reset recovers it. */
    public fun fail(component: String)

    /** Ends [breakDown], [hang] and [freeze]. */
    public fun repair(component: String)

    /** Its out-ports stop publishing while it stays ACTIVE. */
    public fun freeze(component: String)

    /** Its `on_execute` never returns, stalling its execution context. */
    public fun hang(component: String)

    /** The component exits, as rtexit does. */
    public fun exit(component: String)

    /** Every connector of the component's ports is lost, as when its peer stops answering: both ends drop it. */
    public fun loseConnectors(component: String)

    /** The master manager's process dies, with the components it hosts itself. */
    public fun killManager()

    /**
     * The process of manager [name] dies with every component it hosts: a slave (`localisation`, or
     * `manager.mgr/localisation`) or the master (`manager.mgr`), as the profile saved them.
     */
    public fun killManager(name: String)

    /** The naming service restarts with its bindings. */
    public fun restartNaming()

    /**
     * The component logs [message] at [level], as its OpenRTM-aist logger would: the record reaches the coordinator's
     * tree through its log input, from the component (`log("laser0", WARN, "scan timeout")`).
     */
    public fun log(component: String, level: LogLevel, message: String)

    /** [log] at [LogLevel.ERROR], for a scenario's bare `log("laser0", ERROR, ...)` (see [LogLevelNames]). */
    public fun log(component: String, level: LifeCycle, message: String): Unit =
        log(component, LogLevelNames.of(level), message)
}
