package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import org.rtcoord.ComponentNode
import org.rtcoord.ContextSelector
import org.rtcoord.LifeCycle

/** `rtcoord deact`: rtdeact that checks every path first and reports the component's answer. */
class DeactCommand : LifecycleCommand("deact", "deactivate", "deactivated", LifeCycle.ACTIVE, LifeCycle.INACTIVE) {
    override fun help(context: Context): String =
        "Deactivate components and wait until they are Inactive. Every PATH is checked first (a live component, " +
            "Active or already Inactive): if one is not, nothing changes."

    override fun helpEpilog(context: Context): String = examples(
        "rtcoord deact /localhost/host.host_cxt/laser0.rtc /localhost/host.host_cxt/gyro0.rtc" to "stop both sensors",
    )

    override suspend fun ComponentNode.transition(context: ContextSelector): Unit = deactivate(context)
}
