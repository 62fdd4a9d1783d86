package org.rtcoord.examples

import java.nio.file.Path
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.rtcoord.EventOptions
import org.rtcoord.LogInput
import org.rtcoord.LogLevel
import org.rtcoord.LogRecord
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordination
import org.rtcoord.dsl.Coordinator

/**
 * Component logs on real OpenRTM-aist-Python: a manager of its own, as a standalone component's process is, configured
 * through its rtc.conf to send its log records with OpenRTM's FluentLogger.py plugin to a tree's log input, hosting
 * `warner0` (`examples/openrtm-python/warner.py`), which logs a warning when told to.
 */
object OpenRtmPythonLogs {
    /** The instance name of the warner's manager, which its records carry in their `manager` field. */
    private const val MANAGER = "warner_manager"

    /**
     * The warner's warning arrives as a [LogRecord] from `warner0` (its process's manager, which is in no naming
     * context and no master's listing, hosts that one component) and fires a coordinator's `logged` rule.
     */
    fun logs(installation: OpenRtmPython): Unit = runBlocking {
        OpenRtmSystem.start(installation).use { system ->
            val config = TreeConfig(nameServers = listOf(system.naming))
            RtcTree(config).use { tree ->
                val input = tree.listenForLogs("127.0.0.1:0")
                val records = LinkedBlockingQueue<LogRecord>()
                tree.on(tree.root, LogRecord::class.java, EventOptions()) { records += it }
                system.startOwnManager(
                    "warner",
                    listOf(installation.components),
                    listOf("warner0"),
                    "manager.instance_name: $MANAGER",
                    "manager.modules.preload: warner.py",
                    "manager.components.precreate: warner",
                    *logLines(installation.fluentLogger(), input).toTypedArray(),
                )
                // OpenRTM's own start-up lines, logged by the manager at INFO, show the plugin sends at all.
                val first = records.poll(30, TimeUnit.SECONDS) ?: error("no record in 30 s; ${system.output("warner")}")
                println("${installation.label}: first record $first")
                assertEquals(MANAGER, first.manager, "$first")
                assertEquals(TAG, first.tag)

                val fired = LinkedBlockingQueue<LogRecord>()
                val coordination =
                    Coordination(emptyList(), config, system.directory).apply {
                        on(component("warner0.rtc")).logged(LogLevel.WARN, matching = Regex("^scan timeout")) {
                            fired += it
                        }
                    }
                Coordinator(tree, coordination) { println("coordinator: $it") }
                    .use { coordinator ->
                        coordinator.start()
                        val warner = tree.component(system.path("warner0.rtc"))
                        warner.activate()
                        warner.setParameter("warn", "scan timeout 1")
                        val record = fired.poll(30, TimeUnit.SECONDS) ?: error("the rule did not fire: $records")
                        assertEquals(warner.path, record.source.path, "$record")
                        assertEquals(LogLevel.WARN, record.level)
                        assertEquals("scan timeout 1", record.message)
                        // Every Python component's logger is `rtobject`, prefixed by FluentLogger.
                        assertEquals("fluent.rtobject", record.logger)
                        assertEquals(MANAGER, record.manager)
                        assertTrue(record.pid != null && record.host != null, "$record")
                        assertEquals(0, coordinator.failures)
                    }
            }
        }
    }

    /** The Fluentd tag the warner's process sends its records with. */
    private const val TAG = "rtcoord.openrtm"

    /**
     * The rtc.conf lines that make a manager's logger send records at INFO and above to [address] with FluentLogger.py
     * at [plugin]: OpenRTM loads a logger plugin as a module, by its path.
     */
    private fun logLines(plugin: Path, input: LogInput): List<String> =
        listOf(
            "logger.enable: YES",
            "logger.log_level: INFO",
            "logger.plugins: $plugin",
            "logger.logstream.fluentd.output0.tag: $TAG",
            "logger.logstream.fluentd.output0.host: ${input.host}",
            "logger.logstream.fluentd.output0.port: ${input.port}",
        )
}
