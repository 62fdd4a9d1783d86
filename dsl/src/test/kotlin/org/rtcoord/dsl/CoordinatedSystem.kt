package org.rtcoord.dsl

import java.nio.file.Path
import java.nio.file.Paths
import java.util.concurrent.CopyOnWriteArrayList
import org.junit.jupiter.api.AfterEach
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.WatchMode
import org.rtcoord.runtime.RtSystem
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/**
 * What a coordinator test runs against, made for each test and closed after it: a naming service, a fixture system
 * registered in it (the localisation system unless the test declares its own), a tree for the coordinator, a [witness]
 * tree to read results back with, and the coordinator's [log].
 *
 * @param declareSystem the system to start, given the naming service's `corbaloc`.
 * @param options how the coordinators of the test watch, unless a call says otherwise.
 */
abstract class CoordinatedSystem(
    declareSystem: (naming: String) -> RtSystem = { Scenarios.localisation(it) },
    private val options: EventOptions = EventOptions(WatchMode.PUSH),
) {
    protected val naming: NamingService = NamingService.start()
    protected val system: RtSystem = declareSystem(naming.corbaloc)
    protected val config: TreeConfig = TreeConfig(nameServers = listOf(naming.address))
    protected val tree: RtcTree = RtcTree(config)
    private val witnessTree = lazy { RtcTree(config) }

    /** A second tree, so that what the coordinator did is read back without its tree's cache. */
    protected val witness: RtcTree by witnessTree

    // Copy-on-write: tests iterate it while the coordinator appends.
    protected val log: MutableList<String> = CopyOnWriteArrayList()

    /** The naming context the fixtures register their components in. */
    protected val host: String
        get() = "/${naming.address}/${RuntimeProcess.hostContext}"

    /** What a coordinator resolves the script's relative file names against. */
    protected open val scriptDirectory: Path
        get() = Paths.get("")

    /** The full path of [name] (a component, or a port as `component.rtc:port`) in [host]. */
    protected fun path(name: String): String = "$host/$name"

    /** Takes each line the coordinator logs. */
    protected open fun onLogLine(line: String) {
        log += line
    }

    /** A coordinator of what [declare] declares, on [tree]; the test closes it. */
    protected fun coordinator(options: EventOptions = this.options, declare: Coordination.() -> Unit): Coordinator =
        Coordinator(tree, Coordination(emptyList(), config, scriptDirectory).apply(declare), options) { onLogLine(it) }

    @AfterEach
    fun closeSystem() {
        tree.close()
        if (witnessTree.isInitialized()) witness.close()
        system.close()
        naming.close()
    }
}
