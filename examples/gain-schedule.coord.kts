// Keeps a localiser's active configuration set consistent with its gain: "precise" while the gain in
// force (the active set's) is above 2.0, "default" otherwise. The component and the parameter are the
// first two arguments (laser_localise0.rtc and gain by default, as the fixtures have them); `rtcoord run`
// warns at start when the component lacks the parameter, and `--strict` refuses to run then. The rule
// sees the gain in force change however it changes: set in the active set, or by a switch of the active
// set, whoever switches (`rtconf -s precise act`, this rule). It carries the gain into the set it
// switches to, so its own switch leaves the gain in force as it was and fires nothing more.
val localiserName = args.getOrElse(0) { "laser_localise0.rtc" }
val parameter = args.getOrElse(1) { "gain" }

on(component(localiserName)).configParam(parameter) { _, new ->
    val value = new ?: return@configParam
    val gain = value.toDoubleOrNull() ?: return@configParam
    val wanted = if (gain > 2.0) "precise" else "default"
    if ((event as ParameterChanged).set == wanted) return@configParam
    val localiser = component(localiserName)
    localiser.configure {
        set(parameter, value)
        inSet(wanted)
    }
    localiser.activateConfigSet(wanted)
}
