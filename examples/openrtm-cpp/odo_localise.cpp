// The fallback localiser from odometry and the gyro: in-ports `odo`, `gyro`, out-port `pose`; parameter `gain`.
#include "localisation_rtc.h"

namespace
{
  class OdoLocalise : public rtcoord::Localiser<RTC::TimedDouble>
  {
  public:
    explicit OdoLocalise(RTC::Manager* manager) : Localiser(manager, "gyro", false) {}
  };
} // namespace

extern "C" void odo_localiseInit(RTC::Manager* manager)
{
  rtcoord::registerType<OdoLocalise>(manager, rtcoord::spec("odo_localise", "odometry and gyro localiser", {{"gain", "1.0"}}));
}
