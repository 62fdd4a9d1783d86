package org.rtcoord.dsl

import kotlin.time.Duration

/**
 * A supervisor gave up: [component] failed once more than its restart intensity allows. The supervisor stops watching
 * and restarting its components; `onEscalation` handlers decide what happens next.
 *
 * @property supervisor the supervisor, as its log lines name it.
 * @property component the path of the component whose failure escalated.
 * @property failure what happened to it (entered ERROR, lost, exited).
 * @property restarts how many restarts the supervisor made within [period] before this failure.
 */
public class Escalation
internal constructor(
    public val supervisor: String,
    public val component: String,
    public val failure: String,
    public val restarts: Int,
    public val period: Duration,
) {
    /** One line saying why the supervisor gave up. */
    public val reason: String
        get() = "$component $failure after $restarts restarts within $period"

    override fun toString(): String = "$supervisor escalates: $reason"
}
