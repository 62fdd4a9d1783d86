package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.ProgramResult
import com.github.ajalt.clikt.core.terminal
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import org.rtcoord.ComponentNode
import org.rtcoord.DirectoryNode
import org.rtcoord.Node
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.WrongKindException
import org.rtcoord.ZombieNode
import org.rtcoord.nameServerPath

/** `rtcoord ls`: rtls, without its hangs, its 200-entry limit or its all-or-nothing failures. */
class LsCommand : TreeCommand("ls") {
    override fun help(context: Context): String =
        "List name servers, naming contexts, managers and components, as rtls does. Directories end in '/', " +
            "dead registrations (zombies) start with '*'. With no PATH, list the working directory as rtls does: RTCOORD_CWD " +
            "(or RTCSH_CWD) when set, else the root context of each name server given by -n or the environment; '/' lists " +
            "the name servers themselves. A name server that cannot be reached, or an address where something else answers, is reported on stderr, one line each, and " +
            "the status is 1; what can be reached is listed. " +
            "A slave manager's components are listed below it, not a second time below its master as rtls does."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord -n localhost ls -l" to "the name server's root context in the long form, as rtls -l /localhost/",
            "rtcoord ls -l /localhost/host.host_cxt" to "state and ports of every component in a context",
            "rtcoord -n localhost ls -l -R" to
                "state and ports of everything the name server knows, directory by directory",
            "rtcoord -n localhost ls host.host_cxt" to "a relative path starts at the first name server given",
            "rtcoord --json ls /localhost/host.host_cxt" to "the same entries as JSON",
        )

    private val long by
        option("-l", help = "Long format: state, then all/in/out/service ports as total/connected, then the name.")
            .flag()

    private val recursive by
        option("-R", "--recursive", help = "List every directory below, each under a 'path:' header.").flag()

    private val paths by argument("PATH", help = "What to list; '/' is every name server the run knows.").multiple()

    override suspend fun execute() {
        val targets = paths.ifEmpty { workingDirectories() }
        val failures = mutableListOf<RtcException>()
        val read = targets.flatMap { text ->
            try {
                listing(text, headed = targets.size > 1)
            } catch (e: RtcException) {
                // A name server's root that cannot be listed (unreachable, or not a name server) is one error
                // line among the listings, as below.
                if (!pathOf(text).isNameServer) throw e
                failures += e
                emptyList()
            }
        }
        // As rtls fails on a name server it cannot list, rather than list it as a dead registration.
        val unlisted = read.flatMap { block ->
            block.entries.map { it.node }.filterIsInstance<ZombieNode>().filter { it.path.isNameServer }
        }
        val blocks = read.map { block -> Block(block.header, block.entries.filter { it.node !in unlisted }) }
        show(blocks)
        val errors =
            failures.map { explain(it) } + unlisted.distinctBy { it.path }.map { "${it.path}: ${it.cause.reason}" }
        if (errors.isEmpty()) return
        errors.forEach { echo(CommandFailed(it).message, err = true) }
        throw ProgramResult(1)
    }

    /**
     * What `ls` without a PATH lists: the working directory the environment set, else each name server's root context
     * (rtls lists its working directory, which rtshell users point at a name server).
     */
    private fun workingDirectories(): List<String> {
        session.workingDirectory?.let {
            return listOf(it.toString())
        }
        if (session.nameServers.isEmpty()) fail(NO_NAME_SERVER)
        return session.nameServers.map { "${nameServerPath(it)}/" }
    }

    private fun show(blocks: List<Block>) {
        if (session.json) {
            echoJson(blocks.flatMap { block -> block.entries.map { it.toJson() } })
            return
        }
        val width = terminal.size.width.takeIf { terminal.terminalInfo.outputInteractive }
        blocks.forEachIndexed { index, block ->
            if (index > 0 && !recursive) echo()
            block.header?.let { echo("$it:") }
            (if (long) longLines(block.entries) else shortLines(block.entries, width)).forEach { echo(it) }
            if (recursive) echo()
        }
    }

    /** What one PATH argument lists: the node itself, its children, or with -R every directory below it. */
    private suspend fun listing(text: String, headed: Boolean): List<Block> {
        val path = pathOf(text)
        val node = node(text)
        if (node !is DirectoryNode) {
            if (path.isDirectory) throw WrongKindException(path.toString(), "directory", node.kind.label)
            return listOf(Block(null, listOf(readNow(node))))
        }
        if (!recursive) {
            node.survey(1)
            return listOf(Block(text.takeIf { headed }, node.children().map(::entryOf)))
        }
        discover(node, progressLine(), summaries = true)
        return directoriesBelow(node).map { directory ->
            val header =
                when {
                    directory === node -> if (headed) text else "."
                    else -> (if (headed) text.trimEnd('/') else ".") + relativePath(node, directory)
                }
            Block(header, directory.listed.value.orEmpty().map(::entryOf))
        }
    }

    /** [below]'s path from [top], `/a/b`; below the root it starts with the name server. */
    private fun relativePath(top: Node, below: Node): String {
        val names = below.path.names.drop(top.path.names.size)
        val start = if (top.path.isRoot) listOf(below.path.nameServer!!) else emptyList()
        return (start + names).joinToString("") { "/$it" }
    }

    /** A single component (or zombie, or unknown object): read now, dead if it does not answer. */
    private suspend fun readNow(node: Node): Entry {
        if (node !is ComponentNode) return entryOf(node)
        return try {
            node.refresh()
            entryOf(node)
        } catch (e: RtcException) {
            if (!e.meansDead) throw e
            Entry(node, null, foundDead = true)
        }
    }

    /** [directory] and every directory below it, depth first, each before its children, as rtls -R lists them. */
    private fun directoriesBelow(directory: DirectoryNode): List<DirectoryNode> =
        listOf(directory) +
            directory.listed.value.orEmpty().filterIsInstance<DirectoryNode>().flatMap(::directoriesBelow)

    /** Whether the path is a name server's root context, `/host:port`. */
    private val RtcPath.isNameServer: Boolean
        get() = nameServer != null && names.isEmpty() && objectReference == null

    /** A listing under an optional `header:` line. */
    private class Block(val header: String?, val entries: List<Entry>)
}
