package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument

/** `rtcoord mgr PATH delete NAME`: removes a component the manager (or a slave of it) hosts. */
class MgrDeleteCommand(private val mgr: MgrCommand) : TreeCommand("delete") {
    override fun help(context: Context): String =
        "Delete component NAME (its instance name) through the manager that hosts it; returns once it has left naming."

    private val name by argument("NAME", help = "The component's instance name, e.g. odo_localise0.")

    override suspend fun execute() {
        manager(mgr.path).delete(name)
    }
}
