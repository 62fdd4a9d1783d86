package org.rtcoord.bench

import RTC.RTObject
import RTC.RTObjectHelper
import java.util.concurrent.atomic.AtomicInteger
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.launch
import kotlinx.coroutines.runInterruptible
import org.omg.CosNaming.NamingContextExtHelper
import org.rtcoord.ComponentNode
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.runtime.RuntimeOrb

/**
 * The physical limit of discovery on this machine: the loopback round trip of one profile read ([roundTrip], in
 * microseconds, from plain JacORB stubs with nothing of rtcoord in the way) and how many such reads overlap when
 * [threads] callers issue them at once ([concurrency] = throughput x round trip). Discovering N components cannot take
 * less than N profile reads at that rate.
 */
internal class DiscoveryFloor(
    val roundTrip: Samples,
    val threads: Int,
    val callsPerSecond: Double,
    val byCallers: Map<Int, Double>,
) {
    val concurrency: Double
        get() = callsPerSecond * roundTrip.median / 1e6

    /**
     * The floor for [n] components, in seconds: N x round trip / concurrency. Concurrency below one counts as one:
     * reading one component at a time would then be the faster way.
     */
    fun estimate(n: Int): Double = n * (roundTrip.median / 1e6) / concurrency.coerceAtLeast(1.0)

    companion object {
        /** Measures on the system whose naming service is at [address] with [calls] (one at a time, all at once). */
        suspend fun measure(address: String, calls: Pair<Int, Int>): DiscoveryFloor {
            val (sequential, parallel) = calls
            val components = componentNames(address)
            val threads = TreeConfig().concurrency
            RuntimeOrb.start().use { client ->
                val naming =
                    NamingContextExtHelper.narrow(client.orb.string_to_object("corbaloc:iiop:$address/NameService"))
                val refs = components.take(threads * 2).map { RTObjectHelper.narrow(naming.resolve_str(it)) }
                repeat(sequential / 5) { refs[it % refs.size].get_component_profile() }
                val roundTrips =
                    List(sequential) {
                        val start = System.nanoTime()
                        refs[0].get_component_profile()
                        (System.nanoTime() - start) / 1e3
                    }
                concurrently(refs, threads, parallel / 10)
                val elapsed = concurrently(refs, threads, parallel)
                // Throughput by callers in flight: where adding callers stops paying (a per-endpoint limit).
                val byCallers = CALLERS.associateWith { callers ->
                    parallel / 2 / (concurrently(refs, callers, parallel / 2) / 1e9)
                }
                return DiscoveryFloor(Samples(roundTrips, "us"), threads, parallel / (elapsed / 1e9), byCallers)
            }
        }

        private val CALLERS = listOf(1, 2, 4, 8, 16)

        /** [calls] profile reads spread over [refs] by [threads] callers; nanoseconds. */
        private suspend fun concurrently(refs: List<RTObject>, threads: Int, calls: Int): Long {
            val next = AtomicInteger()
            val start = System.nanoTime()
            coroutineScope {
                val callers = Dispatchers.IO.limitedParallelism(threads)
                repeat(threads) {
                    launch(callers) {
                        runInterruptible {
                            while (true) {
                                val index = next.getAndIncrement()
                                if (index >= calls) break
                                refs[index % refs.size].get_component_profile()
                            }
                        }
                    }
                }
            }
            return System.nanoTime() - start
        }

        /** The naming paths (`a/b/name.rtc`) of the system's components, as a tree finds them. */
        private suspend fun componentNames(address: String): List<String> =
            RtcTree(TreeConfig(listOf(address))).use { tree ->
                tree.refresh()
                tree.find { it is ComponentNode }.toList().map { it.path.names.joinToString("/") }
            }
    }
}
