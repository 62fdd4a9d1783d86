// The laser-based localiser: in-ports `laser`, `odo`, out-port `pose`; parameter `gain`.
#include "localisation_rtc.h"

namespace
{
  class LaserLocalise : public rtcoord::Localiser<RTC::TimedDoubleSeq>
  {
  public:
    explicit LaserLocalise(RTC::Manager* manager) : Localiser(manager, "laser", true) {}
  };
} // namespace

extern "C" void laser_localiseInit(RTC::Manager* manager)
{
  rtcoord::registerType<LaserLocalise>(manager, rtcoord::spec("laser_localise", "laser-based localiser", {{"gain", "1.0"}}));
}
