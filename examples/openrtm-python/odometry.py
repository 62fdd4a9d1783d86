"""Wheel odometry: out-port `odo` (TimedDoubleSeq: x, y, heading), parameter `broken`."""

import localisation_rtc as rtc

odometry_spec = rtc.spec("odometry", "wheel odometry", {"broken": "0"})


def odometryInit(manager):
    rtc.register(manager, odometry_spec, lambda m: rtc.Source(m, "odo", rtc.time_double_seq(), lambda tick: [0.1 * tick, 0.0, 0.0]))
