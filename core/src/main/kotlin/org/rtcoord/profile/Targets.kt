package org.rtcoord.profile

import org.jspecify.annotations.Nullable

/**
 * How a profile refers to a component: its component id and instance name, with, for a port, the port
 * (`instance.port`, as rtshell and RTSystemEditor write it) and, for an execution context, the context id.
 */
public data class TargetComponent(
    val componentId: String,
    val instanceName: String,
    /** Set for a port end of a connector. */
    val portName: @Nullable String? = null,
    /** Set for the target of an ordering condition. */
    val contextId: @Nullable String? = null,
    val ext: Extension = Extension(),
) {
    /** The port's short name: [portName] without the `instance.` prefix. */
    val shortPortName: @Nullable String? get() = portName?.removePrefix("$instanceName.")
}
