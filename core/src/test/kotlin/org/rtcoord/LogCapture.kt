package org.rtcoord

import ch.qos.logback.classic.Logger
import ch.qos.logback.classic.spi.ILoggingEvent
import ch.qos.logback.core.AppenderBase
import java.util.concurrent.ConcurrentLinkedQueue
import org.slf4j.LoggerFactory

/** What [source]'s logger writes while it is open, for tests that check a fault is reported. */
class LogCapture(source: Class<*>) : AutoCloseable {
    private val logger = LoggerFactory.getLogger(source) as Logger
    private val captured = ConcurrentLinkedQueue<String>()
    private val appender =
        object : AppenderBase<ILoggingEvent>() {
                override fun append(event: ILoggingEvent) {
                    captured += event.formattedMessage
                }
            }
            .apply {
                context = logger.loggerContext
                start()
            }

    init {
        logger.addAppender(appender)
    }

    /** The messages so far, formatted. */
    val lines: List<String>
        get() = captured.toList()

    override fun close() {
        logger.detachAppender(appender)
        appender.stop()
    }
}
