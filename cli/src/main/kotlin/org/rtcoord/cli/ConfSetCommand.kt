package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.option

/** `rtcoord conf PATH set NAME VALUE`: changes one parameter, if the component accepts the value. */
class ConfSetCommand(private val conf: ConfCommand) : TreeCommand("set") {
    override fun help(context: Context): String =
        "Set parameter NAME to VALUE in the active set (or --set), then activate the set that was active (--set's " +
            "when none was) so that the component applies it, and read it back."

    private val name by argument("NAME", help = "The parameter.")

    private val value by argument("VALUE", help = "Its new value.")

    private val set by option("--set", metavar = "SET", help = "Change it in this set instead.")

    override suspend fun execute() {
        component(conf.path).setParameter(name, value, set)
    }
}
