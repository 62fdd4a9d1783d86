@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl.internal

import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import org.rtcoord.ComponentNode
import org.rtcoord.DataListener
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.LifeCycle
import org.rtcoord.Overlap
import org.rtcoord.PortData
import org.rtcoord.RtcException
import org.rtcoord.Subscription
import org.rtcoord.dsl.DataRule
import org.rtcoord.dsl.Reaction
import org.rtcoord.internal.treeTime

/**
 * One run of a [DataRule]: taps the port and hands samples to the handler (the newest waiting while it runs), or
 * watches the port's silence and rate with a [DataLiveness] checked a few times per threshold. The port's component is
 * followed through the engine's [Identities]: when it is re-created, the new one's port is tapped in its place. [fire]
 * runs a handler as the coordinator runs any (counted, logged, its failure contained).
 */
internal class DataRuleRun(
    private val rule: DataRule,
    private val engine: Engine,
    private val scope: CoroutineScope,
    private val fire: suspend (String, suspend Reaction.() -> Unit) -> Unit,
) {
    private val began = engine.tree.treeTime().markNow()
    private var following: Subscription? = null
    @Volatile private var tapped: Subscription? = null
    /** The silence and rate of a [DataRule.Silence] or [DataRule.RateBelow], counted from each tap. */
    private var liveness: DataLiveness? = null

    /** Taps the port; fails as the tap does (no such port, not an out-port). */
    suspend fun start() {
        val listener =
            when (rule) {
                is DataRule.Samples<*> -> samples(rule)
                is DataRule.Silence,
                is DataRule.RateBelow -> watchLiveness()
            }
        following =
            engine.identities.listen(
                rule.port.component.selector,
                emptySet(),
                prepare = { node -> tap(node, listener) },
            ) {}
    }

    fun stop() {
        following?.cancel()
        tapped?.cancel()
    }

    /** Taps the port of [node], which the rule's component name resolves to now, in place of the one it replaced. */
    private suspend fun tap(node: ComponentNode, listener: DataListener) {
        val first = tapped == null
        tapped?.cancel()
        tapped =
            try {
                node.port(rule.port.name).tap(listener).also {
                    liveness?.let { watched -> synchronized(watched) { watched.tapped(now()) } }
                }
            } catch (e: RtcException) {
                if (first) throw e
                engine.log("warning: ${rule.description}: could not tap the re-created component: ${e.message}")
                null
            }
    }

    private fun <T : PortData> samples(rule: DataRule.Samples<T>): DataListener {
        val queue =
            HandlerQueue<T>(scope, Overlap.LATEST) { sample -> fire(rule.description) { rule.handler(this, sample) } }
        return DataListener { data -> if (rule.type.isInstance(data)) queue.offer(rule.type.cast(data)) }
    }

    /** Starts checking the port's silence and rate; returns the listener that counts its samples. */
    private fun watchLiveness(): DataListener {
        val silence = (rule as? DataRule.Silence)?.limit
        val rate = (rule as? DataRule.RateBelow)?.rate
        val liveness = DataLiveness(silence?.inWholeMilliseconds, rate).also { this.liveness = it }
        val period = ((silence ?: 1000.milliseconds) / 5).coerceIn(10.milliseconds, 200.milliseconds)
        scope.launch {
            while (isActive) {
                delay(period)
                val active =
                    try {
                        rule.port.component.state() == LifeCycle.ACTIVE
                    } catch (e: RtcException) {
                        false
                    }
                when (val finding = synchronized(liveness) { liveness.check(now(), active) }) {
                    is DataLiveness.Finding.Silent ->
                        (rule as DataRule.Silence).let { silent -> fire(rule.description) { silent.handler(this) } }
                    is DataLiveness.Finding.Slow ->
                        (rule as DataRule.RateBelow).let { slow ->
                            fire(rule.description) { slow.handler(this, finding.rate) }
                        }
                    DataLiveness.Finding.NOTHING -> Unit
                }
            }
        }
        return DataListener { synchronized(liveness) { liveness.sample(now()) } }
    }

    /** Milliseconds of the tree's time (see [org.rtcoord.TreeConfig.speed]) since the rule began. */
    private fun now(): Long = began.elapsedNow().inWholeMilliseconds
}
