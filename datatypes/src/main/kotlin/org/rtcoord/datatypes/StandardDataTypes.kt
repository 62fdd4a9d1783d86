package org.rtcoord.datatypes

import java.util.concurrent.ConcurrentHashMap

/**
 * The data types of OpenRTM-aist's `BasicDataType.idl`, `ExtendedDataTypes.idl` and `InterfaceDataTypes.idl`, which the
 * idl module declares. Each is read on first use from the TypeCode idlj generated for it at build time (a class load:
 * about a millisecond in a JVM already running Kotlin and JacORB), not parsed at run time (the three files cost about
 * 450 ms cold).
 */
public object StandardDataTypes {
    /** The IDL files that declare them, as the idl module ships them (resources under [RESOURCE_DIRECTORY]). */
    @JvmField
    public val FILES: List<String> = listOf("BasicDataType.idl", "ExtendedDataTypes.idl", "InterfaceDataTypes.idl")

    /** Where [FILES] are in the class path. */
    public const val RESOURCE_DIRECTORY: String = "org/rtcoord/idl"

    private val known = ConcurrentHashMap<String, Lookup>()

    /**
     * The standard type [name] means (any form [DataTypeName] takes: `IDL:RTC/RangeData:1.0`, `RangeData`, ...), or
     * null when it names none.
     */
    @JvmStatic
    public fun named(name: String): IdlType? {
        val id = DataTypeName.repositoryId(name)
        return known.computeIfAbsent(id, ::lookUp).type
    }

    private fun lookUp(repositoryId: String): Lookup {
        val path = repositoryId.removePrefix("IDL:").substringBeforeLast(':').split('/')
        if (path.size != 2 || path[0] != "RTC" || path[1].isEmpty()) return Lookup(null)
        val helper =
            try {
                Class.forName("RTC.${path[1]}Helper", true, StandardDataTypes::class.java.classLoader)
            } catch (e: ClassNotFoundException) {
                return Lookup(null)
            }
        val code = helper.getMethod("type").invoke(null) as org.omg.CORBA.TypeCode
        if (code.id() != repositoryId) return Lookup(null)
        return Lookup(runCatching { TypeCodes.read(code) }.getOrNull())
    }

    /** A lookup's answer, null included: ConcurrentHashMap holds no null. */
    private class Lookup(val type: IdlType?)
}
