package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option

/** `rtcoord conf PATH set NAME VALUE`: changes one parameter, if the component accepts the value. */
class ConfSetCommand(private val conf: ConfCommand) : TreeCommand("set") {
    override fun help(context: Context): String =
        "Set parameter NAME to VALUE in the active set (or --set), then activate the set that was active (--set's " +
            "when none was) so that the component applies it, and read it back. A value outside the constraint the component " +
            "declares is written with a warning, as rtconf and OpenRTM-aist write it; --strict refuses it."

    private val name by argument("NAME", help = "The parameter.")

    private val value by argument("VALUE", help = "Its new value.")

    private val set by option("--set", metavar = "SET", help = "Change it in this set instead.")

    private val strict by
        option("--strict", help = "Refuse a value outside the constraint the component declares in __constraints__.")
            .flag()

    override suspend fun execute() {
        val node = component(conf.path)
        node.setParameter(name, value, set, strict).forEach {
            echo("rtcoord: warning: ${node.path}: $it (written: OpenRTM-aist does not check constraints)", err = true)
        }
    }
}
