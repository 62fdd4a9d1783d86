package org.rtcoord.internal

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import org.omg.CORBA.ORB
import org.omg.PortableServer.CurrentHelper
import org.omg.PortableServer.POA
import org.omg.PortableServer.POAHelper
import org.rtcoord.idl.OrbRecipe

/**
 * The tree's ORB: a JacORB ORB it configures and owns, listening on [listenAddress] only, whose every call times out
 * after [callTimeout]; or one handed in by a host application, used as it is (its policies are the host's) and left
 * running on close. An owned ORB starts on first use, when the tree knows which name server it talks to and so which
 * address to listen on.
 */
internal class OrbHolder(supplied: ORB?, listenAddress: () -> String, callTimeout: Duration) : AutoCloseable {
    val owned: Boolean = supplied == null
    private val started = lazy {
        supplied ?: withJacorbLoader { ORB.init(emptyArray(), jacorbProperties(listenAddress(), callTimeout)) }
    }
    val orb: ORB by started

    private val root = lazy { POAHelper.narrow(orb.resolve_initial_references("RootPOA")) }

    /**
     * The ORB's root POA, resolved on first use, when the tree first serves an object (an observer, a tap, a reply
     * handler). JacORB makes it, its object adapter and its listening socket then: a tree that only reads the system
     * (`ls`) never listens, and its [close] does not make them only to shut them down.
     */
    val rootPoa: POA by root

    /** The connections peers opened to an owned ORB; null for a host's, whose sockets are its own. */
    val inbound: InboundConnections? by lazy {
        if (owned)
            (orb as org.jacorb.orb.ORB).transportManager.socketFactoryManager.serverSocketFactory as InboundConnections
        else null
    }

    /**
     * Shuts an owned ORB down, once nothing more can come in. JacORB's shutdown deadlocks with a reader waiting for
     * room in a POA's full queue (`jacorb.poa.queue_wait`, which a peer flooding an observer with oneway calls brings
     * about): the reader holds its connection and its POA, and a POA being destroyed stops emptying its queue. So the
     * POAs first reject what they hold, and every connection peers opened is closed and its reader let go, before the
     * ORB shuts down. The shutdown waits for its POAs to be destroyed, so that nothing of the ORB runs (or logs) once
     * [close] returns; only a close from inside one of its own requests, where JacORB refuses to wait, leaves that
     * behind.
     */
    override fun close() {
        if (!owned || !started.isInitialized()) return
        val served = root.isInitialized()
        if (served) runCatching { rootPoa.the_POAManager().discard_requests(false) }
        inbound?.closeAll(READERS_GONE)
        orb.shutdown(!(served && inOwnRequest()))
        orb.destroy()
    }

    /** Whether this thread is serving one of the ORB's requests, where JacORB refuses to wait for its POAs. */
    private fun inOwnRequest(): Boolean = runCatching {
        CurrentHelper.narrow(orb.resolve_initial_references("POACurrent")).get_object_id()
    }
        .isSuccess

    private companion object {
        /** How long a closing ORB waits for its readers to let go; far longer than emptying a full queue takes. */
        val READERS_GONE = 5.seconds

        /**
         * Runs [create] with the class loader that loaded this class as the thread's context loader: JacORB loads its
         * ORB class and plug-ins through the context loader, which in an OSGi framework (an Eclipse plug-in) is the
         * caller's bundle or none, and cannot see the JacORB this bundle holds.
         */
        fun <T> withJacorbLoader(create: () -> T): T {
            val thread = Thread.currentThread()
            val previous = thread.contextClassLoader
            thread.contextClassLoader = OrbHolder::class.java.classLoader
            try {
                return create()
            } finally {
                thread.contextClassLoader = previous
            }
        }

        /**
         * rtcoord's one ORB recipe ([OrbRecipe], shared with the fixtures) on [listenAddress], any port, whose accepted
         * connections are counted ([InboundConnections]).
         */
        fun jacorbProperties(listenAddress: String, callTimeout: Duration) =
            OrbRecipe.properties(listenAddress, 0, callTimeout.inWholeMilliseconds).apply {
                setProperty("jacorb.net.server_socket_factory", InboundConnections::class.java.name)
            }
    }
}
