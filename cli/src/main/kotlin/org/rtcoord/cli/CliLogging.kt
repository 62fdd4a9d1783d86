package org.rtcoord.cli

import java.util.concurrent.ConcurrentHashMap
import org.jacorb.config.Configuration
import org.jacorb.config.LoggingInitializer
import org.slf4j.ILoggerFactory
import org.slf4j.IMarkerFactory
import org.slf4j.Logger
import org.slf4j.Marker
import org.slf4j.event.Level
import org.slf4j.helpers.BasicMarkerFactory
import org.slf4j.helpers.LegacyAbstractLogger
import org.slf4j.helpers.MessageFormatter
import org.slf4j.helpers.NOPMDCAdapter
import org.slf4j.spi.MDCAdapter
import org.slf4j.spi.SLF4JServiceProvider

/**
 * The command's logging, an SLF4J provider of its own: warnings only, one line each on stderr, nothing from JacORB;
 * `-v` lowers both to INFO. Not a logging framework: starting one cost a twentieth of a second on every command, for a
 * command that logs next to nothing. [Main][main] names this provider to SLF4J, which then does not search the class
 * path for one.
 */
class CliLogging : SLF4JServiceProvider {
    private val loggers = ConcurrentHashMap<String, Logger>()
    private val markers = BasicMarkerFactory()
    private val mdc = NOPMDCAdapter()

    override fun getLoggerFactory(): ILoggerFactory = ILoggerFactory { name ->
        loggers.computeIfAbsent(name, ::StderrLogger)
    }

    override fun getMarkerFactory(): IMarkerFactory = markers

    override fun getMDCAdapter(): MDCAdapter = mdc

    override fun getRequestedApiVersion(): String = "2.0.99"

    override fun initialize() = Unit

    /**
     * JacORB's own logging setup, which the command skips: JacORB logs through SLF4J, so through [CliLogging]. The
     * default setup only probes for an SLF4J 1 binding (a class lookup that misses, and so opens every jar of the class
     * path, the Kotlin compiler's among them) and starts java.util.logging, at every ORB start.
     */
    class JacorbSetup : LoggingInitializer() {
        override fun init(config: Configuration) = Unit
    }

    companion object {
        private const val JACORB = "org.jacorb"

        /** The least severe level shown from JacORB's loggers, and from every other one; null: none. */
        @Volatile private var jacorbThreshold: Level? = null
        @Volatile private var threshold: Level = Level.WARN

        /** What `-v` asks for: INFO from everything, JacORB included. */
        fun verbose() {
            threshold = Level.INFO
            jacorbThreshold = Level.INFO
        }

        /** Whether [logger] is one of JacORB's (they ask whether to log at every step of every call). */
        internal fun isJacorb(logger: String): Boolean = logger == JACORB || logger.startsWith("$JACORB.")

        internal fun enabled(jacorb: Boolean, level: Level): Boolean {
            val limit = if (jacorb) jacorbThreshold else threshold
            return limit != null && level.toInt() >= limit.toInt()
        }
    }
}

/** Prints each event as `rtcoord: LEVEL logger: message`, with its exception's class and message. */
private class StderrLogger(name: String) : LegacyAbstractLogger() {
    private val jacorb = CliLogging.isJacorb(name)

    init {
        this.name = name
    }

    override fun isTraceEnabled(): Boolean = CliLogging.enabled(jacorb, Level.TRACE)

    override fun isDebugEnabled(): Boolean = CliLogging.enabled(jacorb, Level.DEBUG)

    override fun isInfoEnabled(): Boolean = CliLogging.enabled(jacorb, Level.INFO)

    override fun isWarnEnabled(): Boolean = CliLogging.enabled(jacorb, Level.WARN)

    override fun isErrorEnabled(): Boolean = CliLogging.enabled(jacorb, Level.ERROR)

    override fun getFullyQualifiedCallerName(): String? = null

    override fun handleNormalizedLoggingCall(
        level: Level,
        marker: Marker?,
        pattern: String?,
        arguments: Array<out Any?>?,
        throwable: Throwable?,
    ) {
        val message = MessageFormatter.basicArrayFormat(pattern, arguments)
        val failure = throwable?.let { ": ${it.javaClass.name}: ${it.message}" }.orEmpty()
        System.err.println("rtcoord: $level $name: $message$failure")
    }
}
