package org.rtcoord.sim

/**
 * The `rtsExt:Properties` that tell a simulator what the RTSProfile schema cannot. `rtcoord profile save` writes them
 * all; a profile without them (rtcryo's, RTSystemEditor's) still simulates.
 *
 * On the system element, the managers: the master ([MANAGER], [MANAGER_TYPES], [MANAGER_COMPONENTS], [MANAGER_COMMAND])
 * and each slave, numbered from 1 in the master's order ([slave]: `name`, `components`, `types`, `loadable`); lists are
 * separated by commas. A type with no instance in the system needs its ports added by hand ([typePort]), as no live
 * system tells them.
 *
 * On a service port, its interfaces ([interfaceKey]); on an execution context, its implementation ([CONTEXT_TYPE]).
 */
public object ProfileKeys {
    /** The master manager's naming path, as a component's `pathUri`: `host:port/host.host_cxt/manager.mgr`. */
    public const val MANAGER: String = "rtcoord.manager"

    /** The types the master can create, through its slaves or itself. */
    public const val MANAGER_TYPES: String = "rtcoord.manager.types"

    /** The components the master hosts itself. */
    public const val MANAGER_COMPONENTS: String = "rtcoord.manager.components"

    /**
     * What the master runs to start a slave when none of its slaves can create a type
     * (`manager.modules.<language>.manager_cmd`); the simulated master then starts a slave that can load every type the
     * profile names, as one started with the master's load path would.
     */
    public const val MANAGER_COMMAND: String = "rtcoord.manager.command"

    /** The prefix of every slave's keys. */
    public const val SLAVE_PREFIX: String = "rtcoord.slave."

    /**
     * The key of [field] of slave [number] (from 1): `name` (its instance name), `components` (the components it
     * hosts), `types` (those it has factories for), `loadable` (those of the modules it can load).
     */
    public fun slave(number: Int, field: String): String = "$SLAVE_PREFIX$number.$field"

    /**
     * The key of port [port] of type [type]: its value is `DataInPort DATA_TYPE`, `DataOutPort DATA_TYPE` or
     * `CorbaPort`.
     */
    public fun typePort(type: String, port: String): String = "rtcoord.type.$type.port.$port"

    /** The prefix of a service port's interface keys. */
    public const val INTERFACE_PREFIX: String = "rtcoord.interface."

    /**
     * The key of a service port's interface [instanceName], `provided` or `required` as [provided] says: its value is
     * the interface's type (`SimpleService::MyService`). The keys' order is the interfaces'.
     */
    public fun interfaceKey(provided: Boolean, instanceName: String): String =
        "$INTERFACE_PREFIX${if (provided) "provided" else "required"}.$instanceName"

    /**
     * An execution context's implementation (`PeriodicExecutionContext`, `EventDrivenExecutionContext`, ...), as its
     * profile's `type` says.
     */
    public const val CONTEXT_TYPE: String = "type"
}
