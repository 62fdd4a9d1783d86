// A component with a service port, `probe`, providing one interface, `probe` of type
// `SDOPackage::SDOService` (an interface without operations, which the library compiles already): the
// C++ side of the service ports a saved profile must carry and a simulation reproduce. probe_client
// requires it.
#include "localisation_rtc.h"

#include <rtm/CorbaPort.h>
#include <rtm/idl/SDOPackageSkel.h>

namespace
{
  class Probe : public virtual POA_SDOPackage::SDOService, public virtual PortableServer::RefCountServantBase
  {
  };

  class ProbeServer : public RTC::DataFlowComponentBase
  {
  public:
    explicit ProbeServer(RTC::Manager* manager) : RTC::DataFlowComponentBase(manager), m_port("probe") {}

    RTC::ReturnCode_t onInitialize() override
    {
      m_port.registerProvider("probe", "SDOPackage::SDOService", m_probe);
      addPort(m_port);
      return RTC::RTC_OK;
    }

  private:
    RTC::CorbaPort m_port;
    Probe m_probe;
  };
} // namespace

extern "C" void probe_serverInit(RTC::Manager* manager)
{
  rtcoord::registerType<ProbeServer>(manager, rtcoord::spec("probe_server", "a service port providing an interface", {}));
}
