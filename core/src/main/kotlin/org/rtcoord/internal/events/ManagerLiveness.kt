package org.rtcoord.internal.events

import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import org.rtcoord.ComponentNode
import org.rtcoord.ManagerDied
import org.rtcoord.ManagerNode
import org.rtcoord.ManagerReturned
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.TimedOutException
import org.rtcoord.UnreachableException
import org.rtcoord.internal.TreeCore
import org.slf4j.LoggerFactory
import java.util.concurrent.ConcurrentHashMap
import kotlin.time.Duration

/**
 * Says once that a manager died, instead of leaving it to each of its components going silent: when
 * something a manager hosts stops answering, the manager is asked too; if it does not answer either,
 * one [ManagerDied] goes to [sinksOf] the manager and to [report], and the manager is asked again every
 * period until it answers ([ManagerReturned]) or nobody watches anything it hosted.
 *
 * When a manager's process dies its components vanish with it, and a master drops the manager from its
 * slaves only at its next failed call to it (OpenRTM-aist's `ManagerServant`): asking the manager
 * itself is the only prompt way to tell.
 */
internal class ManagerLiveness(
    private val core: TreeCore,
    private val sinksOf: (ManagerNode) -> Set<EventSink>,
    private val report: (RtcEvent) -> Unit,
) {
    private val log = LoggerFactory.getLogger(ManagerLiveness::class.java)

    /** Managers being asked, or found dead and asked again until they answer, by path. */
    private val checks = ConcurrentHashMap<RtcPath, Job>()

    /** Something [manager] hosts stopped answering: asks the manager, unless that is under way or it is known dead. */
    fun suspect(manager: ManagerNode, period: Duration) {
        checks.computeIfAbsent(manager.path) { core.scope.launch(start = CoroutineStart.LAZY) { check(manager, period) } }.start()
    }

    private suspend fun check(manager: ManagerNode, period: Duration) {
        try {
            val failure = failureOf(manager) ?: return
            val hosted = manager.listed.value.orEmpty().filterIsInstance<ComponentNode>()
            log.info("{}; its components {} went with it", failure.message, hosted.joinToString { it.name }.ifEmpty { "(none)" })
            publish(manager, ManagerDied(manager, hosted, failure))
            while (true) {
                delay(period)
                if (sinksOf(manager).isEmpty()) return
                if (failureOf(manager) == null) {
                    log.info("{}: answers again", manager.path)
                    publish(manager, ManagerReturned(manager))
                    return
                }
            }
        } finally {
            checks.remove(manager.path)
        }
    }

    /** Why [manager] does not answer; null when it does. */
    private suspend fun failureOf(manager: ManagerNode): RtcException? = try {
        manager.profile()
        null
    } catch (e: UnreachableException) {
        e
    } catch (e: TimedOutException) {
        e
    }

    private fun publish(manager: ManagerNode, event: RtcEvent) {
        sinksOf(manager).forEach { it.offer(event) }
        report(event)
    }
}
