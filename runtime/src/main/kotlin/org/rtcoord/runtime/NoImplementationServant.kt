package org.rtcoord.runtime

import org.omg.CORBA.CompletionStatus
import org.omg.CORBA.NO_IMPLEMENT
import org.omg.CORBA.portable.InputStream
import org.omg.CORBA.portable.InvokeHandler
import org.omg.CORBA.portable.OutputStream
import org.omg.CORBA.portable.ResponseHandler
import org.omg.PortableServer.POA
import org.omg.PortableServer.Servant
import org.slf4j.LoggerFactory

/**
 * The object a simulated service port publishes for a provided interface: it is what the interface's type says (`_is_a`
 * and `_non_existent` answer as for a real servant), and every operation is answered at once with `NO_IMPLEMENT`, whose
 * message names the port, the interface and the operation. JacORB clients read that message from the reply's
 * `ExceptionDetailMessage` service context; other ORBs see `NO_IMPLEMENT` alone.
 */
internal class NoImplementationServant(private val port: String, private val service: ServiceInterface) :
    Servant(), InvokeHandler {
    private val log = LoggerFactory.getLogger(NoImplementationServant::class.java)

    /** The repository id of the interface's type: `IDL:SimpleService/MyService:1.0` for `SimpleService::MyService`. */
    private val repositoryId: String = repositoryId(service.typeName)

    override fun _all_interfaces(poa: POA?, objectId: ByteArray?): Array<String> = arrayOf(repositoryId)

    override fun _invoke(method: String, input: InputStream, handler: ResponseHandler): OutputStream {
        log.info(
            "{}: {} was called on {}, which the simulation provides without an implementation",
            port,
            method,
            service,
        )
        throw NO_IMPLEMENT(
            "$port: interface ${service.instanceName} (${service.typeName}) is simulated without an implementation: " +
                "$method cannot be answered (rtcoord simulates service ports, not their operations)",
            0,
            CompletionStatus.COMPLETED_NO,
        )
    }

    companion object {
        /** The repository id IDL gives [typeName] (`Module::Interface`, or an id already). */
        fun repositoryId(typeName: String): String =
            if (typeName.startsWith("IDL:")) typeName else "IDL:${typeName.removePrefix("::").replace("::", "/")}:1.0"
    }
}
