// A gyro: out-port `gyro` (TimedDouble), parameter `broken`.
#include "localisation_rtc.h"

namespace
{
  constexpr char port[] = "gyro";

  void rate(RTC::TimedDouble& turn, long tick)
  {
    turn.data = 0.01 * static_cast<double>(tick % 100);
  }
} // namespace

extern "C" void gyroInit(RTC::Manager* manager)
{
  rtcoord::registerType<rtcoord::Source<RTC::TimedDouble, port, rate>>(manager, rtcoord::spec("gyro", "gyro", {{"broken", "0"}}));
}
