package org.rtcoord.sim.test

import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.LifeCycle

/**
 * What a condition (`expect { }`, `always { }`, `never { }`) can look at: the simulated system's components and the
 * coordinator's modes and log. Every read is recorded with what it returned, and a failure shows them:
 * `component("laser_localise0").state() was INACTIVE`.
 *
 * An `expect` reads the system as it is when the condition is read (a component's state is asked of the component). An
 * invariant reads it as it was just after the event it is checked on: states, which components exist, modes and the log
 * as the events up to that one told them; a snapshot is the tree's latest.
 */
@TestDsl
public interface Observation {
    /** The component [name] (`odo_localise0` or `odo_localise0.rtc`) of the simulated system, there or not (yet). */
    public fun component(name: String): ObservedComponent

    /**
     * The components of the simulated system whose instance names match the glob [pattern] (`*` any run of characters,
     * `?` one), in name order: `components("odo_localise*").any { it.state() == ACTIVE }` holds whichever instance a
     * manager created (OpenRTM-aist names one created while an exited one still holds `odo_localise0` `odo_localise1`).
     */
    public suspend fun components(pattern: String): List<ObservedComponent>

    /**
     * The active mode of the coordinator's mode machine [machine] (`localisation/degraded/odometry`), or null before it
     * has one.
     */
    public fun modeOf(machine: String): String?

    /**
     * The coordinator's log so far, one line a message: what it writes as rules fire, actions run, modes change and
     * handlers fail, and what the script's `log` and `warn` say (`warn` lines start with `warning:`).
     */
    public val log: List<String>
}

/** A component of the simulated system, as a condition reads it. */
@TestDsl
public interface ObservedComponent {
    /** The instance name, without `.rtc`. */
    public val name: String

    /** Its state in its default execution context; [LifeCycle.UNKNOWN] while the system has no such component. */
    public suspend fun state(): LifeCycle

    /** Whether the system has it (it was not created yet, or it exited, otherwise). */
    public suspend fun exists(): Boolean

    /** What the tree last read of it; throws when the system has no such component. */
    public suspend fun snapshot(): ComponentSnapshot

    /** The component itself, for what the other reads do not cover; what is read through it is not recorded. */
    public suspend fun node(): ComponentNode
}
