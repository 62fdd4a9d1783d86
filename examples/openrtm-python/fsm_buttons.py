"""Buttons for OpenRTM-aist's StaticFsm Microwave, pressed through configuration instead of a keyboard.

Written for rtcoord's end-to-end test (OpenRtmPythonExamplesTest), as the example's own Inputbutton is
driven from stdin: one TimedLong out-port per Microwave event (`open`, `close`, `minute`, `start`,
`stop`, `tick`), each connected to the Microwave's `event` port with `fsm_event_name` set to the event.
Parameter `press`: set it to `<event> <n>` (a new `n` each time) and the next execution writes one
sample on that event's port. Its default is `none`: OpenRTM-aist binds no parameter whose default is empty.
"""

import OpenRTM_aist
import RTC

import localisation_rtc as rtc

EVENTS = ("open", "close", "minute", "start", "stop", "tick")

fsm_buttons_spec = rtc.spec("fsm_buttons", "Microwave buttons pressed through configuration", {"press": "none"})


class Buttons(OpenRTM_aist.DataFlowComponentBase):
    def __init__(self, manager):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)
        self._press = ["none"]
        self._pressed = "none"

    def onInitialize(self):
        self.bindParameter("press", self._press, "none")
        self._ports = {}
        for event in EVENTS:
            data = RTC.TimedLong(RTC.Time(0, 0), 0)
            port = OpenRTM_aist.OutPort(event, data)
            self.addOutPort(event, port)
            self._ports[event] = (port, data)
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        press = self._press[0].strip()
        if press != self._pressed:
            self._pressed = press
            port, data = self._ports[press.split()[0]]
            data.data = 1
            port.write()
        return RTC.RTC_OK


def fsm_buttonsInit(manager):
    rtc.register(manager, fsm_buttons_spec, Buttons)
