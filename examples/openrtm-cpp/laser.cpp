// A laser scanner: out-port `laser` (TimedDoubleSeq), parameter `broken`.
#include "localisation_rtc.h"

namespace
{
  constexpr char port[] = "laser";

  void scan(RTC::TimedDoubleSeq& ranges, long tick)
  {
    ranges.data.length(8);
    for (CORBA::ULong i = 0; i < 8; ++i)
      {
        ranges.data[i] = 4.0 + static_cast<double>((tick + static_cast<long>(i)) % 3);
      }
  }
} // namespace

extern "C" void laserInit(RTC::Manager* manager)
{
  rtcoord::registerType<rtcoord::Source<RTC::TimedDoubleSeq, port, scan>>(manager, rtcoord::spec("laser", "laser scanner", {{"broken", "0"}}));
}
