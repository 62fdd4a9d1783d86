"""Decodes samples with omniORB's own CDR code, as OpenRTM-aist-Python's CORBA_CdrMemoryStream does.

Reads lines `TYPE ORDER HEX` (ORDER little or big) on stdin; prints, for each, the type and a summary of
the value omniORB unmarshalled from the bytes, or the error it raised.
"""
import sys

import rtctree.rtc.BasicDataType_idl  # noqa: F401 (registers the types)
import rtctree.rtc.ExtendedDataTypes_idl  # noqa: F401
import rtctree.rtc.InterfaceDataTypes_idl  # noqa: F401
from omniORB import CORBA, cdrUnmarshal
from rtctree.rtc import RTC

CORBA.ORB_init([], CORBA.ORB_ID)


def summary(name, value):
    if name == "TimedPose2D":
        return "x=%.9f y=%.9f heading=%.9f sec=%d" % (value.data.position.x, value.data.position.y, value.data.heading, value.tm.sec)
    if name == "RangeData":
        return "ranges=%d first=%.9f maxRange=%.9f" % (len(value.ranges), value.ranges[0], value.config.maxRange)
    if name == "CameraImage":
        return "width=%d height=%d bpp=%d pixels=%d" % (value.width, value.height, value.bpp, len(value.pixels))
    if name == "PointCloud":
        return "points=%d z=%.9f" % (len(value.points), value.points[0].point.z)
    if name == "GPSData":
        return "fix=%s satellites=%d" % (value.fixType, value.numSatellites)
    if name == "ActArrayState":
        return "actuators=%d status=%s" % (len(value.actuators), value.actuators[0].status)
    return repr(value)


for line in sys.stdin:
    name, order, data = line.split()
    try:
        value = cdrUnmarshal(getattr(RTC, "_tc_" + name), bytes.fromhex(data), order == "little")
        print(name, order, summary(name, value))
    except Exception as error:  # the test prints what omniORB said
        print(name, order, "FAILED", repr(error))
