package org.rtcoord.runtime

import RTC.ComponentProfile
import RTC.RTObject
import RTC.ReturnCode_t
import RTM.Manager
import RTM.ManagerHelper
import RTM.ManagerPOA
import RTM.ManagerProfile
import RTM.ModuleProfile
import _SDOPackage.NameValue
import java.util.concurrent.CopyOnWriteArrayList

/**
 * An `RTM::Manager` hosted by [runtime]. A master (named `manager`, bound as `<host>.host_cxt/manager.mgr`) hosts no
 * components: it forwards `create_component` to a slave. A slave creates components from the types of its loaded
 * modules in its own runtime; it is not bound in naming, only reachable through its master or at
 * `corbaloc:iiop:<host>:<port>/manager`.
 *
 * It is longer than most files here because it answers every operation of `RTM::Manager`, and a master forwards or
 * aggregates each through its slaves as OpenRTM-aist's does.
 */
public class RuntimeManager(
    public val runtime: RuntimeProcess,
    public val isMaster: Boolean,
    public val name: String = "manager",
    modules: List<RuntimeModule> = emptyList(),
    preloaded: List<String> = modules.map { it.fileName },
) : ManagerPOA() {
    private val loadable = modules.associateBy { it.fileName }
    private val loaded =
        CopyOnWriteArrayList(preloaded.onEach { require(it in loadable) { "no module $it to preload" } })
    private val masters = CopyOnWriteArrayList<Manager>()
    private val slaves = CopyOnWriteArrayList<Manager>()
    private val configuration =
        linkedMapOf(
            "manager.instance_name" to name,
            "manager.name" to name,
            "manager.is_master" to if (isMaster) "YES" else "NO",
            "manager.language" to LANGUAGE,
            "manager.modules.search_auto" to "YES",
            "manager.modules.$LANGUAGE.manager_cmd" to "",
            "corba.endpoints" to "${runtime.orb.host}:${runtime.orb.port}",
            "pid" to ProcessHandle.current().pid().toString(),
            "naming_formats" to "%h.host_cxt/%n.rtc",
            "refstring_path" to "/var/log/rtcmanager.ref",
            "components.precreate" to "",
            "modules.load_path" to ".",
            "modules.config_path" to "",
            "modules.preload" to preloaded.joinToString(","),
            "modules.init_func_prefix" to "",
            "modules.init_func_suffix" to "Init",
            "modules.download_allowed" to "NO",
            "modules.abs_path_allowed" to "YES",
            "os.name" to System.getProperty("os.name"),
            "os.release" to System.getProperty("os.version"),
            "os.version" to System.getProperty("os.version"),
            "os.arch" to System.getProperty("os.arch"),
            "os.hostname" to RuntimeProcess.hostContext.removeSuffix(".host_cxt"),
        )

    /** This manager's reference, reachable as `corbaloc:iiop:<host>:<port>/manager`. */
    public val ref: Manager =
        ManagerHelper.narrow(runtime.orb.activate(this)).also {
            runtime.orb.bindKey("manager", it)
            if (isMaster) runtime.bind("$name.mgr", it)
        }

    /** Makes [slave] one of this master's slaves, and this its master. */
    public fun adopt(slave: RuntimeManager) {
        check(isMaster) { "$name is not a master" }
        add_slave_manager(slave.ref)
        slave.add_master_manager(ref)
    }

    /**
     * Runs on the request thread before each `create_component`, with its spec: tests make creation slow with it, to
     * fault the manager while a creation is under way.
     */
    @Volatile public var beforeCreate: (spec: String) -> Unit = {}

    /**
     * What a master runs to start a new slave, as OpenRTM-aist runs `manager.modules.<language>.manager_cmd`: given the
     * new slave's instance name (`manager_%p`: the new process puts its pid for `%p`), it starts one that joins this
     * master. Null: no command is configured, and a master none of whose slaves could create a component refuses it.
     */
    @Volatile
    public var managerCommand: ((instanceName: String) -> Unit)? = null
        set(value) {
            field = value
            configuration["manager.modules.$LANGUAGE.manager_cmd"] = if (value == null) "" else "fixture-slave"
        }

    private fun factories(): List<ComponentType> =
        listOf(sharedComposite) + loaded.flatMap { loadable.getValue(it).types }

    override fun create_component(spec: String): RTObject? {
        beforeCreate(spec)
        val (typeName, options) = parse(spec)
        if (typeName.isBlank()) return null
        return if (isMaster) delegate(spec, options["manager_name"]) else createHere(typeName, options)
    }

    /**
     * As `Manager.createComponent`: an existing instance of the name is returned; a type without a factory is looked
     * for among the loadable modules (`manager.modules.search_auto`), whose module is loaded first. Null when no module
     * provides the type.
     */
    private fun createHere(typeName: String, options: Map<String, String>): RTObject? {
        options["instance_name"]?.let { name ->
            runtime.components
                .firstOrNull { it.instanceName == name }
                ?.let {
                    return it.ref
                }
        }
        val type = factories().firstOrNull { it.typeName == typeName } ?: autoLoad(typeName) ?: return null
        val instanceName = options["instance_name"] ?: runtime.nextName(typeName)
        return runtime.create(type, instanceName).ref
    }

    private fun autoLoad(typeName: String): ComponentType? {
        if (configuration["manager.modules.search_auto"].equals("NO", ignoreCase = true)) return null
        val module =
            loadable.values.firstOrNull { module -> module.types.any { it.typeName == typeName } } ?: return null
        if (module.fileName !in loaded) loaded += module.fileName
        return module.types.first { it.typeName == typeName }
    }

    /**
     * As `ManagerServant.create_component` on a master: to the slave named by `manager_name` (started with
     * [managerCommand] when there is none), else to each slave of the same language in turn, dropping those that fail;
     * when none creates it, to a new slave `manager_<n>` started for it.
     */
    private fun delegate(spec: String, managerName: String?): RTObject? {
        val forwarded = spec.withoutOption("manager_name")
        if (managerName != null) {
            val target = slaveNamed(managerName) ?: launch(managerName) ?: return null
            return runCatching { target.create_component(forwarded) }.getOrNull()
        }
        for (slave in ArrayList(slaves)) {
            val created =
                try {
                    if (slave.configurationValue("manager.language") != LANGUAGE) continue
                    slave.create_component(spec)
                } catch (e: org.omg.CORBA.SystemException) {
                    slaves.remove(slave)
                    null
                }
            if (created != null) return created
        }
        val fresh = launch(ANY_PID) ?: return null
        return runCatching { fresh.create_component(spec) }.getOrNull()
    }

    private fun slaveNamed(name: String): Manager? = slaveNames().entries.firstOrNull { it.value == name }?.key

    /** The slaves by instance name; a slave that fails is dropped. */
    private fun slaveNames(): Map<Manager, String?> =
        ArrayList(slaves).associateWith { slave ->
            try {
                slave.configurationValue("manager.instance_name")
            } catch (e: org.omg.CORBA.SystemException) {
                slaves.remove(slave)
                null
            }
        }

    /**
     * Runs [managerCommand] for a slave named [name] and waits (10 s at most, as OpenRTM does) until it joins; for
     * [ANY_PID], until a slave `manager_<digits>` joins that was not there before.
     */
    private fun launch(name: String): Manager? {
        val command = managerCommand ?: return null
        val numbered = Regex("manager_[0-9]+")
        val before = slaveNames().values.filterNotNull().toSet()
        command(name)
        val deadline = System.nanoTime() + LAUNCH_WAIT_NANOS
        while (System.nanoTime() < deadline) {
            val joined =
                if (name == ANY_PID) {
                    slaveNames()
                        .entries
                        .firstOrNull { (_, it) -> it != null && it !in before && numbered.matches(it) }
                        ?.key
                } else {
                    slaveNamed(name)
                }
            if (joined != null) return joined
            Thread.sleep(10)
        }
        return null
    }

    private fun Manager.configurationValue(name: String): String? =
        get_configuration().firstOrNull { it.name == name }?.value?.extract_string()

    override fun delete_component(instanceName: String): ReturnCode_t {
        val component =
            runtime.components.firstOrNull { it.instanceName == instanceName } ?: return ReturnCode_t.BAD_PARAMETER
        return component.exit()
    }

    override fun get_components(): Array<RTObject> =
        (runtime.components.map { it.ref } + fromSlaves { it.get_components().toList() }).toTypedArray()

    override fun get_component_profiles(): Array<ComponentProfile> =
        (runtime.components.map { it.get_component_profile() } + fromSlaves { it.get_component_profiles().toList() })
            .toTypedArray()

    /** What every slave answers to [read], as a master adds it to its own; a slave that fails is dropped. */
    private fun <T> fromSlaves(read: (Manager) -> List<T>): List<T> =
        ArrayList(slaves).flatMap { slave ->
            try {
                read(slave)
            } catch (e: org.omg.CORBA.SystemException) {
                slaves.remove(slave)
                emptyList()
            }
        }

    override fun get_factory_profiles(): Array<ModuleProfile> {
        val own = factories().map { type -> profile(*typeProfile(type)) }
        return (own + (if (isMaster) fromSlaves { it.get_factory_profiles().toList() } else emptyList())).toTypedArray()
    }

    /**
     * As `ModuleManager.getLoadableModules`: a profile per module on the load path, the profile of the component type
     * it provides (OpenRTM-aist reads it from the module; a module here that provides several gives its first) with the
     * module's file and language.
     */
    override fun get_loadable_modules(): Array<ModuleProfile> =
        loadable.values
            .map { module ->
                val described = module.types.firstOrNull()?.let(::typeProfile).orEmpty()
                profile(
                    *described,
                    "module_file_name" to module.fileName,
                    "module_file_path" to module.fileName,
                    "language" to LANGUAGE,
                )
            }
            .toTypedArray()

    private fun typeProfile(type: ComponentType): Array<Pair<String, String>> =
        arrayOf(
            "implementation_id" to type.typeName,
            "type_name" to type.typeName,
            "description" to type.description,
            "version" to type.version,
            "vendor" to type.vendor,
            "category" to type.category,
            "language" to LANGUAGE,
        )

    override fun get_loaded_modules(): Array<ModuleProfile> {
        val own = loaded.map { profile("file_path" to it) }
        return (own + (if (isMaster) fromSlaves { it.get_loaded_modules().toList() } else emptyList())).toTypedArray()
    }

    override fun load_module(path: String, initfunc: String): ReturnCode_t =
        when {
            path !in loadable -> ReturnCode_t.BAD_PARAMETER
            path in loaded -> ReturnCode_t.PRECONDITION_NOT_MET
            else -> ReturnCode_t.RTC_OK.also { loaded += path }
        }

    override fun unload_module(path: String): ReturnCode_t =
        if (loaded.remove(path)) ReturnCode_t.RTC_OK else ReturnCode_t.BAD_PARAMETER

    /** As `ManagerServant.get_profile`: the configuration's `manager` node, its keys without the `manager.` prefix. */
    override fun get_profile(): ManagerProfile =
        ManagerProfile(
            nameValues(
                configuration.filterKeys { it.startsWith("manager.") }.mapKeys { it.key.removePrefix("manager.") }
            )
        )

    override fun get_configuration(): Array<NameValue> = nameValues(configuration)

    override fun set_configuration(name: String, value: String): ReturnCode_t {
        configuration[name] = value
        return ReturnCode_t.RTC_OK
    }

    override fun is_master(): Boolean = isMaster

    override fun get_master_managers(): Array<Manager> = masters.toTypedArray()

    override fun add_master_manager(peer: Manager): ReturnCode_t = adding(masters, peer)

    override fun remove_master_manager(peer: Manager): ReturnCode_t = removing(masters, peer)

    override fun get_slave_managers(): Array<Manager> = slaves.toTypedArray()

    override fun add_slave_manager(peer: Manager): ReturnCode_t = adding(slaves, peer)

    override fun remove_slave_manager(peer: Manager): ReturnCode_t = removing(slaves, peer)

    override fun fork(): ReturnCode_t = ReturnCode_t.UNSUPPORTED

    override fun restart(): ReturnCode_t = ReturnCode_t.UNSUPPORTED

    override fun shutdown(): ReturnCode_t {
        Thread({ runtime.close() }, "runtime-manager-shutdown").start()
        return ReturnCode_t.RTC_OK
    }

    override fun get_service(name: String): org.omg.CORBA.Object? = null

    /**
     * [call] on [slave], or null when the call fails: then the slave is dropped, its process presumed gone, as
     * OpenRTM-aist's master does at the first failed call to a slave (until then `get_slave_managers` still lists it).
     */
    private fun <T> asking(slave: Manager, call: (Manager) -> T): T? =
        try {
            call(slave)
        } catch (e: org.omg.CORBA.SystemException) {
            slaves.remove(slave)
            null
        }

    private fun adding(list: MutableList<Manager>, peer: Manager): ReturnCode_t {
        if (list.any { it._is_equivalent(peer) }) return ReturnCode_t.PRECONDITION_NOT_MET
        list += peer
        return ReturnCode_t.RTC_OK
    }

    private fun removing(list: MutableList<Manager>, peer: Manager): ReturnCode_t =
        if (list.removeIf { it._is_equivalent(peer) }) ReturnCode_t.RTC_OK else ReturnCode_t.BAD_PARAMETER

    private fun profile(vararg properties: Pair<String, String>) = ModuleProfile(nameValues(properties.toMap()))

    private fun nameValues(values: Map<String, String>): Array<NameValue> =
        values
            .map { (name, value) ->
                NameValue(name, runtime.orb.orb.create_any().apply { insert_string(value) })
            }
            .toTypedArray()

    private companion object {
        /** The language of these managers and of the components they create, as `manager.language` says. */
        const val LANGUAGE = "Kotlin"

        /**
         * The composite type every OpenRTM-aist manager registers at start-up (`Manager.initComposite`), before any
         * module: so a master's factory list names it once for itself and once per slave. Its organisation of members
         * is not modelled: an instance is a component without ports.
         */
        val sharedComposite =
            ComponentType(
                "PeriodicECSharedComposite",
                vendor = "jp.go.aist",
                category = "composite.PeriodicECShared",
                version = "1.0",
                description = "PeriodicECSharedComposite",
            )

        /** The name a master gives a slave it starts for a component no slave could create. */
        const val ANY_PID = "manager_%p"

        /** How long a master waits for a slave it started to join it, as `createComponentByManagerName` does. */
        val LAUNCH_WAIT_NANOS = java.util.concurrent.TimeUnit.SECONDS.toNanos(10)

        /** [this] spec without option [name]. */
        fun String.withoutOption(name: String): String {
            val typeName = substringBefore('?')
            val rest = substringAfter('?', "").split('&').filter { it.isNotEmpty() && it.substringBefore('=') != name }
            return if (rest.isEmpty()) typeName else "$typeName?${rest.joinToString("&")}"
        }

        /** Splits `Type?key=value&key=value` into the type and its options. */
        fun parse(spec: String): Pair<String, Map<String, String>> {
            val typeName = spec.substringBefore('?')
            val options =
                spec
                    .substringAfter('?', "")
                    .split('&')
                    .filter { '=' in it }
                    .associate { it.substringBefore('=') to it.substringAfter('=') }
            return typeName to options
        }
    }
}
