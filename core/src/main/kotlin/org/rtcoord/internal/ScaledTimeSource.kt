package org.rtcoord.internal

import kotlin.time.AbstractLongTimeSource
import kotlin.time.DurationUnit

/**
 * The host's monotonic clock run [speed] times as fast: the robot's time of a system simulated faster than real time,
 * which every timer of the tree, its coordinators and the simulation follows (so a 30 s scenario takes 3 s at 10).
 */
internal class ScaledTimeSource(private val speed: Double) : AbstractLongTimeSource(DurationUnit.NANOSECONDS) {
    private val origin = System.nanoTime()

    override fun read(): Long = ((System.nanoTime() - origin) * speed).toLong()

    override fun toString(): String = "the monotonic clock at ${speed}x"
}
