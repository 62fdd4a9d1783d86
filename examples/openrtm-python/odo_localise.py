"""The fallback localiser from odometry and the gyro: in-ports `odo`, `gyro`, out-port `pose`; parameter `gain`."""

import localisation_rtc as rtc

odo_localise_spec = rtc.spec("odo_localise", "odometry and gyro localiser", {"gain": "1.0"})


def odo_localiseInit(manager):
    rtc.register(manager, odo_localise_spec, lambda m: rtc.Localiser(m, [("odo", rtc.time_double_seq()), ("gyro", rtc.time_double())]))
