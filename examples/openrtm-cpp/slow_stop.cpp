// A component whose on_deactivated takes `stop_seconds` (1 s by default): longer than its execution
// context's transition timeout (exec_cxt.transition_timeout, 0.5 s by default), so the context answers
// a deactivation RTC_ERROR before the component is INACTIVE.
#include "localisation_rtc.h"

#include <chrono>
#include <thread>

namespace
{
  class SlowStop : public RTC::DataFlowComponentBase
  {
  public:
    explicit SlowStop(RTC::Manager* manager) : RTC::DataFlowComponentBase(manager) {}

    RTC::ReturnCode_t onInitialize() override
    {
      bindParameter("stop_seconds", m_stopSeconds, "1.0");
      return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onDeactivated(RTC::UniqueId) override
    {
      std::this_thread::sleep_for(std::chrono::duration<double>(m_stopSeconds));
      return RTC::RTC_OK;
    }

  private:
    double m_stopSeconds{1.0};
  };
} // namespace

extern "C" void slow_stopInit(RTC::Manager* manager)
{
  rtcoord::registerType<SlowStop>(manager, rtcoord::spec("slow_stop", "an on_deactivated slower than the transition timeout",
                                                         {{"stop_seconds", "1.0"}}));
}
