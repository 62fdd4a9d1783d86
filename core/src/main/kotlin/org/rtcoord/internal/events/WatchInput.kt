package org.rtcoord.internal.events

import org.rtcoord.LifeCycle

/**
 * What happened to a watched component, as its [ComponentMonitor] tells its [ComponentWatch], in the order it took it.
 */
internal sealed interface WatchInput {
    /** A hint from the observer, received at [at]: a lifecycle hint, or one that something else changed. */
    class Hinted(val hint: Hint, val at: Long) : WatchInput

    /** Anything asks for a whole read (an attachment, a registration). */
    object ReadWanted : WatchInput

    /** A poll tick. */
    object Ticked : WatchInput

    /** A poll probe found [states] (by handle) in read [stamp], against what read number [epoch] expected. */
    class Probed(val states: Map<Int, LifeCycle>, val epoch: Long, val stamp: Long) : WatchInput

    /** A poll probe that could not finish alone. */
    object Unsettled : WatchInput

    /** [timer], armed for [at], fired. */
    class Fired(val timer: ComponentWatch.Timer, val at: Long) : WatchInput

    /** A marker came back through the observer. */
    class MarkerBack(val marker: String) : WatchInput

    /** The heartbeat watchdog found a beat overdue: the last sign of life came at [heardAt]. */
    class Overdue(val heardAt: Long) : WatchInput

    /** The registrations changed: how the component is watched is arranged anew. */
    object Reconfigured : WatchInput
}
