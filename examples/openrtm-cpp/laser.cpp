// A laser scanner: out-port `laser` (TimedDoubleSeq), parameter `broken`.
#include "localisation_rtc.h"

namespace
{
  class Laser : public rtcoord::Source<RTC::TimedDoubleSeq>
  {
  public:
    explicit Laser(RTC::Manager* manager) : Source(manager, "laser") {}

  protected:
    void sample(RTC::TimedDoubleSeq& scan, long tick) override
    {
      scan.data.length(8);
      for (CORBA::ULong i = 0; i < 8; ++i)
        {
          scan.data[i] = 4.0 + static_cast<double>((tick + static_cast<long>(i)) % 3);
        }
    }
  };
} // namespace

extern "C" void laserInit(RTC::Manager* manager)
{
  rtcoord::registerType<Laser>(manager, rtcoord::spec("laser", "laser scanner", {{"broken", "0"}}));
}
