package org.rtcoord.internal

import org.omg.CORBA.ORB
import java.util.Properties
import kotlin.time.Duration

/**
 * The tree's ORB: a JacORB ORB it configures and owns, listening on [listenAddress] only, whose every
 * call times out after [callTimeout]; or one handed in by a host application, used as it is (its
 * policies are the host's) and left running on close. An owned ORB starts on first use, when the tree
 * knows which name server it talks to and so which address to listen on.
 */
internal class OrbHolder(supplied: ORB?, listenAddress: () -> String, callTimeout: Duration) : AutoCloseable {
    val owned: Boolean = supplied == null
    private val started = lazy { supplied ?: withJacorbLoader { ORB.init(emptyArray(), jacorbProperties(listenAddress(), callTimeout)) } }
    val orb: ORB by started

    override fun close() {
        if (!owned || !started.isInitialized()) return
        orb.shutdown(false)
        orb.destroy()
    }

    private companion object {
        /**
         * Runs [create] with the class loader that loaded this class as the thread's context loader: JacORB
         * loads its ORB class and plug-ins through the context loader, which in an OSGi framework (an
         * Eclipse plug-in) is the caller's bundle or none, and cannot see the JacORB this bundle holds.
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

        fun jacorbProperties(listenAddress: String, callTimeout: Duration) = Properties().apply {
            setProperty("org.omg.CORBA.ORBClass", "org.jacorb.orb.ORB")
            setProperty("org.omg.CORBA.ORBSingletonClass", "org.jacorb.orb.ORBSingleton")
            // Binds the listener to this address alone, and it is the only one the references carry.
            setProperty("OAIAddr", listenAddress)
            // A refused connection fails at once (default: five retries, 2.5 s); a host that never completes
            // the TCP handshake fails at the call deadline instead of after 90 s.
            setProperty("jacorb.retries", "0")
            setProperty("jacorb.connection.client.connect_timeout", callTimeout.inWholeMilliseconds.toString())
            // The deadline of every call. A RELATIVE_RT_TIMEOUT policy would do the same at three times the
            // cost per call (JacORB arms a timer for each request): measured 380 us against 115 us on loopback.
            setProperty("jacorb.connection.client.pending_reply_timeout", callTimeout.inWholeMilliseconds.toString())
            setProperty("jacorb.iiop.enable_loopback", "off")
            // Observer hints queue up behind the one thread that takes them, in order. A full queue would
            // reject the next ones (TRANSIENT, which a oneway sender never sees): a lost transition. Waiting
            // for room slows the senders down instead.
            setProperty("jacorb.poa.queue_wait", "on")
            setProperty("jacorb.poa.queue_max", "1000")
        }
    }
}
