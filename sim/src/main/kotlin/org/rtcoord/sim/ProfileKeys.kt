package org.rtcoord.sim

/**
 * The `rtsExt:Properties` of a profile's system element that tell a simulator what the schema cannot:
 * the manager and the types it can create. `rtcoord profile save` writes them; a type with no instance
 * in the system needs its ports added by hand, as no live system tells them.
 */
public object ProfileKeys {
    /** The master manager's naming path, as a component's `pathUri`: `host:port/host.host_cxt/manager.mgr`. */
    public const val MANAGER: String = "rtcoord.manager"

    /** The types the manager can create, separated by commas. */
    public const val MANAGER_TYPES: String = "rtcoord.manager.types"

    /** The key of port [port] of type [type]: its value is `DataInPort DATA_TYPE`, `DataOutPort DATA_TYPE` or `CorbaPort`. */
    public fun typePort(type: String, port: String): String = "rtcoord.type.$type.port.$port"
}
