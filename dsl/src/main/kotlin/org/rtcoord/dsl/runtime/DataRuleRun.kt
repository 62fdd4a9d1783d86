package org.rtcoord.dsl.runtime

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import org.rtcoord.LifeCycle
import org.rtcoord.Overlap
import org.rtcoord.PortData
import org.rtcoord.RtcException
import org.rtcoord.Subscription
import org.rtcoord.dsl.DataRule
import org.rtcoord.dsl.Reaction
import kotlin.time.Duration.Companion.milliseconds

/**
 * One run of a [DataRule]: taps the port and hands samples to the handler (the newest waiting while it
 * runs), or watches the port's silence and rate with a [DataLiveness] checked a few times per threshold.
 * [fire] runs a handler as the coordinator runs any (counted, logged, its failure contained).
 */
internal class DataRuleRun(
    private val rule: DataRule,
    private val engine: Engine,
    private val scope: CoroutineScope,
    private val fire: suspend (String, suspend Reaction.() -> Unit) -> Unit,
) {
    private var subscription: Subscription? = null

    /** Taps the port; fails as the tap does (no such port, not an out-port). */
    suspend fun start() {
        val port = rule.port.port()
        when (rule) {
            is DataRule.Samples<*> -> subscription = port.tap(samples(rule))
            is DataRule.Silence, is DataRule.RateBelow -> watchLiveness { listener -> subscription = port.tap(listener) }
        }
    }

    fun stop() {
        subscription?.cancel()
    }

    private fun <T : PortData> samples(rule: DataRule.Samples<T>): org.rtcoord.DataListener {
        val queue = HandlerQueue<T>(scope, Overlap.LATEST) { sample -> fire(rule.description) { rule.handler(this, sample) } }
        return org.rtcoord.DataListener { data -> if (rule.type.isInstance(data)) queue.offer(rule.type.cast(data)) }
    }

    private suspend fun watchLiveness(tap: suspend (org.rtcoord.DataListener) -> Unit) {
        val silence = (rule as? DataRule.Silence)?.limit
        val rate = (rule as? DataRule.RateBelow)?.rate
        val liveness = DataLiveness(now(), silence?.inWholeMilliseconds, rate)
        tap(org.rtcoord.DataListener { synchronized(liveness) { liveness.sample(now()) } })
        val period = ((silence ?: 1000.milliseconds) / 5).coerceIn(10.milliseconds, 200.milliseconds)
        scope.launch {
            while (isActive) {
                delay(period)
                val active = try {
                    rule.port.component.state() == LifeCycle.ACTIVE
                } catch (e: RtcException) {
                    false
                }
                when (val finding = synchronized(liveness) { liveness.check(now(), active) }) {
                    is DataLiveness.Finding.Silent -> (rule as DataRule.Silence).let { silent -> fire(rule.description) { silent.handler(this) } }
                    is DataLiveness.Finding.Slow -> (rule as DataRule.RateBelow).let { slow -> fire(rule.description) { slow.handler(this, finding.rate) } }
                    DataLiveness.Finding.NOTHING -> Unit
                }
            }
        }
    }

    private companion object {
        fun now(): Long = System.nanoTime() / 1_000_000
    }
}
