"""A laser scanner: out-port `laser` (TimedDoubleSeq), parameter `broken`."""

import localisation_rtc as rtc

laser_spec = rtc.spec("laser", "laser scanner", {"broken": "0"})


def laserInit(manager):
    rtc.register(manager, laser_spec, lambda m: rtc.Source(m, "laser", rtc.time_double_seq(), lambda tick: [4.0 + (tick + i) % 3 for i in range(8)]))
