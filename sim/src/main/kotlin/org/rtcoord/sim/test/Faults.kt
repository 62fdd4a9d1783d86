package org.rtcoord.sim.test

/** The faults and actions an `at(...) { }` step applies to the simulated system, by component name (`laser0` or `laser0.rtc`). */
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

    /** The manager's process dies. */
    public fun killManager()

    /** The naming service restarts with its bindings. */
    public fun restartNaming()
}
