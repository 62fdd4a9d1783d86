package org.rtcoord.profile

/** The ordering blocks of a profile, with their element names in XML and keys in YAML. */
public enum class OrderingKind(internal val xmlName: String, internal val yamlKey: String) {
    START_UP("StartUp", "startUp"),
    SHUT_DOWN("ShutDown", "shutDown"),
    ACTIVATION("Activation", "activation"),
    DEACTIVATION("Deactivation", "deactivation"),
    RESETTING("Resetting", "resetting"),
    INITIALIZING("Initializing", "initializing"),
    FINALIZING("Finalizing", "finalizing"),
}

/** One ordering block: the targets of an action (activation, ...) with their conditions. */
public data class Ordering(val targets: List<OrderedTarget> = emptyList(), val ext: Extension = Extension())

/** One component's place in an ordering: its [sequence] number and the [condition] before acting on it. */
public data class OrderedTarget(
    val sequence: Int,
    /** The component and its execution context ([TargetComponent.contextId]). */
    val target: TargetComponent,
    val condition: Condition = Condition.None,
    val ext: Extension = Extension(),
)

/** What must hold before a target is acted on. */
public sealed interface Condition {
    /** No condition: act in sequence order. */
    public object None : Condition {
        override fun toString(): String = "None"
    }

    /** Wait [milliseconds] before acting. */
    public data class WaitTime(val milliseconds: Int) : Condition

    /**
     * Act once the [components] have reached the action's state, waiting at most [timeoutMillis] (0:
     * no limit); [sendingTiming] `SYNC` waits for them, `ASYNC` does not.
     */
    public data class Preceding(
        val components: List<TargetComponent>,
        val timeoutMillis: Int = 0,
        val sendingTiming: String = "ASYNC",
    ) : Condition
}
