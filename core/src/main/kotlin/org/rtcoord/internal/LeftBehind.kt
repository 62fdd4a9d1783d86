package org.rtcoord.internal

import org.rtcoord.RtcException
import org.slf4j.LoggerFactory

private val log = LoggerFactory.getLogger("org.rtcoord.internal.LeftBehind")

/**
 * Removes, of the [entries] (observers, tap connectors) a component lists under this library's names, those that trees
 * which are gone left behind (a coordinator that crashed or was restarted): the ones whose [endpoint] no longer
 * answers, or that have none. One whose endpoint answers belongs to a live tree, this one or another, and stays; so
 * does one whose fate a probe cannot tell (it timed out). [what] names an entry in the log; [removal] is the remote
 * operation [remove] makes.
 */
internal suspend fun <T> TreeCore.removeLeftBehind(
    subject: String,
    what: String,
    entries: List<T>,
    id: (T) -> String,
    endpoint: (T) -> org.omg.CORBA.Object?,
    removal: String,
    remove: (String) -> Unit,
) {
    for (entry in entries) {
        val name = id(entry)
        val gone =
            try {
                remote.call(subject, "probe $what $name") { endpoint(entry)?.let(::isGone) ?: true }
            } catch (e: RtcException) {
                false
            }
        if (!gone) continue
        try {
            remote.call(subject, removal) { remove(name) }
            log.info("{}: removed stale {} {} left by an earlier run", subject, what, name)
        } catch (e: RtcException) {
            log.debug("{}: could not remove stale {} {}: {}", subject, what, name, e.message)
        }
    }
}
