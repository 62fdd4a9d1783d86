package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.multiple
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.choice
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.restrictTo
import kotlinx.coroutines.flow.toList
import org.rtcoord.LifeCycle
import org.rtcoord.Node
import org.rtcoord.NodeFilters
import org.rtcoord.NodeFilters.and
import org.rtcoord.NodeKind
import org.rtcoord.cli.json.FoundJson

/** `rtcoord find`: rtfind, with its short options, over a tree read concurrently. */
class FindCommand : TreeCommand("find") {
    override fun help(context: Context): String =
        "Print the paths of the objects below PATH (PATH included) that match every filter given. rtfind's options work " +
            "as they do there: -t, -n, -i, -m. " +
            "Each component is found once, where it is bound in naming; below the manager that hosts it only when its " +
            "naming path is not found (rtfind finds it there, and again below the master)."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord find /localhost -t c --state error" to
                "components in ERROR (--state takes any case: ERROR, error)",
            "rtcoord find /localhost -n laser0" to "everything with laser0 in its path, as rtfind -n laser0",
            "rtcoord find /localhost -t d -m 1" to
                "name servers, naming contexts and managers one level down, as rtfind -t d -m 1",
            "rtcoord find / --type zombie" to "dead registrations on every name server the run knows",
            "rtcoord find /localhost --port pose" to "components with a port named pose",
        )

    private val path by argument("PATH", help = "Where to start.")

    private val type by
        option(
                "-t",
                "--type",
                metavar = "TYPE",
                help =
                    "Only objects of these kinds: rtfind's letters c (component), d (directory), m (manager), n (name server), " +
                        "z (zombie), several at once as in -t dmn; or a word: component, manager, nameserver, context, directory, zombie. " +
                        "'directory' (d) is name servers, naming contexts, managers and '/'; 'context' is naming contexts alone, which rtfind cannot ask for.",
            )
            .convert { text ->
                kindsOf(text)
                    ?: fail("'$text' is not a type: letters of cdmnz, or one of ${KIND_WORDS.keys.joinToString()}")
            }

    private val names by
        option(
                "-n",
                "--name",
                metavar = "GLOB",
                help =
                    "Only objects whose full path contains a match for GLOB ('*' any run of characters, '?' one), as rtfind's -n: " +
                        "'laser0' finds laser0.rtc, and a directory's name finds everything below it. Repeatable: any one may match.",
            )
            .multiple()

    private val caseless by
        option("-i", "--iname", metavar = "GLOB", help = "As --name, ignoring case (rtfind's -i). Repeatable.")
            .multiple()

    private val maxDepth by
        option(
                "-m",
                "--maxdepth",
                metavar = "N",
                help = "Only objects at most N levels below PATH (PATH is level 0), as rtfind's -m; 0 for no limit.",
            )
            .int()
            .restrictTo(min = 0)
            .default(0)

    private val state by
        option("--state", help = "Only components in this state in their first execution context (any case).")
            .choice(
                "active" to LifeCycle.ACTIVE,
                "inactive" to LifeCycle.INACTIVE,
                "error" to LifeCycle.ERROR,
                ignoreCase = true,
            )

    private val port by option("--port", metavar = "NAME", help = "Only components with a port named NAME.")

    override suspend fun execute() {
        val start = node(path)
        val depth = maxDepth.takeIf { it > 0 } ?: Int.MAX_VALUE
        discover(start, progressLine(), depth = depth)
        val patterns = names.map { glob(it, ignoreCase = false) } + caseless.map { glob(it, ignoreCase = true) }
        val filters =
            listOfNotNull(
                type?.let(::ofKinds),
                patterns.takeIf { it.isNotEmpty() }?.let(::pathContainsAny),
                state?.let(NodeFilters::state),
                port?.let { NodeFilters.hasPort(it) },
            )
        val found =
            tree
                .find(start.path, depth, filters.reduceOrNull { all, next -> all and next } ?: { _: Node -> true })
                .toList()
        if (session.json) {
            echoJson(found.map { FoundJson(it.path.toString(), it.kind.name.lowercase()) })
        } else {
            found.forEach { echo(it.path.toString()) }
        }
    }

    private fun ofKinds(kinds: Set<NodeKind>): suspend (Node) -> Boolean = { it.kind in kinds }

    /** rtfind's name test: each glob, unanchored, searched for in the whole path; any one matching will do. */
    private fun pathContainsAny(patterns: List<Regex>): suspend (Node) -> Boolean = { node ->
        patterns.any { it.containsMatchIn(node.path.toString()) }
    }

    private fun glob(text: String, ignoreCase: Boolean): Regex =
        Regex(
            text.split('*').joinToString(".*?") { part -> part.split('?').joinToString(".") { Regex.escape(it) } },
            if (ignoreCase) setOf(RegexOption.IGNORE_CASE) else emptySet(),
        )

    private companion object {
        private val DIRECTORIES = setOf(NodeKind.ROOT, NodeKind.NAME_SERVER, NodeKind.CONTEXT, NodeKind.MANAGER)

        private val KIND_WORDS =
            linkedMapOf(
                "component" to setOf(NodeKind.COMPONENT),
                "manager" to setOf(NodeKind.MANAGER),
                "nameserver" to setOf(NodeKind.NAME_SERVER),
                "context" to setOf(NodeKind.CONTEXT),
                "directory" to DIRECTORIES,
                "zombie" to setOf(NodeKind.ZOMBIE),
            )

        private val KIND_LETTERS =
            mapOf(
                'c' to setOf(NodeKind.COMPONENT),
                'd' to DIRECTORIES,
                'm' to setOf(NodeKind.MANAGER),
                'n' to setOf(NodeKind.NAME_SERVER),
                'z' to setOf(NodeKind.ZOMBIE),
            )

        /** The kinds [text] names: a word, or rtfind's letters; null if it is neither. */
        fun kindsOf(text: String): Set<NodeKind>? {
            val word = text.lowercase()
            KIND_WORDS[word]?.let {
                return it
            }
            if (word.isEmpty() || word.any { it !in KIND_LETTERS }) return null
            return word.flatMap { KIND_LETTERS.getValue(it) }.toSet()
        }
    }
}
