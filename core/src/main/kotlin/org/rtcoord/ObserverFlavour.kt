package org.rtcoord

/**
 * The two ComponentObserver interfaces in use, by the repository id a component advertises and `add_service_profile`
 * takes.
 */
public enum class ObserverFlavour(
    /** The interface's repository id. */
    public val repositoryId: String,
    /** How people name it. */
    public val label: String,
) {
    /** `OpenRTM::ComponentObserver`: what stock OpenRTM-aist components accept and RTSystemEditor speaks. */
    OPENRTM("IDL:OpenRTM/ComponentObserver:1.0", "OpenRTM::ComponentObserver"),

    /**
     * `RTC::ComponentObserver` of FSM4RTC: what components built with the fsm4rtc observer accept and rtctree speaks.
     */
    OMG("IDL:omg.org/RTC/ComponentObserver:1.0", "RTC::ComponentObserver (FSM4RTC)"),
}
