package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option

/** `rtcoord conf PATH list`: the configuration sets and their parameters. */
class ConfListCommand(private val conf: ConfCommand) : TreeCommand("list") {
    override fun help(context: Context): String =
        "List the configuration sets and their parameters, the active set marked '*' (none is after a set was " +
            "written without being activated). OpenRTM's hidden sets " +
            "(__constraints__ and the like) only with --all."

    private val set by option("--set", metavar = "SET", help = "Only this set.")

    private val all by option("--all", help = "Also the hidden __name__ sets.").flag()

    override suspend fun execute() {
        show(set, all)
    }

    /** Prints set [set] (every set when null; hidden ones too when [all]). */
    internal suspend fun show(set: String?, all: Boolean) {
        val component = component(conf.path)
        val configuration = component.configuration()
        if (set != null && set !in configuration.sets) {
            throw noSuchSet(component, set, configuration.sets.keys)
        }
        val shown = configuration.shownSets(showHidden = all, only = set)
        if (session.json) {
            echoJson(configuration.toJson(shown))
            return
        }
        configuration.lines(shown, "").forEach { echo(it) }
        if (configuration.activeSet == null && configuration.sets.isNotEmpty()) {
            echo(
                "rtcoord: ${component.path}: no configuration set is active; 'rtcoord conf ${conf.path} act SET' activates one",
                err = true,
            )
        }
    }
}
