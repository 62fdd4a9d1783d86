package org.rtcoord.internal.logs

import java.net.InetSocketAddress
import java.util.concurrent.ConcurrentLinkedQueue
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import org.rtcoord.fixtures.await
import org.rtcoord.fixtures.awaitValue

/** One refusal as [ForwardInput] reported it. */
internal class Refused(val sender: InetSocketAddress, val refusal: ForwardRefusal, val reason: String) {
    override fun toString() = "$refusal from $sender: $reason"
}

/**
 * A [ForwardInput] on 127.0.0.1, any free port, in a scope the test owns (a `SupervisorJob`, as a tree's is), with what
 * it received and refused.
 */
internal class ForwardHarness(settings: (InetSocketAddress) -> ForwardSettings = { ForwardSettings(it) }) :
    AutoCloseable {
    val job = SupervisorJob()
    val scope = CoroutineScope(job + Dispatchers.Default)
    val entries = ConcurrentLinkedQueue<ForwardEntry>()
    val refused = ConcurrentLinkedQueue<Refused>()
    val input =
        ForwardInput(scope, settings(InetSocketAddress("127.0.0.1", 0)), entries::add) { sender, refusal, reason ->
            refused += Refused(sender, refusal, reason)
        }

    /** Waits for [count] entries in all and returns them in the order received. */
    fun awaitEntries(count: Int): List<ForwardEntry> {
        await("$count entries, got ${entries.size}: $entries; refused $refused") { entries.size >= count }
        return entries.toList()
    }

    /** Waits for the first refusal of [refusal]. */
    fun awaitRefusal(refusal: ForwardRefusal): Refused =
        awaitValue("a refusal as $refusal, got $refused") { refused.firstOrNull { it.refusal == refusal } }

    /** The one entry tagged [tag], waited for. */
    fun awaitTagged(tag: String): ForwardEntry =
        awaitValue("an entry tagged $tag, got $entries; refused $refused") { entries.firstOrNull { it.tag == tag } }

    override fun close() {
        input.close()
        job.cancel()
    }
}
