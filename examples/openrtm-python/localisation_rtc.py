"""The localisation system's components for a real OpenRTM-aist-Python manager.

Written for rtcoord's end-to-end test (OpenRtmPythonTest): the same types, ports and parameters as the
fixtures' localisation system. A manager loads each type's module (laser.py, gyro.py, ...) from its
load path; this module holds what they share and is not a component module itself.
"""

import OpenRTM_aist
import RTC


def spec(type_name, description, parameters=None):
    """A component profile in the flat form OpenRTM-aist's factories take."""
    profile = [
        "implementation_id", type_name, "type_name", type_name, "description", description,
        "version", "1.0", "vendor", "rtcoord", "category", "localisation",
        "activity_type", "DataFlowComponent", "max_instance", "10", "language", "Python", "lang_type", "SCRIPT",
    ]
    for name, value in (parameters or {}).items():
        profile += ["conf.default." + name, value]
    return profile + [""]


def register(manager, profile, component):
    """Registers the factory of the type [profile] describes, making instances of [component]."""
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=profile), component, OpenRTM_aist.Delete)


class Source(OpenRTM_aist.DataFlowComponentBase):
    """A sensor that writes one sample per period on one out-port.

    Parameter `broken`: while it is 1 the sensor's execution fails (the component goes to ERROR) and
    every reset fails too, as hardware that stays broken does.
    """

    def __init__(self, manager, port, data, sample):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)
        self._port_name = port
        self._data = data
        self._sample = sample
        self._tick = 0
        self._broken = [0]

    def onInitialize(self):
        self.bindParameter("broken", self._broken, "0")
        self._out = OpenRTM_aist.OutPort(self._port_name, self._data)
        self.addOutPort(self._port_name, self._out)
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        if self._broken[0]:
            return RTC.RTC_ERROR
        self._tick += 1
        self._data.data = self._sample(self._tick)
        self._out.write()
        return RTC.RTC_OK

    def onReset(self, ec_id):
        return RTC.RTC_ERROR if self._broken[0] else RTC.RTC_OK


class Localiser(OpenRTM_aist.DataFlowComponentBase):
    """A localiser fusing two in-ports into a pose (x, y, heading): the odometry's, when it has one."""

    def __init__(self, manager, inputs):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)
        self._inputs = inputs
        self._gain = [1.0]

    def onInitialize(self):
        self.bindParameter("gain", self._gain, "1.0")
        self._in = {}
        for name, data in self._inputs:
            self._in[name] = (OpenRTM_aist.InPort(name, data), data)
            self.addInPort(name, self._in[name][0])
        self._pose = RTC.TimedDoubleSeq(RTC.Time(0, 0), [0.0, 0.0, 0.0])
        self._out = OpenRTM_aist.OutPort("pose", self._pose)
        self.addOutPort("pose", self._out)
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        port, data = self._in["odo"]
        if port.isNew():
            port.read()
            if len(data.data) == 3:
                self._pose.data = list(data.data)
                self._out.write()
        for name, (other, _) in self._in.items():
            if name != "odo" and other.isNew():
                other.read()
        return RTC.RTC_OK


def time_double_seq():
    return RTC.TimedDoubleSeq(RTC.Time(0, 0), [])


def time_double():
    return RTC.TimedDouble(RTC.Time(0, 0), 0.0)
