package org.rtcoord.cli

import org.rtcoord.LifeCycle

/** `rtcoord deact`: rtdeact that checks every path first and reports the component's answer. */
class DeactCommand :
    LifecycleCommand(
        "deact",
        "deactivate",
        "deactivated",
        LifeCycle.ACTIVE,
        LifeCycle.INACTIVE,
        does = "Deactivate components and wait until they are Inactive.",
        fromWords = "Active",
        usage =
            listOf(
                "rtcoord deact /localhost/host.host_cxt/laser0.rtc /localhost/host.host_cxt/gyro0.rtc" to
                    "stop both sensors"
            ),
        transition = { deactivate(it) },
    )
