package org.rtcoord.internal.events

import org.slf4j.LoggerFactory
import java.util.UUID

/**
 * Tells when every hint that reached the ORB before now has been taken: a marker sent through its
 * observer ([ObserverHost.Observer.sendMarker]) comes back after them, as one thread takes the observers'
 * calls in the order they reached the ORB. JacORB hands each hint through two threads, while a read's reply
 * wakes its reader at once, so a read made after one hint often overtakes the next: an abort's INACTIVE and
 * ERROR, say. A hint still on its way in (its connection's reader thread not yet run) is not covered: the
 * marker travels a connection of its own. One marker is pending at a time; sending another forgets the
 * previous one.
 */
internal class HintMarker(private val subject: String) {
    private val log = LoggerFactory.getLogger(HintMarker::class.java)

    /** The marker on its way; read on the ORB's thread. */
    @Volatile private var pending: String? = null

    /** Whether a marker is on its way. */
    val isPending: Boolean get() = pending != null

    /** Sends a new marker through [observer]; one that cannot be sent never comes back. */
    fun send(observer: ObserverHost.Observer?) {
        val marker = PREFIX + UUID.randomUUID()
        pending = marker
        try {
            observer?.sendMarker(marker)
        } catch (e: Exception) {
            log.debug("{}: marker not sent: {}", subject, e.toString())
        }
    }

    /** Whether [hint] is a marker, the pending one or an older one; then it is nothing else either. */
    fun isMarker(hint: Hint): Boolean = hint.kind == HintKind.OTHER && hint.text.startsWith(PREFIX)

    /** Takes [hint], a marker: whether it is the pending one, which then no longer is. */
    fun cameBack(hint: Hint): Boolean {
        if (hint.text != pending) return false
        pending = null
        return true
    }

    /** Forgets the pending marker: whatever waited for it is over. */
    fun forget() {
        pending = null
    }

    private companion object {
        const val PREFIX = "rtcoord-marker-"
    }
}
