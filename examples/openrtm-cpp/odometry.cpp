// Wheel odometry: out-port `odo` (TimedDoubleSeq: x, y, heading), parameter `broken`.
#include "localisation_rtc.h"

namespace
{
  constexpr char port[] = "odo";

  void pose(RTC::TimedDoubleSeq& xyh, long tick)
  {
    xyh.data.length(3);
    xyh.data[0] = 0.1 * static_cast<double>(tick);
    xyh.data[1] = 0.0;
    xyh.data[2] = 0.0;
  }
} // namespace

extern "C" void odometryInit(RTC::Manager* manager)
{
  rtcoord::registerType<rtcoord::Source<RTC::TimedDoubleSeq, port, pose>>(manager, rtcoord::spec("odometry", "wheel odometry", {{"broken", "0"}}));
}
