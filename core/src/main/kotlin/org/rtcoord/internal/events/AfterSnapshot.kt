package org.rtcoord.internal.events

import kotlinx.coroutines.CompletableDeferred
import org.rtcoord.RtcEvent

/**
 * A followed registration's handler: passes [handler] the events after the snapshot's sequence, once [begun] holds it
 * (those up to it are in the snapshot). Failures name what [handler] stands for.
 */
internal class AfterSnapshot(
    private val begun: CompletableDeferred<Long>,
    private val handler: suspend (RtcEvent) -> Unit,
) : suspend (RtcEvent) -> Unit, StandIn {
    override val listener: Any = (handler as? StandIn)?.listener ?: handler

    override suspend fun invoke(event: RtcEvent) {
        if (event.sequence > begun.await()) handler(event)
    }
}
