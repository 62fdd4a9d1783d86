// A component with a service port, `probe`, requiring the interface probe_server provides: `probe` of
// type `SDOPackage::SDOService`.
#include "localisation_rtc.h"

#include <rtm/CorbaConsumer.h>
#include <rtm/CorbaPort.h>
#include <rtm/idl/SDOPackageStub.h>

namespace
{
  class ProbeClient : public RTC::DataFlowComponentBase
  {
  public:
    explicit ProbeClient(RTC::Manager* manager) : RTC::DataFlowComponentBase(manager), m_port("probe") {}

    RTC::ReturnCode_t onInitialize() override
    {
      m_port.registerConsumer("probe", "SDOPackage::SDOService", m_probe);
      addPort(m_port);
      return RTC::RTC_OK;
    }

  private:
    RTC::CorbaPort m_port;
    RTC::CorbaConsumer<SDOPackage::SDOService> m_probe;
  };
} // namespace

extern "C" void probe_clientInit(RTC::Manager* manager)
{
  rtcoord::registerType<ProbeClient>(manager, rtcoord::spec("probe_client", "a service port requiring an interface", {}));
}
