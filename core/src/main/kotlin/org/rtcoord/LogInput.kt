package org.rtcoord

/**
 * One of the tree's log inputs ([RtcTree.listenForLogs]): a Fluentd forward input that OpenRTM-aist's components send
 * their log records to, each becoming a [LogRecord] event. Closed with its tree, or by [close].
 */
public interface LogInput : AutoCloseable {
    /** Where it listens, `host:port` (the port chosen when 0 was asked for): what a component's `rtc.conf` names. */
    public val address: String

    /** How many records it has received. */
    public val received: Long

    /**
     * What it refused, counted by reason (`malformed`, `too-large`, `wrong-key`, `flood`, `incomplete-frame`). Each
     * refusal is also logged, at most once a minute for each sending host. Records it took but dropped, the oldest
     * first, so that a flood costs bounded memory, are counted too, and logged at most once a minute: `dropped`, more
     * than 10,000 waiting to be published; `slow-handler`, more than 10,000 waiting for a handler of records alone (the
     * tree's handlers, counted on each of its inputs).
     */
    public fun refusals(): Map<String, Long>

    /** Stops listening and closes every connection. Idempotent. */
    override fun close()
}
