package org.rtcoord.internal.events

import java.util.concurrent.ConcurrentHashMap
import kotlin.time.Duration
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import org.rtcoord.Node
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.TimedOutException
import org.rtcoord.UnreachableException
import org.rtcoord.internal.TreeCore
import org.slf4j.LoggerFactory

/**
 * Says once that a process everything else depends on stopped answering (a manager, a name server), instead of leaving
 * it to each thing below it failing on its own: when something it stands behind fails, [probe] asks it; if it does not
 * answer either, one [lost] event goes to [sinksOf] it (whoever watches something behind it, and whoever wants every
 * report), and it is asked again every period until it answers ([back], with how long it was gone) or nobody is left to
 * tell.
 *
 * When a manager's process dies its components vanish with it, and a master drops the manager from its slaves only at
 * its next failed call to it (OpenRTM-aist's `ManagerServant`): asking the manager itself is the only prompt way to
 * tell. A name server's outage makes every listing below it fail at once.
 */
internal class Outages<T : Node>(
    private val core: TreeCore,
    private val sinksOf: (T) -> Set<EventSink>,
    private val probe: suspend (T) -> Unit,
    private val lost: (T, RtcException) -> RtcEvent,
    private val back: (T, Long) -> RtcEvent,
    /** Called once [node] is found lost, after its event. */
    private val whenLost: (T) -> Unit = {},
) {
    private val log = LoggerFactory.getLogger(Outages::class.java)

    /** Nodes being asked, or found lost and asked again until they answer, by path. */
    private val checks = ConcurrentHashMap<RtcPath, Job>()

    /** Something behind [node] failed: asks [node], unless that is under way or it is known lost. */
    fun suspect(node: T, period: Duration) {
        checks
            .computeIfAbsent(node.path) { core.scope.launch(start = CoroutineStart.LAZY) { check(node, period) } }
            .start()
    }

    private suspend fun check(node: T, period: Duration) {
        try {
            val failure = failureOf(node) ?: return
            val since = core.time.markNow()
            val event = lost(node, failure)
            log.info("{}: {}", node.path, failure.reason)
            publish(node, event)
            whenLost(node)
            while (true) {
                delay(period)
                if (sinksOf(node).isEmpty()) return
                if (failureOf(node) == null) {
                    log.info("{}: answers again", node.path)
                    publish(node, back(node, since.elapsedNow().inWholeMilliseconds))
                    return
                }
            }
        } finally {
            checks.remove(node.path)
        }
    }

    /** Why [node] does not answer; null when it does, even wrongly (the next failure behind it asks again). */
    private suspend fun failureOf(node: T): RtcException? =
        try {
            probe(node)
            null
        } catch (e: UnreachableException) {
            e
        } catch (e: TimedOutException) {
            e
        } catch (e: RtcException) {
            log.debug("{}: answered the check with {}", node.path, e.reason)
            null
        }

    private fun publish(node: T, event: RtcEvent) {
        val sinks = sinksOf(node)
        core.model.publish(listOf(event)) { published -> sinks.forEach { it.offer(published) } }
    }
}
