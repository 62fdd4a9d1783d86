package org.rtcoord.internal.events

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * The heartbeats a tree takes: each is a CORBA call that its ORB hands from the connection's reader to the observers'
 * POA and on to that POA's thread, about 20 us of a core here, so 10,000 components beating every second cost a fifth
 * of a core whatever the tree does with them. Up to [BEATS_PER_SECOND] watched components, each observer beats as its
 * registrations ask; past that, no more often than the [floor]: the power of two seconds that keeps them together under
 * that many beats a second (2 s up to 5000 components, 4 s up to 10,000). [changed] is told when the floor changes, so
 * that observers attached before are attached anew at it.
 */
internal class HeartbeatBudget(private val changed: () -> Unit) {
    /** The shortest heartbeat asked of an observer now; zero while the tree watches few components. */
    @Volatile
    var floor: Duration = Duration.ZERO
        private set

    /** The tree watches [count] components now. */
    fun watching(count: Int) {
        val floor = floorFor(count)
        val before = synchronized(this) { this.floor.also { this.floor = floor } }
        if (floor != before) changed()
    }

    companion object {
        /** The heartbeats a second the tree takes at most, past which observers beat less often. */
        const val BEATS_PER_SECOND = 2500

        /** The floor for [count] watched components. */
        fun floorFor(count: Int): Duration {
            if (count <= BEATS_PER_SECOND) return Duration.ZERO
            var seconds = 2L
            while (count > BEATS_PER_SECOND * seconds) seconds *= 2
            return seconds.seconds
        }
    }
}
