package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import java.nio.file.Files
import java.nio.file.Path
import java.time.LocalTime
import java.time.format.DateTimeFormatter
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.delay
import kotlinx.coroutines.withTimeoutOrNull
import org.rtcoord.ComponentNode
import org.rtcoord.EventOptions
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.LifeCycle
import org.rtcoord.RtcTree
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.internal.pollUntil
import org.rtcoord.runtime.RtSystem
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/**
 * The newcomer's first command: the paper's localisation system, in this process on an embedded naming service,
 * coordinated by `examples/localisation.coord.kts`; the laser breaks down for good (it cannot be reset) and the
 * coordinator switches to odometry and gyro anyway. Succeeds when the system ends as the coordinator intends.
 */
class DemoCommand : TreeCommand("demo") {
    override fun help(context: Context): String =
        "Run the paper's example: a localisation system whose laser breaks down, and the coordinator that recovers it."

    override fun helpEpilog(context: Context): String =
        examples("rtcoord demo" to "start the system, break the laser after 3 s, show the coordinator reacting")

    override suspend fun execute() {
        CompilerJars.require("rtcoord demo")
        echo("Starting an embedded naming service and the paper's localisation system...")
        NamingService.start().use { naming ->
            Scenarios.localisation(naming.corbaloc).use { system ->
                RtcTree(session.treeConfig(listOf(naming.address))).use { tree ->
                    demonstrate(naming, system, tree)
                }
            }
        }
    }

    @OptIn(InternalRtcoordApi::class)
    private suspend fun demonstrate(naming: NamingService, system: RtSystem, tree: RtcTree) {
        val host = "/${naming.address}/${RuntimeProcess.hostContext}"
        echo("The system, at $host:")
        showNetwork(tree, host)

        val script = script()
        echo("\nCompiling examples/localisation.coord.kts (cached after the first run)...")
        val coordination = ScriptHost().load(script, host = session.treeConfig(listOf(naming.address)))
        Coordinator(tree, coordination, EventOptions()) { echo("${now()}   coordinator: $it") }
            .use { coordinator ->
                coordinator.start()
                echo("${now()} coordinator running: ${coordination.description.joinToString("; ")}")
                echo("${now()} the laser will break down in 3 seconds")
                delay(3.seconds)
                echo("${now()} laser0 breaks down: its on_execute fails, and its on_reset fails while the fault lasts")
                val failed = TimeSource.Monotonic.markNow()
                system.component("laser0").breakDown()
                val recovered =
                    withTimeoutOrNull(30.seconds) {
                        pollUntil(null, 20.milliseconds) {
                            failed.elapsedNow().takeIf {
                                runCatching { tree.component("$host/odo_localise0.rtc").state() }.getOrNull() ==
                                    LifeCycle.ACTIVE
                            }
                        }
                    }
                echo("\nThe system after the coordinator's reaction:")
                tree.refresh()
                showNetwork(tree, host)
                val problems = expectedStateProblems(tree, host) + coordinatorProblems(coordinator)
                if (recovered == null || problems.isNotEmpty())
                    fail(
                        "the system did not end as expected: ${problems.joinToString("; ").ifEmpty { "odo_localise0 never became ACTIVE" }}"
                    )
                echo(
                    "\nRecovered ${recovered.inWholeMilliseconds} ms after the laser failed: odo_localise0 is ACTIVE on odometry and gyro."
                )
                val reset = coordinator.failedActions.first { it.action == "reset $host/laser0.rtc" }
                echo(
                    "laser0 could not be reset (${reset.reason}): it stays in ERROR until repaired; the coordinator switched without it."
                )
            }
    }

    private suspend fun showNetwork(tree: RtcTree, host: String) {
        val components =
            (tree.node(host) as org.rtcoord.ContextNode)
                .also { it.refresh(1) }
                .children()
                .filterIsInstance<ComponentNode>()
        for (component in components.sortedBy { it.name }) {
            val snapshot = component.snapshot()
            val links =
                snapshot.ports
                    .filter { it.connectors.isNotEmpty() }
                    .flatMap { port ->
                        component.port(port.name).connections().map { connection ->
                            val peer = connection.ports.firstOrNull { it.path != component.path.withPort(port.name) }
                            "${port.name} <-> ${peer?.path?.let { "${it.names.last()}:${it.port}" } ?: peer?.fullName}"
                        }
                    }
            echo("  %-22s %-9s %s".format(component.name, snapshot.state, links.joinToString(", ")))
        }
    }

    /**
     * What the coordinator did that the demo does not intend: a failed handler, a failed action other than the laser's
     * reset.
     */
    private fun coordinatorProblems(coordinator: Coordinator): List<String> = buildList {
        if (coordinator.failures > 0) add("${coordinator.failures} handler failures")
        coordinator.failedActions
            .filterNot { it.bestEffort && it.action.startsWith("reset ") && it.action.endsWith("/laser0.rtc") }
            .forEach { add("${it.action} failed: ${it.reason}") }
        if (coordinator.failedActions.none { it.action.endsWith("/laser0.rtc") })
            add("the laser's reset did not fail, though its fault persists")
    }

    private suspend fun expectedStateProblems(tree: RtcTree, host: String): List<String> = buildList {
        val laser = tree.component("$host/laser0.rtc").state()
        if (laser != LifeCycle.ERROR) add("laser0 is $laser, though broken")
        val created = runCatching { tree.component("$host/odo_localise0.rtc").snapshot() }.getOrNull()
        if (created == null) add("odo_localise0 was not created")
        else {
            if (created.state != LifeCycle.ACTIVE) add("odo_localise0 is ${created.state}")
            if (created.port("odo")?.connectors?.size != 1 || created.port("gyro")?.connectors?.size != 1)
                add("odo_localise0 is not fed by odometry and gyro")
        }
        val old = tree.component("$host/laser_localise0.rtc").snapshot()
        if (old.state != LifeCycle.INACTIVE) add("laser_localise0 is ${old.state}")
        if (old.ports.any { it.connectors.isNotEmpty() }) add("laser_localise0 is still connected")
    }

    /** The coordinator shipped in this jar, as a file the script host can compile. */
    private fun script(): Path {
        val directory = Files.createTempDirectory("rtcoord-demo")
        // Deleted at exit in the reverse order of registration: the file, then its directory.
        directory.toFile().deleteOnExit()
        val file = directory.resolve("localisation.coord.kts")
        file.toFile().deleteOnExit()
        DemoCommand::class.java.getResourceAsStream("/demo/localisation.coord.kts")!!.use { Files.copy(it, file) }
        return file
    }

    private fun now(): String = LocalTime.now().format(DateTimeFormatter.ofPattern("HH:mm:ss.SSS"))
}
