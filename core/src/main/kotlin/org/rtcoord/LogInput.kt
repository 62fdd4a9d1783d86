@file:JvmName("LogInputs")

package org.rtcoord

/**
 * One of the tree's log inputs ([RtcTree.listenForLogs]): a Fluentd forward input that OpenRTM-aist's components send
 * their log records to, each becoming a [LogRecord] event. Closed with its tree, or by [close].
 */
public interface LogInput : AutoCloseable {
    /** The host it listens on: what a component's `rtc.conf` names as `logger.logstream.fluentd.output0.host`. */
    public val host: String

    /** The port it listens on, the one chosen when 0 was asked for: `rtc.conf`'s `output0.port`. */
    public val port: Int

    /** Where it listens, `host:port`. */
    public val address: String
        get() = "$host:$port"

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

/**
 * Where OpenRTM-aist's loggers send by default (FluentLogger.py's and Fluent Bit's forward defaults): what a [LogInput]
 * listens on unless told. Java: `LogInputs.DEFAULT_LOG_ADDRESS`.
 */
public const val DEFAULT_LOG_ADDRESS: String = "127.0.0.1:24224"
