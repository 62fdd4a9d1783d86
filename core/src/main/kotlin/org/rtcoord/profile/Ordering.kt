package org.rtcoord.profile

import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields

/** The ordering blocks of a profile, with their element names in XML and keys in YAML. */
public enum class OrderingKind(
    @get:JvmSynthetic internal val xmlName: String,
    @get:JvmSynthetic internal val yamlKey: String,
) {
    START_UP("StartUp", "startUp"),
    SHUT_DOWN("ShutDown", "shutDown"),
    ACTIVATION("Activation", "activation"),
    DEACTIVATION("Deactivation", "deactivation"),
    RESETTING("Resetting", "resetting"),
    INITIALIZING("Initializing", "initializing"),
    FINALIZING("Finalizing", "finalizing"),
}

/** One ordering block: the targets of an action (activation, ...) with their conditions. */
public class Ordering
@JvmOverloads
constructor(
    public val targets: List<OrderedTarget> = emptyList(),
    public val ext: Extension = Extension(),
) : ValueObject() {
    override fun fields(): ValueFields = ValueFields("targets" to targets, "ext" to ext)
}

/** One component's place in an ordering: its [sequence] number and the [condition] before acting on it. */
public class OrderedTarget
@JvmOverloads
constructor(
    public val sequence: Int,
    /** The component and its execution context ([TargetComponent.contextId]). */
    public val target: TargetComponent,
    public val condition: Condition = Condition.None,
    public val ext: Extension = Extension(),
) : ValueObject() {
    override fun fields(): ValueFields =
        ValueFields("sequence" to sequence, "target" to target, "condition" to condition, "ext" to ext)
}

/** What must hold before a target is acted on. */
public sealed interface Condition {
    /** No condition: act in sequence order. */
    public object None : Condition {
        override fun toString(): String = "None"
    }

    /** Wait [milliseconds] before acting. */
    public class WaitTime(public val milliseconds: Int) : ValueObject(), Condition {
        override fun fields(): ValueFields = ValueFields("milliseconds" to milliseconds)
    }

    /**
     * Act once the [components] have reached the action's state, waiting at most [timeoutMillis] (0: no limit);
     * [sendingTiming] `SYNC` waits for them, `ASYNC` does not.
     */
    public class Preceding
    @JvmOverloads
    constructor(
        public val components: List<TargetComponent>,
        public val timeoutMillis: Int = 0,
        public val sendingTiming: String = "ASYNC",
    ) : ValueObject(), Condition {
        override fun fields(): ValueFields =
            ValueFields("components" to components, "timeoutMillis" to timeoutMillis, "sendingTiming" to sendingTiming)
    }
}
