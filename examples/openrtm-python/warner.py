"""A component that logs a warning when told to, for rtcoord's end-to-end test of component logs.

Written for OpenRtmPythonTest: parameter `warn`: set it to a new text and the next execution logs that
text at WARN through the component's own OpenRTM logger (`self._rtcout`), which the manager's logger
plugins (FluentLogger.py, configured in rtc.conf) send on. Its default is `none`, logged never:
OpenRTM-aist binds no parameter whose default is empty.
"""

import OpenRTM_aist
import RTC

import localisation_rtc as rtc

warner_spec = rtc.spec("warner", "logs a warning when its parameter changes", {"warn": "none"})


class Warner(OpenRTM_aist.DataFlowComponentBase):
    def __init__(self, manager):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)
        self._warn = ["none"]
        self._warned = "none"

    def onInitialize(self):
        self.bindParameter("warn", self._warn, "none")
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        warn = self._warn[0]
        if warn != self._warned:
            self._warned = warn
            self._rtcout.RTC_WARN(warn)
        return RTC.RTC_OK


def warnerInit(manager):
    rtc.register(manager, warner_spec, Warner)
