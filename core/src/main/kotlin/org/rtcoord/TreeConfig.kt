package org.rtcoord

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlin.time.toKotlinDuration

/**
 * How an [RtcTree] talks to the system.
 *
 * @property nameServers name servers added at creation: `host`, `host:port` or `corbaloc:` addresses.
 * @property callTimeout the deadline of every remote call unless the call gives its own.
 * @property concurrency how many remote calls discovery keeps in flight at once.
 * @property orb an `org.omg.CORBA.ORB` owned by the host application; the tree then neither configures nor destroys it.
 *   By default the tree creates and owns a JacORB ORB. Typed `Any` so that the API names no CORBA type: in the OSGi
 *   bundle, CORBA's packages are private, and the host's own would not be the same. On a host's ORB the tree cannot
 *   count what its sockets hold, so an abort whose component is reset at once may, under load, be published as a
 *   deactivation (its ERROR hint read too late).
 * @property listenAddress the one address the tree's own ORB listens on for callbacks (observers), and the only one its
 *   object references carry. By default (null) the address this host uses to reach the first name server the tree has
 *   when it makes its first remote call: loopback for a name server on this host or when there is none. Name servers
 *   added later must be able to reach that address (their components call observers back there); give an address
 *   explicitly when they cannot. `0.0.0.0` listens on every interface, and only when given.
 * @property listenerFailures where what event listeners and handlers throw goes, with the listener and the event
 *   ([ListenerFailure]); by default it is logged ([ListenerFailureHandler.Log]). Never dropped.
 * @property speed how many times as fast as the robot's clock the tree's own time runs: its timers, polling, liveness
 *   checks, call deadlines and the heartbeats it asks observers for, and a coordinator's waits and measures on it. 1
 *   (the default) on a robot; more only against a simulated system that runs as fast (`rtcoord test --speed`). Every
 *   duration the tree and its coordinators are given or report stays in the robot's time.
 *
 * Java callers write `new TreeConfig(List.of("127.0.0.1:2809"))`, or use a [Builder]: `new
 * TreeConfig.Builder().nameServer("127.0.0.1").build()`. [listenAddressProblem] checks a listen address before it is
 * given.
 */
public class TreeConfig(
    public val nameServers: List<String> = emptyList(),
    @get:JvmSynthetic public val callTimeout: Duration = 3.seconds,
    public val concurrency: Int = 32,
    public val orb: Any? = null,
    public val listenAddress: String? = null,
    public val listenerFailures: ListenerFailureHandler = ListenerFailureHandler.Log,
    public val speed: Double = 1.0,
) {
    /** A configuration with [nameServers] and the defaults for the rest. */
    public constructor(nameServers: List<String>) : this(nameServers, 3.seconds)

    /** [callTimeout] in milliseconds, for Java callers. */
    public val callTimeoutMillis: Long
        get() = callTimeout.inWholeMilliseconds

    init {
        require(speed > 0 && speed.isFinite()) { "speed must be positive, was $speed" }
        require(callTimeout.isPositive()) { "callTimeout must be positive, was $callTimeout" }
        require(concurrency > 0) { "concurrency must be positive, was $concurrency" }
        require(orb == null || orb is org.omg.CORBA.ORB) {
            "orb: a ${orb!!.javaClass.name} is not an org.omg.CORBA.ORB"
        }
        val problem = listenAddress?.let(::listenAddressProblem)
        require(problem == null) { "listen address: $problem" }
    }

    /**
     * Builds a [TreeConfig] step by step, for Java callers: `new TreeConfig.Builder().nameServer("127.0.0.1").build()`.
     */
    public class Builder {
        private val nameServers = mutableListOf<String>()
        private var callTimeout: Duration = 3.seconds
        private var concurrency = 32
        private var orb: Any? = null
        private var listenAddress: String? = null
        private var listenerFailures: ListenerFailureHandler = ListenerFailureHandler.Log
        private var speed = 1.0

        /** Adds a name server (see [TreeConfig.nameServers]). */
        public fun nameServer(address: String): Builder = apply { nameServers += address }

        /** Sets [TreeConfig.callTimeout]. */
        public fun callTimeout(timeout: java.time.Duration): Builder = apply {
            callTimeout = timeout.toKotlinDuration()
        }

        /** Sets [TreeConfig.concurrency]. */
        public fun concurrency(calls: Int): Builder = apply { concurrency = calls }

        /** Sets [TreeConfig.orb]: an `org.omg.CORBA.ORB` the host application owns. */
        public fun orb(orb: Any?): Builder = apply { this.orb = orb }

        /** Sets [TreeConfig.listenAddress]. */
        public fun listenAddress(address: String?): Builder = apply { listenAddress = address }

        /** Sets [TreeConfig.listenerFailures]. */
        public fun listenerFailures(handler: ListenerFailureHandler): Builder = apply { listenerFailures = handler }

        /** Sets [TreeConfig.speed]. */
        public fun speed(speed: Double): Builder = apply { this.speed = speed }

        /** The configuration; fails as the constructor does on a bad value. */
        public fun build(): TreeConfig =
            TreeConfig(nameServers.toList(), callTimeout, concurrency, orb, listenAddress, listenerFailures, speed)
    }
}
