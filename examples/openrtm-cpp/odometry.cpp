// Wheel odometry: out-port `odo` (TimedDoubleSeq: x, y, heading), parameter `broken`.
#include "localisation_rtc.h"

namespace
{
  class Odometry : public rtcoord::Source<RTC::TimedDoubleSeq>
  {
  public:
    explicit Odometry(RTC::Manager* manager) : Source(manager, "odo") {}

  protected:
    void sample(RTC::TimedDoubleSeq& pose, long tick) override
    {
      pose.data.length(3);
      pose.data[0] = 0.1 * static_cast<double>(tick);
      pose.data[1] = 0.0;
      pose.data[2] = 0.0;
    }
  };
} // namespace

extern "C" void odometryInit(RTC::Manager* manager)
{
  rtcoord::registerType<Odometry>(manager, rtcoord::spec("odometry", "wheel odometry", {{"broken", "0"}}));
}
