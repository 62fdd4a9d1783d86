"""The laser-based localiser: in-ports `laser`, `odo`, out-port `pose`; parameter `gain`."""

import localisation_rtc as rtc

laser_localise_spec = rtc.spec("laser_localise", "laser-based localiser", {"gain": "1.0"})


def laser_localiseInit(manager):
    rtc.register(manager, laser_localise_spec, lambda m: rtc.Localiser(m, [("laser", rtc.time_double_seq()), ("odo", rtc.time_double_seq())]))
