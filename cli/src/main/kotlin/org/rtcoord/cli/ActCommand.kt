package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import org.rtcoord.ComponentNode
import org.rtcoord.ContextSelector
import org.rtcoord.LifeCycle

/** `rtcoord act`: rtact that checks every path first and reports the component's answer. */
class ActCommand : LifecycleCommand("act", "activate", "activated", LifeCycle.INACTIVE, LifeCycle.ACTIVE) {
    override fun help(context: Context): String =
        "Activate components and wait until they are Active. Every PATH is checked first (a live component, " +
            "Inactive or already Active): if one is not, nothing changes."

    override fun helpEpilog(context: Context): String = examples(
        "rtcoord act /localhost/host.host_cxt/laser0.rtc" to "activate in the first owned execution context",
        "rtcoord act --context 1000 /localhost/host.host_cxt/laser0.rtc" to "in the context it participates in",
    )

    override suspend fun ComponentNode.transition(context: ContextSelector): Unit = activate(context)
}
