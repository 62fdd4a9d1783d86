package org.rtcoord.runtime

/**
 * What a component does on its execution context, in the spirit of OpenRTM's `onExecute` and friends. Each callback
 * returns true on success; false (or a thrown exception) sends the component to ERROR as OpenRTM does. Callbacks of one
 * component run one at a time.
 */
public interface Behaviour {
    public fun onActivated(rtc: ComponentContext): Boolean = true

    public fun onDeactivated(rtc: ComponentContext): Boolean = true

    public fun onExecute(rtc: ComponentContext): Boolean = true

    public fun onReset(rtc: ComponentContext): Boolean = true

    /** Does nothing, successfully. */
    public object Idle : Behaviour

    public companion object {
        /** Writes `value(tick)` to [port] on every execution. */
        public fun source(port: String, value: (Long) -> Any): Behaviour =
            object : Behaviour {
                override fun onExecute(rtc: ComponentContext): Boolean {
                    rtc.write(port, value(rtc.tick))
                    return true
                }
            }

        /**
         * Writes `combine(inputs)` to [output] whenever an input has a sample newer than the last one used: a localiser
         * fusing its sensors.
         */
        public fun fuse(inputs: List<String>, output: String, combine: (List<Sample?>) -> Any): Behaviour =
            object : Behaviour {
                private var lastUsed = emptyList<Sample?>()

                override fun onExecute(rtc: ComponentContext): Boolean {
                    val latest = inputs.map(rtc::latest)
                    if (latest != lastUsed && latest.any { it != null }) {
                        lastUsed = latest
                        rtc.write(output, combine(latest))
                    }
                    return true
                }
            }
    }
}

/** What a behaviour sees of its component. */
public interface ComponentContext {
    /** The component's instance name. */
    public val instanceName: String

    /** How many times `onExecute` ran since activation. */
    public val tick: Long

    /** The current value of parameter [name] in the active configuration set. */
    public fun parameter(name: String): String

    /** Writes [value] to out-port [port] (pushed to every connected in-port). */
    public fun write(port: String, value: Any)

    /** The latest sample in-port [port] received, or null if none yet. */
    public fun latest(port: String): Sample?
}
