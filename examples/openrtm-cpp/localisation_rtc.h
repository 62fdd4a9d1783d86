// The localisation system's components for a real OpenRTM-aist C++ 2.0 manager, written for rtcoord's
// end-to-end test (OpenRtmCppTest): the same types, ports, data types and parameters as the fixtures'
// localisation system and examples/openrtm-python. Each type is a module of its own (laser.cpp, ...);
// this header holds what they share.
#ifndef RTCOORD_LOCALISATION_RTC_H
#define RTCOORD_LOCALISATION_RTC_H

// omniORB declares the data types' Any operators at global scope, out of reach of argument-dependent
// lookup: they must be declared before the port templates that use them.
#include <rtm/idl/BasicDataTypeSkel.h>

#include <rtm/DataFlowComponentBase.h>
#include <rtm/InPort.h>
#include <rtm/Manager.h>
#include <rtm/OutPort.h>

#include <map>
#include <string>

namespace rtcoord
{
  // A component profile as OpenRTM-aist's factories take it; [parameters] become the default set.
  inline coil::Properties spec(const std::string& type, const std::string& description,
                               const std::map<std::string, std::string>& parameters)
  {
    coil::Properties profile;
    profile["implementation_id"] = type;
    profile["type_name"] = type;
    profile["description"] = description;
    profile["version"] = "1.0";
    profile["vendor"] = "rtcoord";
    profile["category"] = "localisation";
    profile["activity_type"] = "DataFlowComponent";
    profile["max_instance"] = "10";
    profile["language"] = "C++";
    profile["lang_type"] = "compile";
    for (const auto& parameter : parameters)
      {
        profile["conf.default." + parameter.first] = parameter.second;
      }
    return profile;
  }

  // Registers the factory of [Component] under [profile].
  template <class Component>
  void registerType(RTC::Manager* manager, coil::Properties profile)
  {
    manager->registerFactory(profile, RTC::Create<Component>, RTC::Delete<Component>);
  }

  // A sensor that writes one sample of Data per period on its out-port Port, made by Sample from the
  // period's number. Parameter `broken`: while it is 1 the sensor's execution fails (the component goes
  // to ERROR) and every reset fails too, as hardware that stays broken does.
  template <class Data, const char* Port, void (*Sample)(Data&, long)>
  class Source : public RTC::DataFlowComponentBase
  {
  public:
    explicit Source(RTC::Manager* manager) : RTC::DataFlowComponentBase(manager), m_out(Port, m_data) {}

    RTC::ReturnCode_t onInitialize() override
    {
      bindParameter("broken", m_broken, "0");
      addOutPort(Port, m_out);
      return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
      if (m_broken != 0)
        {
          return RTC::RTC_ERROR;
        }
      Sample(m_data, ++m_tick);
      m_out.write();
      return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onReset(RTC::UniqueId) override
    {
      return m_broken != 0 ? RTC::RTC_ERROR : RTC::RTC_OK;
    }

  private:
    Data m_data;
    RTC::OutPort<Data> m_out;
    int m_broken{0};
    long m_tick{0};
  };

  // A localiser fusing the odometry's in-port `odo` and the in-port Other into a pose (x, y, heading):
  // the odometry's, when it has one. OtherFirst: Other is registered before `odo`, as the type lists
  // its ports. Parameter `gain`.
  template <class OtherData, const char* Other, bool OtherFirst>
  class Localiser : public RTC::DataFlowComponentBase
  {
  public:
    explicit Localiser(RTC::Manager* manager)
      : RTC::DataFlowComponentBase(manager), m_odoIn("odo", m_odo), m_otherIn(Other, m_other), m_poseOut("pose", m_pose)
    {
    }

    RTC::ReturnCode_t onInitialize() override
    {
      bindParameter("gain", m_gain, "1.0");
      if (OtherFirst)
        {
          addInPort(Other, m_otherIn);
        }
      addInPort("odo", m_odoIn);
      if (!OtherFirst)
        {
          addInPort(Other, m_otherIn);
        }
      addOutPort("pose", m_poseOut);
      return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
      if (m_odoIn.isNew())
        {
          m_odoIn.read();
          if (m_odo.data.length() == 3)
            {
              m_pose.data = m_odo.data;
              m_poseOut.write();
            }
        }
      if (m_otherIn.isNew())
        {
          m_otherIn.read();
        }
      return RTC::RTC_OK;
    }

  private:
    RTC::TimedDoubleSeq m_odo;
    RTC::InPort<RTC::TimedDoubleSeq> m_odoIn;
    OtherData m_other;
    RTC::InPort<OtherData> m_otherIn;
    RTC::TimedDoubleSeq m_pose;
    RTC::OutPort<RTC::TimedDoubleSeq> m_poseOut;
    double m_gain{1.0};
  };
} // namespace rtcoord

#endif // RTCOORD_LOCALISATION_RTC_H
