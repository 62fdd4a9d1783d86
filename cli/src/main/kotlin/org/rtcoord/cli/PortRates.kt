@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.cli

import java.time.Instant
import java.time.ZoneId
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.delay
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.Node
import org.rtcoord.Port
import org.rtcoord.PortKind
import org.rtcoord.RtcException
import org.rtcoord.cli.json.EventDetail
import org.rtcoord.cli.json.EventJson
import org.rtcoord.cli.json.OneLineJson
import org.rtcoord.internal.componentsFound

/**
 * The data rates of the out-ports of some components, for `watch --data`: each port is tapped (see [Port.tap]) and its
 * samples counted; [report] prints one line per port every [period].
 */
internal class PortRates
private constructor(private val counted: List<Pair<Port, AtomicLong>>, private val period: Duration) {
    /** Prints each port's rate over the last period, every period, until cancelled. */
    suspend fun report(json: Boolean, print: (String) -> Unit) {
        var last = counted.map { 0L }
        var mark = TimeSource.Monotonic.markNow()
        while (true) {
            delay(period)
            val now = counted.map { it.second.get() }
            val seconds = mark.elapsedNow().inWholeMicroseconds / 1e6
            mark = TimeSource.Monotonic.markNow()
            val time = Instant.now()
            counted.forEachIndexed { index, (port, _) ->
                val rate = (now[index] - last[index]) / seconds
                print(
                    if (json)
                        OneLineJson.encodeToString(
                            EventJson.found(time.toEpochMilli(), port.path, EventDetail.DataRate(round(rate)))
                        )
                    else "${TIMESTAMP.format(time.atZone(ZoneId.systemDefault()))} ${port.path} data ${round(rate)} Hz"
                )
            }
            last = now
        }
    }

    companion object {
        private fun round(rate: Double): Double = Math.round(rate * 10) / 10.0

        /** Taps every data out-port of the components at or below [nodes]; returns once every tap is connected. */
        suspend fun tap(nodes: List<Node>, period: Duration = 1.seconds): PortRates {
            val components = componentsFound(nodes)
            val ports = components.flatMap { component ->
                val snapshot =
                    try {
                        component.snapshot()
                    } catch (e: RtcException) {
                        return@flatMap emptyList()
                    }
                snapshot.ports.filter { it.kind == PortKind.DATA_OUT }.map { component.port(it.name) }
            }
            val counted = ports.map { port -> port to AtomicLong() }
            counted.forEach { (port, count) -> port.tap { count.incrementAndGet() } }
            return PortRates(counted, period)
        }
    }
}
