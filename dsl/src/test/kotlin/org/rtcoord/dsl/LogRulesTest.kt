package org.rtcoord.dsl

import java.net.InetSocketAddress
import java.util.concurrent.ConcurrentLinkedQueue
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.LifeCycle
import org.rtcoord.LogLevel.ERROR
import org.rtcoord.LogLevel.WARN
import org.rtcoord.LogRecord
import org.rtcoord.fixtures.await

/**
 * Rules on log records, sent by the fixtures' components through a real forward-protocol connection to the
 * coordinator's tree: a component's own at a level, a burst of matching ones, and any sender's.
 */
class LogRulesTest : CoordinatedSystem() {
    private fun laserLogs(level: String, message: String) =
        check(system.component("laser0").log(level, message)) { "laser0 could not send its record" }

    private fun sendLogsToTree() {
        val input = tree.listenForLogs("127.0.0.1:0")
        system.runtime.sendLogsTo(
            InetSocketAddress(input.host, input.port),
            "manager_slave",
        )
    }

    @Test
    fun `three timeouts within the window switch to odometry before the laser fails`(): Unit = runBlocking {
        sendLogsToTree()
        val warnings = ConcurrentLinkedQueue<String>()
        val errors = ConcurrentLinkedQueue<LogRecord>()
        coordinator {
            on(component("laser0.rtc")).logged(WARN) { warnings += it.message }
            on(component("laser0.rtc")).logged(WARN, matching = Regex("timeout"), atLeast = 3, within = 10.seconds) {
                component("laser_localise0.rtc").deactivate()
            }
            on(logs()).level(ERROR) { errors += it }
        }
            .use { coordinator ->
                coordinator.start()
                laserLogs("WARN", "scan timeout")
                laserLogs("INFO", "scan 1024 ok")
                laserLogs("WARN", "scan timeout")
                laserLogs("WARNING", "intensity low")
                await("the laser's warnings") { warnings.size == 3 }
                assertEquals(listOf("scan timeout", "scan timeout", "intensity low"), warnings.toList())
                assertEquals(LifeCycle.ACTIVE, witness.component(path("laser_localise0.rtc")).state())

                laserLogs("ERROR", "scan timeout")
                await("the third timeout to stop the laser's localiser") {
                    runBlocking { witness.component(path("laser_localise0.rtc")).state() } == LifeCycle.INACTIVE
                }
                await("the error, heard by the rule on every record") { errors.size == 1 }
                assertEquals(path("laser0.rtc"), errors.single().source.path.toString())
                val burst = coordinator.rules.single { "3 times" in it.description }
                assertEquals(1, burst.status.value.firings, "one firing for three timeouts: ${burst.description}")
            }
    }
}
