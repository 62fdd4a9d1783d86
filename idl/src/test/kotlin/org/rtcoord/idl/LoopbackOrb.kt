package org.rtcoord.idl

import java.util.Properties
import org.omg.CORBA.ORB
import org.omg.PortableServer.POA
import org.omg.PortableServer.POAHelper

/** A JacORB ORB listening on an ephemeral loopback port, with its root POA active. */
internal class LoopbackOrb : AutoCloseable {
    val orb: ORB =
        ORB.init(
            emptyArray(),
            Properties().apply {
                setProperty("org.omg.CORBA.ORBClass", "org.jacorb.orb.ORB")
                setProperty("org.omg.CORBA.ORBSingletonClass", "org.jacorb.orb.ORBSingleton")
                setProperty("OAIAddr", "127.0.0.1")
                setProperty("jacorb.retries", "0")
                setProperty("jacorb.iiop.enable_loopback", "off")
            },
        )
    val poa: POA = POAHelper.narrow(orb.resolve_initial_references("RootPOA")).also { it.the_POAManager().activate() }

    override fun close() {
        orb.shutdown(true)
        orb.destroy()
    }
}
