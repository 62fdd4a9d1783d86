// Keeps the laser localiser's active configuration set consistent with its gain: "precise" while the
// gain in force (the active set's) is above 2.0, "default" otherwise. The rule sees the gain in force
// change however it changes: set in the active set, or by a switch of the active set, whoever switches
// (`rtconf -s precise act`, this rule). It carries the gain into the set it switches to, so its own
// switch leaves the gain in force as it was and fires nothing more.
on(component("laser_localise0.rtc")).configParam("gain") { _, new ->
    val value = new ?: return@configParam
    val gain = value.toDoubleOrNull() ?: return@configParam
    val wanted = if (gain > 2.0) "precise" else "default"
    if ((event as ParameterChanged).set == wanted) return@configParam
    val localiser = component("laser_localise0.rtc")
    localiser.configure {
        set("gain", value)
        inSet(wanted)
    }
    localiser.activateConfigSet(wanted)
}
