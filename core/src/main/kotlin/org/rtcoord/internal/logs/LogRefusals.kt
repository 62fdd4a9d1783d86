package org.rtcoord.internal.logs

import java.net.InetSocketAddress
import org.slf4j.LoggerFactory

/**
 * Says what a log input refused, at most once every [intervalMillis] for each sending host, with how many refusals that
 * host had since it was last said: a sender that floods or sends garbage fills no log.
 */
internal class LogRefusals(
    private val input: String,
    private val now: () -> Long,
    private val intervalMillis: Long = 60_000,
    private val say: (String) -> Unit = { LoggerFactory.getLogger("org.rtcoord.logs").warn(it) },
) {
    private class Said(val at: Long, var since: Long = 0)

    private val said = HashMap<String, Said>()

    fun refused(sender: InetSocketAddress, refusal: ForwardRefusal, reason: String) {
        val host = sender.hostString
        val time = now()
        val unsaid =
            synchronized(said) {
                val last = said[host]
                if (last != null && time - last.at < intervalMillis) {
                    last.since++
                    return
                }
                said[host] = Said(time)
                last?.since ?: 0
            }
        val earlier = if (unsaid > 0) " ($unsaid more refused since the last report)" else ""
        say("log input $input refused ${refusal.id} input from $host: $reason$earlier")
    }
}
