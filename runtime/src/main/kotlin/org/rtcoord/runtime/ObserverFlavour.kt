package org.rtcoord.runtime

/** The two ComponentObserver interfaces in use, by the repository id a component advertises. */
public enum class ObserverFlavour(public val repositoryId: String) {
    /** `OpenRTM::ComponentObserver`: what stock OpenRTM-aist components accept and RTSystemEditor sends. */
    OPENRTM("IDL:OpenRTM/ComponentObserver:1.0"),

    /** `RTC::ComponentObserver` (FSM4RTC): what Python rtctree and rtwatch attach. */
    OMG("IDL:omg.org/RTC/ComponentObserver:1.0"),
}

/** The kinds of status a component reports, mapped onto each flavour's StatusKind. */
internal enum class StatusKind(val openRtm: OpenRTM.StatusKind?, val omg: RTC.StatusKind) {
    COMPONENT_PROFILE(OpenRTM.StatusKind.COMPONENT_PROFILE, RTC.StatusKind.COMPONENT_PROFILE),
    RTC_STATUS(OpenRTM.StatusKind.RTC_STATUS, RTC.StatusKind.RTC_STATUS),
    EC_STATUS(OpenRTM.StatusKind.EC_STATUS, RTC.StatusKind.EC_STATUS),
    PORT_PROFILE(OpenRTM.StatusKind.PORT_PROFILE, RTC.StatusKind.PORT_PROFILE),
    CONFIGURATION(OpenRTM.StatusKind.CONFIGURATION, RTC.StatusKind.CONFIGURATION),
    HEARTBEAT(OpenRTM.StatusKind.HEARTBEAT, RTC.StatusKind.RTC_HEARTBEAT),
    EC_HEARTBEAT(null, RTC.StatusKind.EC_HEARTBEAT),
    FSM_STATUS(null, RTC.StatusKind.FSM_STATUS),
    FSM_STRUCTURE(null, RTC.StatusKind.FSM_STRUCTURE),
}
