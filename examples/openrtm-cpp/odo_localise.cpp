// The fallback localiser from odometry and the gyro: in-ports `odo`, `gyro`, out-port `pose`; parameter `gain`.
#include "localisation_rtc.h"

namespace
{
  constexpr char gyro[] = "gyro";
}

extern "C" void odo_localiseInit(RTC::Manager* manager)
{
  rtcoord::registerType<rtcoord::Localiser<RTC::TimedDouble, gyro, false>>(manager, rtcoord::spec("odo_localise", "odometry and gyro localiser", {{"gain", "1.0"}}));
}
