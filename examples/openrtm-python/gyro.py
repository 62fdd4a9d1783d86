"""A gyro: out-port `gyro` (TimedDouble), parameter `broken`."""

import localisation_rtc as rtc

gyro_spec = rtc.spec("gyro", "gyro", {"broken": "0"})


def gyroInit(manager):
    rtc.register(manager, gyro_spec, lambda m: rtc.Source(m, "gyro", rtc.time_double(), lambda tick: 0.01 * (tick % 100)))
