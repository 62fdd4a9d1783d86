// OpenRTM-aist's StaticFsm Microwave machine (MicrowaveFsm.cpp, compiled from the checkout) in a
// component whose buttons are pressed through configuration, for rtcoord's end-to-end FSM test.
//
// The example's own Microwave cannot be driven on C++ 2.0.2: its EventInPort declares no
// `dataport.marshaling_types`, so PortBase::isExistingMarshalingType refuses every connection to it
// with RTC_ERROR ("cdr is illegal marshaling type."). This component dispatches the same events to the
// same machine as the port would (EventBinder's Macho::Event), on the execution context's thread.
//
// Parameter `press`: set it to `<event> <n>` (a new `n` each time; events `open`, `close`, `minute`,
// `start`, `stop`, `tick`) and the next execution dispatches that event; `minute` adds one minute.
#include "MicrowaveFsm.h"

#include "localisation_rtc.h"

#include <sstream>

namespace
{
  class FsmMicrowave : public RTC::DataFlowComponentBase
  {
  public:
    explicit FsmMicrowave(RTC::Manager* manager) : RTC::DataFlowComponentBase(manager), m_fsm(this) {}

    RTC::ReturnCode_t onInitialize() override
    {
      bindParameter("press", m_press, "none");
      return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onExecute(RTC::UniqueId /*ec_id*/) override
    {
      if (m_press == m_pressed)
        {
          return RTC::RTC_OK;
        }
      m_pressed = m_press;
      std::string event;
      std::istringstream(m_press) >> event;
      using Top = MicrowaveFsm::Top;
      RTC::TimedLong minutes{};
      minutes.data = 1;
      if (event == "open") m_fsm.dispatch(Macho::Event(&Top::open));
      else if (event == "close") m_fsm.dispatch(Macho::Event(&Top::close));
      else if (event == "minute") m_fsm.dispatch(Macho::Event(&Top::minute, minutes));
      else if (event == "start") m_fsm.dispatch(Macho::Event(&Top::start));
      else if (event == "stop") m_fsm.dispatch(Macho::Event(&Top::stop));
      else if (event == "tick") m_fsm.dispatch(Macho::Event(&Top::tick));
      return RTC::RTC_OK;
    }

  private:
    RTC::Machine<MicrowaveFsm::Top> m_fsm;
    std::string m_press{"none"};
    std::string m_pressed{"none"};
  };
} // namespace

extern "C" void fsm_microwaveInit(RTC::Manager* manager)
{
  rtcoord::registerType<FsmMicrowave>(manager, rtcoord::spec("fsm_microwave", "StaticFsm's Microwave machine, its buttons pressed through configuration",
                                                             {{"press", "none"}}));
}
