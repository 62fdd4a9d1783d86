// A gyro: out-port `gyro` (TimedDouble), parameter `broken`.
#include "localisation_rtc.h"

namespace
{
  class Gyro : public rtcoord::Source<RTC::TimedDouble>
  {
  public:
    explicit Gyro(RTC::Manager* manager) : Source(manager, "gyro") {}

  protected:
    void sample(RTC::TimedDouble& rate, long tick) override
    {
      rate.data = 0.01 * static_cast<double>(tick % 100);
    }
  };
} // namespace

extern "C" void gyroInit(RTC::Manager* manager)
{
  rtcoord::registerType<Gyro>(manager, rtcoord::spec("gyro", "gyro", {{"broken", "0"}}));
}
