// The laser-based localiser: in-ports `laser`, `odo`, out-port `pose`; parameter `gain`.
#include "localisation_rtc.h"

namespace
{
  constexpr char laser[] = "laser";
}

extern "C" void laser_localiseInit(RTC::Manager* manager)
{
  rtcoord::registerType<rtcoord::Localiser<RTC::TimedDoubleSeq, laser, true>>(manager, rtcoord::spec("laser_localise", "laser-based localiser", {{"gain", "1.0"}}));
}
