package org.rtcoord.internal

import org.omg.CORBA.ORB
import org.omg.CORBA.PolicyManager
import org.omg.CORBA.PolicyManagerHelper
import org.omg.CORBA.SetOverrideType
import org.omg.Messaging.RELATIVE_RT_TIMEOUT_POLICY_TYPE
import java.util.Properties
import kotlin.time.Duration

/**
 * The tree's ORB: a JacORB ORB it configures and owns, whose every call times out after [callTimeout];
 * or one handed in by a host application, used as it is (its policies are the host's) and left running
 * on close.
 */
internal class OrbHolder(supplied: ORB?, listenAddress: String, callTimeout: Duration) : AutoCloseable {
    val owned: Boolean = supplied == null
    val orb: ORB = supplied ?: ORB.init(emptyArray(), jacorbProperties(listenAddress, callTimeout)).also { limitCalls(it, callTimeout) }

    override fun close() {
        if (!owned) return
        orb.shutdown(false)
        orb.destroy()
    }

    private companion object {
        fun limitCalls(orb: ORB, timeout: Duration) {
            val value = orb.create_any().apply { insert_ulonglong(timeout.inWholeNanoseconds / 100) }
            val manager: PolicyManager = PolicyManagerHelper.narrow(orb.resolve_initial_references("ORBPolicyManager"))
            manager.set_policy_overrides(arrayOf(orb.create_policy(RELATIVE_RT_TIMEOUT_POLICY_TYPE.value, value)), SetOverrideType.ADD_OVERRIDE)
        }

        fun jacorbProperties(listenAddress: String, connectTimeout: Duration) = Properties().apply {
            setProperty("org.omg.CORBA.ORBClass", "org.jacorb.orb.ORB")
            setProperty("org.omg.CORBA.ORBSingletonClass", "org.jacorb.orb.ORBSingleton")
            setProperty("OAIAddr", listenAddress)
            // A refused connection fails at once (default: five retries, 2.5 s); a host that never completes
            // the TCP handshake fails at the call deadline instead of after 90 s.
            setProperty("jacorb.retries", "0")
            setProperty("jacorb.connection.client.connect_timeout", connectTimeout.inWholeMilliseconds.toString())
            setProperty("jacorb.iiop.enable_loopback", "off")
        }
    }
}
