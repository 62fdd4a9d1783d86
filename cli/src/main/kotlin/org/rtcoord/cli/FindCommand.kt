package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.choice
import kotlinx.coroutines.flow.toList
import org.rtcoord.LifeCycle
import org.rtcoord.Node
import org.rtcoord.NodeFilters
import org.rtcoord.NodeFilters.and
import org.rtcoord.NodeKind

/** `rtcoord find`: rtfind, over a tree read concurrently. */
class FindCommand : TreeCommand("find") {
    override fun help(context: Context): String =
        "Print the paths of the objects below PATH (PATH included) that match every filter given. " +
            "A slave manager's components are found below it, not a second time below its master as rtfind does."

    override fun helpEpilog(context: Context): String = examples(
        "rtcoord find /localhost --type component --state error" to "components in ERROR",
        "rtcoord find /localhost --name laser0" to "everything with laser0 in its path, as rtfind -n laser0",
        "rtcoord find /localhost --type directory" to "name servers, naming contexts and managers, as rtfind -t d",
        "rtcoord find / --type zombie" to "dead registrations on every name server the run knows",
        "rtcoord find /localhost --port pose" to "components with a port named pose",
    )

    private val path by argument("PATH", help = "Where to start.")

    private val type by option(
        "--type",
        help = "Only objects of this kind. 'directory' is rtfind's d: name servers, naming contexts, managers and '/'; " +
            "'context' is naming contexts alone, which rtfind cannot ask for.",
    ).choice(
        "component" to setOf(NodeKind.COMPONENT),
        "manager" to setOf(NodeKind.MANAGER),
        "nameserver" to setOf(NodeKind.NAME_SERVER),
        "context" to setOf(NodeKind.CONTEXT),
        "directory" to setOf(NodeKind.ROOT, NodeKind.NAME_SERVER, NodeKind.CONTEXT, NodeKind.MANAGER),
        "zombie" to setOf(NodeKind.ZOMBIE),
    )

    private val name by option(
        "--name",
        metavar = "GLOB",
        help = "Only objects whose full path contains a match for GLOB ('*' any run of characters, '?' one), as rtfind's -n: " +
            "'laser0' finds laser0.rtc, and a directory's name finds everything below it.",
    )

    private val state by option("--state", help = "Only components in this state in their first execution context.")
        .choice("active" to LifeCycle.ACTIVE, "inactive" to LifeCycle.INACTIVE, "error" to LifeCycle.ERROR)

    private val port by option("--port", metavar = "NAME", help = "Only components with a port named NAME.")

    override suspend fun execute() {
        val start = node(path)
        discover(start, progressLine())
        val filters = listOfNotNull(type?.let(::ofKinds), name?.let(::pathContains), state?.let(NodeFilters::state), port?.let { NodeFilters.hasPort(it) })
        val found = tree.find(start.path, filters.reduceOrNull { all, next -> all and next } ?: { _: Node -> true }).toList()
        if (session.json) {
            echoJson(found.map { mapOf("path" to it.path.toString(), "kind" to it.kind.name.lowercase()) })
        } else {
            found.forEach { echo(it.path.toString()) }
        }
    }

    private fun ofKinds(kinds: Set<NodeKind>): suspend (Node) -> Boolean = { it.kind in kinds }

    /** rtfind's name test: the glob, unanchored, searched for in the whole path. */
    private fun pathContains(glob: String): suspend (Node) -> Boolean {
        val regex = Regex(glob.split('*').joinToString(".*?") { part -> part.split('?').joinToString(".") { Regex.escape(it) } })
        return { regex.containsMatchIn(it.path.toString()) }
    }
}
