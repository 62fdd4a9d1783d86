package org.rtcoord.profile

import org.jspecify.annotations.Nullable
import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields

/**
 * How a profile refers to a component: its component id and instance name, with, for a port, the port (`instance.port`,
 * as rtshell and RTSystemEditor write it) and, for an execution context, the context id.
 */
public class TargetComponent
@JvmOverloads
constructor(
    public val componentId: String,
    public val instanceName: String,
    /** Set for a port end of a connector. */
    public val portName: @Nullable String? = null,
    /** Set for the target of an ordering condition. */
    public val contextId: @Nullable String? = null,
    public val ext: Extension = Extension(),
) : ValueObject() {
    /** The port's short name: [portName] without the `instance.` prefix. */
    public val shortPortName: @Nullable String?
        get() = portName?.removePrefix("$instanceName.")

    /** This target naming another port, [portName] (`instance.port`). */
    public fun withPortName(portName: @Nullable String?): TargetComponent =
        TargetComponent(componentId, instanceName, portName, contextId, ext)

    override fun fields(): ValueFields =
        ValueFields(
            "componentId" to componentId,
            "instanceName" to instanceName,
            "portName" to portName,
            "contextId" to contextId,
            "ext" to ext,
        )
}
