package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.option
import org.rtcoord.NotFoundException
import org.rtcoord.cli.json.ParameterJson

/** `rtcoord conf PATH get NAME`: one parameter's value. */
class ConfGetCommand(private val conf: ConfCommand) : TreeCommand("get") {
    override fun help(context: Context): String = "Print the value of parameter NAME in the active set (or --set)."

    private val name by argument("NAME", help = "The parameter.")

    private val set by option("--set", metavar = "SET", help = "Read it from this set instead.")

    override suspend fun execute() {
        val component = component(conf.path)
        val configuration = component.configuration()
        val id = set ?: configuration.activeSet ?: throw noActiveSet(component, "get $name", configuration)
        val parameters = configuration.sets[id] ?: throw noSuchSet(component, id, configuration.sets.keys)
        val value =
            parameters[name]
                ?: throw NotFoundException(
                    component.path.toString(),
                    "no parameter '$name' in configuration set '$id' (parameters: ${parameters.keys.sorted().joinToString()})",
                )
        if (session.json) echoJson(ParameterJson(id, name, value)) else echo(value)
    }
}
