// A component whose configuration holds what OpenRTM-aist's own ConfigSample ships: a set (`mode0`)
// with a value outside the constraint the component declares (`conf.__constraints__`), which a saved
// profile must restore unchanged. Parameters `int_param0` (constrained to 0<=x<=150) and `str_param0`.
#include "localisation_rtc.h"

namespace
{
  class ConfigSample : public RTC::DataFlowComponentBase
  {
  public:
    explicit ConfigSample(RTC::Manager* manager) : RTC::DataFlowComponentBase(manager) {}

    RTC::ReturnCode_t onInitialize() override
    {
      bindParameter("int_param0", m_intParam0, "0");
      bindParameter("str_param0", m_strParam0, "default");
      return RTC::RTC_OK;
    }

  private:
    int m_intParam0{0};
    std::string m_strParam0;
  };
} // namespace

extern "C" void config_sampleInit(RTC::Manager* manager)
{
  coil::Properties profile = rtcoord::spec("config_sample", "configuration sets outside their constraints",
                                           {{"int_param0", "0"}, {"str_param0", "default"}});
  profile["conf.mode0.int_param0"] = "12345";
  profile["conf.mode0.str_param0"] = "mode0";
  profile["conf.__constraints__.int_param0"] = "0<=x<=150";
  rtcoord::registerType<ConfigSample>(manager, profile);
}
