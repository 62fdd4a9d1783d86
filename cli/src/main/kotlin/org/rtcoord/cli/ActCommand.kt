package org.rtcoord.cli

import org.rtcoord.LifeCycle

/** `rtcoord act`: rtact that checks every path first and reports the component's answer. */
class ActCommand :
    LifecycleCommand(
        "act",
        "activate",
        "activated",
        LifeCycle.INACTIVE,
        LifeCycle.ACTIVE,
        does = "Activate components and wait until they are Active.",
        fromWords = "Inactive",
        usage =
            listOf(
                "rtcoord act /localhost/host.host_cxt/laser0.rtc" to "activate in the first owned execution context",
                "rtcoord act --context 1000 /localhost/host.host_cxt/laser0.rtc" to "in the context it participates in",
            ),
        transition = { activate(it) },
    )
