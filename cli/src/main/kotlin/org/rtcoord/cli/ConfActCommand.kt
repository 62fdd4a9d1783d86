package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument

/** `rtcoord conf PATH act SET`: switches the active configuration set. */
class ConfActCommand(private val conf: ConfCommand) : TreeCommand("act") {
    override fun help(context: Context): String = "Make configuration set SET the active one."

    private val set by argument("SET", help = "The set to activate.")

    override suspend fun execute() {
        val component = component(conf.path)
        val sets = component.configuration().sets.keys
        if (set !in sets) throw noSuchSet(component, set, sets)
        component.activateConfigurationSet(set)
    }
}
