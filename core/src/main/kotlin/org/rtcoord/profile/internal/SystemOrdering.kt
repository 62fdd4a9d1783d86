package org.rtcoord.profile.internal

import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.TimeoutCancellationException
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import org.rtcoord.ComponentNode
import org.rtcoord.ContextSelector
import org.rtcoord.RtcException
import org.rtcoord.RtcTree
import org.rtcoord.TransitionOutcome
import org.rtcoord.internal.pollUntil
import org.rtcoord.profile.Condition
import org.rtcoord.profile.OrderedAction
import org.rtcoord.profile.OrderedTarget
import org.rtcoord.profile.PlannedStep
import org.rtcoord.profile.ProfileRefusedException
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.StepOutcome
import org.rtcoord.profile.TargetComponent

/** Plans and runs an ordered start or stop. */
internal class SystemOrdering(private val tree: RtcTree) {
    fun plan(profile: RtsProfile, action: OrderedAction): List<PlannedStep> {
        val targets =
            profile.orderings[action.ordering]?.targets
                ?: profile.components.map { OrderedTarget(0, TargetComponent(it.id, it.instanceName, contextId = "0")) }
        return targets
            .sortedBy { it.sequence }
            .map { t ->
                val component =
                    profile.component(t.target)
                        ?: throw ProfileRefusedException(
                            "${action.ordering.xmlName} names ${t.target.instanceName}, which the profile does not have"
                        )
                PlannedStep(
                    t.sequence,
                    "/" + component.pathUri.removePrefix("/"),
                    t.target.contextId?.toIntOrNull() ?: 0,
                    t.condition,
                )
            }
    }

    suspend fun run(profile: RtsProfile, action: OrderedAction, stepDeadline: Duration): List<StepOutcome> {
        val steps = plan(profile, action)
        val nodes = steps.associate { it.component to tree.component(it.component) }
        val byInstance = profile.components.associate { it.instanceName to "/" + it.pathUri.removePrefix("/") }
        val issued = steps.associateWith { CompletableDeferred<Boolean>() }
        val finished = steps.associateWith { CompletableDeferred<Boolean>() }
        val outcomes = java.util.concurrent.ConcurrentHashMap<PlannedStep, StepOutcome>()
        val start = tree.core.time.markNow()
        coroutineScope {
            for (step in steps) launch {
                // Earlier sequences' time is theirs: a step's deadline starts once they are done.
                val failed = steps.filter { it.sequence < step.sequence }.firstOrNull { !finished.getValue(it).await() }
                var slow = ""
                val outcome =
                    if (failed != null) "not done: ${failed.component} before it was not done"
                    else
                        try {
                            withTimeout(stepDeadline + conditionTime(step.condition)) {
                                when (val c = step.condition) {
                                    is Condition.WaitTime -> delay(c.milliseconds.milliseconds)
                                    is Condition.Preceding ->
                                        awaitPreceding(c, action, steps, byInstance, nodes, issued, finished)?.let {
                                            return@withTimeout it
                                        }
                                    Condition.None -> Unit
                                }
                                issued.getValue(step).complete(true)
                                act(
                                        nodes.getValue(step.component),
                                        ContextSelector.Handle(step.contextId),
                                        action,
                                        stepDeadline,
                                    )
                                    ?.takeIf { it.slow }
                                    ?.let { slow = "slow: $it" }
                                null
                            }
                        } catch (e: TimeoutCancellationException) {
                            "no result within its deadline"
                        } catch (e: RtcException) {
                            e.message ?: e.reason
                        }
                outcomes[step] =
                    StepOutcome(step, outcome == null, start.elapsedNow().inWholeMilliseconds, outcome ?: slow)
                issued.getValue(step).complete(false)
                finished.getValue(step).complete(outcome == null)
            }
        }
        return steps.map { outcomes.getValue(it) }
    }

    /**
     * Brings [node]'s context to [action]'s state, unless it is there (then null). The calls run in the tree's scope:
     * one blocked in a socket read does not give way to cancellation, and the step's deadline must end the wait for it,
     * not the ORB's; abandoned, it ends there within the tree's call deadline.
     */
    private suspend fun act(
        node: ComponentNode,
        selector: ContextSelector,
        action: OrderedAction,
        deadline: Duration,
    ): TransitionOutcome? {
        val call =
            tree.core.scope.async(CoroutineName("${action.name.lowercase()} ${node.path}")) {
                when {
                    node.state(selector) == action.reaches -> null
                    action == OrderedAction.START -> node.activate(selector, deadline)
                    else -> node.deactivate(selector, deadline)
                }
            }
        return try {
            call.await()
        } catch (e: CancellationException) {
            call.cancel()
            throw e
        }
    }

    /** Waits for the preceding components; returns why the step cannot go on, or null. */
    private suspend fun awaitPreceding(
        condition: Condition.Preceding,
        action: OrderedAction,
        steps: List<PlannedStep>,
        byInstance: Map<String, String>,
        nodes: Map<String, ComponentNode>,
        issued: Map<PlannedStep, CompletableDeferred<Boolean>>,
        finished: Map<PlannedStep, CompletableDeferred<Boolean>>,
    ): String? {
        suspend fun wait(): String? {
            for (target in condition.components) {
                val path =
                    byInstance[target.instanceName] ?: return "preceding ${target.instanceName} is not in the profile"
                val step = steps.firstOrNull { it.component == path }
                // SYNC waits for the preceding component's transition, ASYNC only for its action to be sent.
                if (step != null) {
                    val ok =
                        if (condition.sendingTiming.equals("SYNC", ignoreCase = true)) finished.getValue(step).await()
                        else issued.getValue(step).await()
                    if (!ok) return "preceding $path was not done"
                } else {
                    val node = nodes[path] ?: tree.component(path)
                    val selector = ContextSelector.Handle(target.contextId?.toIntOrNull() ?: 0)
                    pollUntil(null, 10.milliseconds) { Unit.takeIf { node.state(selector) == action.reaches } }
                }
            }
            return null
        }
        if (condition.timeoutMillis <= 0) return wait()
        return try {
            withTimeout(condition.timeoutMillis.milliseconds) { wait() }
        } catch (e: TimeoutCancellationException) {
            "preceding ${condition.components.joinToString { it.instanceName }} not ${action.reaches} within ${condition.timeoutMillis} ms"
        }
    }

    private fun conditionTime(condition: Condition): Duration =
        when (condition) {
            is Condition.WaitTime -> condition.milliseconds.milliseconds
            is Condition.Preceding -> condition.timeoutMillis.milliseconds
            Condition.None -> Duration.ZERO
        }
}
