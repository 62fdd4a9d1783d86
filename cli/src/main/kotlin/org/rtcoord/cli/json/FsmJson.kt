package org.rtcoord.cli.json

import kotlinx.serialization.Serializable
import org.rtcoord.FsmStatus

/** A component's FSM as `cat`, `watch` and the live view give it: its [state], or null and why not. */
@Serializable
internal class FsmJson(
    /** The state the machine last entered; null when not known. */
    val state: String?,
    /** Why [state] is not known; null when it is. */
    val unknownBecause: String?,
) {
    companion object {
        /** [status] as the JSON gives it. */
        fun of(status: FsmStatus): FsmJson = FsmJson(status.state, status.unknownBecause)
    }
}
