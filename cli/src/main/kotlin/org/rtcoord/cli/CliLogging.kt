package org.rtcoord.cli

import ch.qos.logback.classic.Level
import ch.qos.logback.classic.Logger
import ch.qos.logback.classic.LoggerContext
import ch.qos.logback.classic.spi.Configurator
import ch.qos.logback.classic.spi.ConfiguratorRank
import ch.qos.logback.classic.spi.ILoggingEvent
import ch.qos.logback.core.AppenderBase
import ch.qos.logback.core.spi.ContextAwareBase
import org.slf4j.LoggerFactory

/**
 * The command's logging, set up in code when logback starts (found through `META-INF/services`): warnings
 * only, one line each on stderr, nothing from JacORB. Code rather than a logback.xml because parsing one
 * costs about a tenth of a second on every start, and the cli jar is the only one that carries it.
 */
@ConfiguratorRank(ConfiguratorRank.CUSTOM_HIGH_PRIORITY)
class CliLogging : ContextAwareBase(), Configurator {
    override fun configure(context: LoggerContext): Configurator.ExecutionStatus {
        val appender = StderrAppender().apply {
            this.context = context
            start()
        }
        context.getLogger(Logger.ROOT_LOGGER_NAME).apply {
            level = Level.WARN
            addAppender(appender)
        }
        context.getLogger(JACORB).level = Level.OFF
        return Configurator.ExecutionStatus.DO_NOT_INVOKE_NEXT_IF_ANY
    }

    companion object {
        private const val JACORB = "org.jacorb"

        /** What `-v` asks for: INFO from everything, JacORB included. */
        fun verbose() {
            val context = LoggerFactory.getILoggerFactory() as? LoggerContext ?: return
            context.getLogger(Logger.ROOT_LOGGER_NAME).level = Level.INFO
            context.getLogger(JACORB).level = Level.INFO
        }
    }
}

/** Prints each event as `rtcoord: LEVEL logger: message`, with its exception's class and message. */
private class StderrAppender : AppenderBase<ILoggingEvent>() {
    override fun append(event: ILoggingEvent) {
        val failure = event.throwableProxy?.let { ": ${it.className}: ${it.message}" }.orEmpty()
        System.err.println("rtcoord: ${event.level} ${event.loggerName}: ${event.formattedMessage}$failure")
    }
}
