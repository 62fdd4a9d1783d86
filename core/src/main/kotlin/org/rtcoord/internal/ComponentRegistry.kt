package org.rtcoord.internal

import RTC.RTObject
import org.rtcoord.idl.ObjectIdentity

/**
 * One [ComponentObject] per component, however many paths reach it (its naming context, its manager, a second name
 * server): references are matched by the object they name ([ObjectIdentity], the ORB's notion of equivalence). Every
 * listing looks up each component it finds, so a lookup must cost little next to the call that found it.
 */
internal class ComponentRegistry(private val core: TreeCore) {
    private val byIdentity = HashMap<String, ComponentObject>()

    fun objectFor(ref: RTObject): ComponentObject {
        val identity = ObjectIdentity.of(ref)
        return synchronized(byIdentity) { byIdentity.getOrPut(identity) { ComponentObject(core, ref) } }
    }
}
