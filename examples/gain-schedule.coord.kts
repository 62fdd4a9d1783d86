// Keeps the laser localiser in its "precise" configuration set while its gain is set above 2.0, and
// in "default" otherwise.
on(component("laser_localise0.rtc")).configParam("gain") { _, new ->
    val gain = new?.toDoubleOrNull() ?: return@configParam
    component("laser_localise0.rtc").activateConfigSet(if (gain > 2.0) "precise" else "default")
}
