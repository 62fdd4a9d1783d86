package org.rtcoord.sim.test

import org.rtcoord.LogLevel
import org.rtcoord.sim.SimulatedSystem

/**
 * An `at` step's faults, applied to the simulated [system]'s components by instance name, each told to [applied] as it
 * is done.
 */
internal class SimFaults(private val system: SimulatedSystem, private val applied: (String) -> Unit) : Faults {
    private fun named(name: String) = system.component(name.removeSuffix(".rtc"))

    private inline fun fault(what: String, action: () -> Unit) {
        action()
        applied(what)
    }

    override fun breakDown(component: String) = fault("breakDown $component") { named(component).breakDown() }

    override fun fail(component: String) = fault("fail $component") { named(component).fail() }

    override fun repair(component: String) =
        fault("repair $component") {
            named(component).run {
                repair()
                resumeExecution()
                thawOutput()
            }
        }

    override fun freeze(component: String) = fault("freeze $component") { named(component).freezeOutput() }

    override fun hang(component: String) = fault("hang $component") { named(component).hangExecution() }

    override fun exit(component: String) = fault("exit $component") { named(component).exit() }

    override fun loseConnectors(component: String) =
        fault("loseConnectors $component") { named(component).loseConnectors() }

    override fun killManager() = fault("killManager") { system.killManager() }

    override fun killManager(name: String) = fault("killManager $name") { system.killManager(name) }

    override fun restartNaming() = fault("restartNaming") { system.restartNaming() }

    override fun log(component: String, level: LogLevel, message: String) =
        fault("log $component $level \"$message\"") {
            check(named(component).log(level.name, message)) { "$component could not send its log record" }
        }
}
