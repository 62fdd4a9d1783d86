package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import org.rtcoord.ComponentNode
import org.rtcoord.ContextSelector
import org.rtcoord.LifeCycle

/** `rtcoord reset`: rtreset that checks every path first and reports the component's answer. */
class ResetCommand : LifecycleCommand("reset", "reset", "reset", LifeCycle.ERROR, LifeCycle.INACTIVE) {
    override fun help(context: Context): String =
        "Reset components from Error and wait until they are Inactive. Every PATH is checked first (a live component, " +
            "in Error or already Inactive): if one is not, nothing changes."

    override fun helpEpilog(context: Context): String = examples(
        "rtcoord reset /localhost/host.host_cxt/laser0.rtc" to "clear the laser's error",
    )

    override suspend fun ComponentNode.transition(context: ContextSelector): Unit = reset(context)
}
