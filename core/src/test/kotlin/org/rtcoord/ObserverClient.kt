package org.rtcoord

import _SDOPackage.ServiceProfile
import kotlin.random.Random
import org.omg.CORBA.portable.ObjectImpl
import org.rtcoord.runtime.RuntimeComponent
import org.rtcoord.runtime.RuntimeOrb

/**
 * A CORBA client with an ORB of its own that reaches a tree's observer the way anyone holding its reference could: it
 * finds the reference in the component's service profiles and sends hints of its own, genuine or to a forged object id.
 */
class ObserverClient : AutoCloseable {
    private val client = RuntimeOrb.start()

    /** The rtcoord observer attached to [component], as the component lists it. */
    fun profile(component: RuntimeComponent): ServiceProfile {
        val profiles = rtObject(component).get_service_profiles().filter { it.id.startsWith("rtcoord-observer-") }
        check(profiles.size == 1) { "${component.instanceName} has ${profiles.size} rtcoord observers" }
        return profiles.single().also {
            check(it.interface_type == "IDL:OpenRTM/ComponentObserver:1.0") {
                "not the OpenRTM flavour: ${it.interface_type}"
            }
        }
    }

    /** Detaches observer [id] from [component] as any client may, so the component no longer tells it anything. */
    fun detach(component: RuntimeComponent, id: String) {
        check(rtObject(component).get_configuration().remove_service_profile(id)) { "could not detach $id" }
    }

    /** Sends [hint] of [kind] to [observer] as the oneway call components make. */
    fun send(observer: org.omg.CORBA.Object, kind: OpenRTM.StatusKind, hint: String) {
        OpenRTM.ComponentObserverHelper.unchecked_narrow(reachable(observer)).update_status(kind, hint)
    }

    /** Sends [hint] of [kind] to [observer] asking for a reply, so that a rejection comes back as an exception. */
    fun sendExpectingReply(observer: org.omg.CORBA.Object, kind: OpenRTM.StatusKind, hint: String) {
        val target = reachable(observer) as ObjectImpl
        val request = target._request("update_status", true)
        OpenRTM.StatusKindHelper.write(request, kind)
        request.write_string(hint)
        target._releaseReply(target._invoke(request))
    }

    /**
     * Returns once [observer] has handled everything sent to it before: its calls are handled one at a time, in order.
     */
    fun sync(observer: org.omg.CORBA.Object) {
        check(exists(observer)) { "the observer is gone" }
    }

    /** Whether [observer]'s ORB still has it. */
    fun exists(observer: org.omg.CORBA.Object): Boolean = !reachable(observer)._non_existent()

    /**
     * [observer]'s reference with the object id replaced by [id] (16 random bytes by default): same host, port and POA,
     * another object. JacORB ends an object key with the POA-escaped object id.
     */
    fun forged(observer: org.omg.CORBA.Object, id: ByteArray = randomId()): org.omg.CORBA.Object {
        val ior = client.orb.object_to_string(observer)
        val parsed = org.jacorb.orb.ParsedIOR(client.orb as org.jacorb.orb.ORB, ior)
        val address =
            (parsed.effectiveProfile as org.jacorb.orb.iiop.IIOPProfile).address as org.jacorb.orb.iiop.IIOPAddress
        val key = parsed.get_object_key()
        val separator = key.lastIndexOf('/'.code.toByte())
        val forgedKey = key.copyOfRange(0, separator + 1) + id
        val escaped = forgedKey.joinToString("") { "%%%02x".format(it.toInt() and 0xff) }
        return client.orb.string_to_object("corbaloc:iiop:1.2@${address.ip}:${address.port}/$escaped")
    }

    override fun close() = client.close()

    private fun rtObject(component: RuntimeComponent): RTC.RTObject =
        RTC.RTObjectHelper.narrow(reachable(component.ref))

    /** [target] as a reference of this client's ORB, whichever ORB handed it out. */
    private fun reachable(target: org.omg.CORBA.Object): org.omg.CORBA.Object =
        client.orb.string_to_object(client.orb.object_to_string(target))

    private companion object {
        /** Bytes that JacORB's object keys would escape ('/' and '&') are left out, so the key stays as written. */
        fun randomId(): ByteArray {
            val bytes = ByteArray(16)
            do Random.nextBytes(bytes) while (bytes.any { it == '/'.code.toByte() || it == '&'.code.toByte() })
            return bytes
        }
    }
}
