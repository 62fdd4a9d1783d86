package org.rtcoord.internal

import org.rtcoord.OperationUnsupportedException
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.UnreachableException
import org.rtcoord.WrongKindException

/**
 * Tells a name server that fails from an address where something else answers. A root context's listing that fails with
 * OBJECT_NOT_EXIST (no `NameService` object there) or BAD_OPERATION (an object that has no `list`) means a server
 * answered, as something other than a name server: a manager's port given for a name server's is the common case (2810
 * next to 2809). Saying "unreachable" there sends the user looking for a server that is down, when it is the address
 * that is wrong.
 */
internal class NameServerProbe(private val core: TreeCore, private val path: RtcPath, private val address: String) {
    /** What to report instead of [failure], the root context's listing's: what answers, or [failure] itself. */
    suspend fun explain(failure: RtcException): RtcException {
        if (!answeredAsSomethingElse(failure)) return failure
        // Not the root context's stub: a stub answers _is_a for its own type without asking.
        val root = objectAt(NAME_SERVICE_KEY)
        val answer =
            try {
                if (isA(root, NAMING_CONTEXT)) return failure
                TYPES.entries.firstOrNull { (id, _) -> isA(root, id) }?.let { (id, label) -> "$label ($id)" }
                    ?: "CORBA object other than a naming context"
            } catch (e: UnreachableException) {
                if (e.cause !is org.omg.CORBA.OBJECT_NOT_EXIST) return failure
                // No object under the key NameService: the server there may be a manager, known by its own key.
                managerThere()?.let { "manager ($it)" } ?: "CORBA server with no NameService object"
            } catch (e: RtcException) {
                return failure
            }
        return WrongKindException(path.toString(), "name server", answer)
    }

    private fun answeredAsSomethingElse(failure: RtcException): Boolean =
        failure is OperationUnsupportedException ||
            (failure is UnreachableException && failure.cause is org.omg.CORBA.OBJECT_NOT_EXIST)

    /** The manager's type id if an OpenRTM-aist manager answers at `corbaloc:iiop:address/manager`, else null. */
    private suspend fun managerThere(): String? =
        try {
            MANAGER.takeIf { isA(objectAt(MANAGER_KEY), it) }
        } catch (e: RtcException) {
            null
        }

    private fun objectAt(key: String): org.omg.CORBA.Object =
        core.orb.orb.string_to_object("corbaloc:iiop:$address/$key")

    private suspend fun isA(target: org.omg.CORBA.Object, id: String): Boolean =
        core.remote.call(path.toString(), "_is_a $id") { target._is_a(id) }

    private companion object {
        const val NAMING_CONTEXT = "IDL:omg.org/CosNaming/NamingContext:1.0"
        const val MANAGER = "IDL:RTM/Manager:1.0"
        const val MANAGER_KEY = "manager"
        const val NAME_SERVICE_KEY = "NameService"

        /** What may answer at a name server's address instead, by type id, in words. */
        val TYPES =
            linkedMapOf(
                MANAGER to "manager",
                "IDL:omg.org/RTC/RTObject:1.0" to "component",
            )
    }
}
