package org.rtcoord.runtime

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import org.omg.CORBA.ORB
import org.omg.PortableServer.POA
import org.omg.PortableServer.POAHelper
import org.omg.PortableServer.Servant
import org.rtcoord.idl.OrbRecipe

/**
 * One runtime "process": a JacORB ORB listening on [host] (loopback by default) and [port], with its root POA active.
 * Outgoing calls (to peer ports, observers, the naming service) have a deadline of [callTimeout], so a dead peer never
 * stalls a component.
 */
public class RuntimeOrb
private constructor(
    public val orb: ORB,
    public val poa: POA,
    public val host: String,
    /** The deadline of every outgoing call. */
    internal val callTimeout: Duration,
) : AutoCloseable {
    /** The port the ORB listens on (the one asked for, or the one the system chose for port 0). */
    public val port: Int =
        (orb as org.jacorb.orb.ORB)
            .basicAdapter
            .endpointProfiles
            .filterIsInstance<org.jacorb.orb.iiop.IIOPProfile>()
            .first()
            .address
            .let { (it as org.jacorb.orb.iiop.IIOPAddress).port }

    @Volatile private var closed = false

    /** Its listener's connections, which [close] ends itself. */
    private val connections =
        (orb as org.jacorb.orb.ORB).transportManager.socketFactoryManager.serverSocketFactory as ServerConnections

    /** Activates [servant] and returns its reference. */
    public fun activate(servant: Servant): org.omg.CORBA.Object = poa.servant_to_reference(servant)

    /** Deactivates [servant]; later calls on its reference raise OBJECT_NOT_EXIST. */
    public fun deactivate(servant: Servant) {
        runCatching { poa.deactivate_object(poa.servant_to_id(servant)) }
    }

    /** Makes [target] reachable as `corbaloc::host:port/key`. */
    public fun bindKey(key: String, target: org.omg.CORBA.Object) {
        (orb as org.jacorb.orb.ORB).addObjectKey(key, target)
    }

    /** The `corbaloc:` address of [key] on this ORB. */
    public fun corbaloc(key: String): String = "corbaloc:iiop:$host:$port/$key"

    /**
     * Stops listening, releases the ORB's threads and ends every connection JacORB's shutdown left open; returns once
     * the port can be bound again. JacORB waits for the requests being served: a servant must not hold one forever.
     * Idempotent.
     */
    override fun close() {
        if (closed) return
        closed = true
        orb.shutdown(false)
        orb.destroy()
        connections.end()
        awaitPortReleased(host, port, 5.seconds)
    }

    public companion object {
        /**
         * Starts an ORB on [host]:[port]; port 0 lets the system choose a free one. It keeps [idleRequestThreads] of
         * its request threads when idle ([OrbRecipe.properties]).
         */
        public fun start(
            port: Int = 0,
            host: String = "127.0.0.1",
            callTimeout: Duration = 2.seconds,
            idleRequestThreads: Int = OrbRecipe.REQUEST_THREADS,
        ): RuntimeOrb {
            // The tree's own recipe: what the benchmarks measure on the runtime is what the tree runs with.
            val properties = OrbRecipe.properties(host, port, callTimeout.inWholeMilliseconds, idleRequestThreads)
            properties.setProperty("jacorb.net.server_socket_factory", ServerConnections::class.java.name)
            val orb = ORB.init(emptyArray(), properties)
            val poa = POAHelper.narrow(orb.resolve_initial_references("RootPOA"))
            poa.the_POAManager().activate()
            return RuntimeOrb(orb, poa, host, callTimeout)
        }
    }
}
