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
     * refusal is also logged, at most once a minute for each sending host.
     */
    public fun refusals(): Map<String, Long>

    /** Stops listening and closes every connection. Idempotent. */
    override fun close()
}
