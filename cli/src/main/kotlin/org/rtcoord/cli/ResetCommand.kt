package org.rtcoord.cli

import org.rtcoord.LifeCycle

/** `rtcoord reset`: rtreset that checks every path first and reports the component's answer. */
class ResetCommand :
    LifecycleCommand(
        "reset",
        "reset",
        "reset",
        LifeCycle.ERROR,
        LifeCycle.INACTIVE,
        does = "Reset components from Error and wait until they are Inactive.",
        fromWords = "in Error",
        usage = listOf("rtcoord reset /localhost/host.host_cxt/laser0.rtc" to "clear the laser's error"),
        transition = { reset(it) },
    )
