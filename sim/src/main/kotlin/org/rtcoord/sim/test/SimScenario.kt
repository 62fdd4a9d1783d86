package org.rtcoord.sim.test

import org.rtcoord.sim.SimulatedSystem

/** A scenario step's faults, applied to the simulated [system]'s components by instance name. */
internal class SimScenario(private val system: SimulatedSystem) : Scenario {
    private fun named(name: String) = system.component(name.removeSuffix(".rtc"))

    override fun breakDown(component: String) = named(component).breakDown()

    override fun fail(component: String) = named(component).fail()

    override fun repair(component: String) {
        named(component).run {
            repair()
            resumeExecution()
            thawOutput()
        }
    }

    override fun freeze(component: String) = named(component).freezeOutput()

    override fun hang(component: String) = named(component).hangExecution()

    override fun exit(component: String) {
        named(component).exit()
    }

    override fun killManager() = system.killManager()

    override fun killManager(name: String) = system.killManager(name)

    override fun restartNaming() = system.restartNaming()
}
