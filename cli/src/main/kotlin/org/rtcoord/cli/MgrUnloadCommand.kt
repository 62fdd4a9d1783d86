package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument

/** `rtcoord mgr PATH unload MODULE`: unloads a module from the manager. */
class MgrUnloadCommand(private val mgr: MgrCommand) : TreeCommand("unload") {
    override fun help(context: Context): String = "Unload module MODULE."

    private val module by argument("MODULE", help = "The module's file, as the manager names it.")

    override suspend fun execute() {
        manager(mgr.path).unloadModule(module)
    }
}
