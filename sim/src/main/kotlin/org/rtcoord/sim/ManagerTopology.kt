package org.rtcoord.sim

import org.rtcoord.profile.RtsProfile

/**
 * The managers a profile records ([ProfileKeys]) and which of them hosts each component: the processes a simulation
 * starts. Read as leniently as the rest of a profile: what cannot be followed is named in [warnings] and the components
 * concerned run all the same, in a process no manager owns.
 *
 * - No manager recorded (rtcryo's and RTSystemEditor's profiles): every component in one process, no manager.
 * - A master without slaves (profiles saved before slaves were recorded, or written by hand): one slave,
 *   `manager_slave`, hosting every component the master does not, able to create every type.
 * - A master with its slaves: each slave hosts the components it lists and creates its own types.
 */
internal class ManagerTopology
private constructor(
    /** The master's naming path below its name server (`ctx.host_cxt`, `manager.mgr`), or null. */
    val masterPath: List<String>?,
    /** The components the master hosts itself. */
    val masterComponents: List<String>,
    val slaves: List<Slave>,
    /** The components no recorded manager hosts. */
    val unhosted: List<String>,
    val warnings: List<String>,
) {
    /**
     * A slave: its instance [name], the [components] it hosts, the [types] it has factories for and those it can
     * [load][loadable].
     */
    class Slave(
        val name: String,
        val components: List<String>,
        val types: List<String>,
        val loadable: List<String>,
        val key: String,
    )

    /** The master's instance name, as its binding (`manager.mgr`) says. */
    val masterName: String?
        get() = masterPath?.last()?.removeSuffix(".mgr")

    companion object {
        /** The name of the one slave of a master whose profile records none. */
        const val DEFAULT_SLAVE = "manager_slave"

        /**
         * The topology [profile] records, for the components of it that can be simulated, [simulated] (instance names;
         * those left out are named elsewhere); a master without slaves gets one that can create [allTypes].
         */
        fun of(profile: RtsProfile, simulated: List<String>, allTypes: List<String>): ManagerTopology {
            val named = profile.components.map { it.instanceName }.toSet()
            val properties = profile.ext.properties
            val warnings = mutableListOf<String>()
            val masterPath =
                properties[ProfileKeys.MANAGER]?.let { path ->
                    namingPath(path).takeIf { it.isNotEmpty() && it.last().endsWith(".mgr") }
                        ?: null.also {
                            warnings +=
                                "${ProfileKeys.MANAGER}: '$path' is not a manager's path (host:port/ctx.host_cxt/name.mgr): no manager simulated"
                        }
                }
            val placed = linkedMapOf<String, String>()
            fun hosts(key: String, list: String?): List<String> =
                names(list).filter { name ->
                    when {
                        name !in named -> false.also { warnings += "$key: no component $name in the profile to host" }
                        name !in simulated -> false
                        name in placed -> false.also { warnings += "$key: $name is hosted by ${placed[name]} already" }
                        else -> true.also { placed[name] = key }
                    }
                }
            val masterComponents =
                if (masterPath == null) emptyList()
                else hosts(ProfileKeys.MANAGER_COMPONENTS, properties[ProfileKeys.MANAGER_COMPONENTS])
            val numbers =
                properties.keys
                    .filter { it.startsWith(ProfileKeys.SLAVE_PREFIX) }
                    .mapNotNull { it.removePrefix(ProfileKeys.SLAVE_PREFIX).substringBefore('.').toIntOrNull() }
                    .distinct()
                    .sorted()
            val slaves = numbers.mapNotNull { number ->
                val key = ProfileKeys.SLAVE_PREFIX + number
                val name = properties[ProfileKeys.slave(number, "name")]?.trim()
                when {
                    masterPath == null ->
                        null.also {
                            warnings +=
                                "$key: no master manager (${ProfileKeys.MANAGER}) for it to join: its components run without a manager"
                        }
                    name.isNullOrEmpty() ->
                        null.also {
                            warnings +=
                                "$key: no name (${ProfileKeys.slave(number, "name")}): its components run without a manager"
                        }
                    else ->
                        Slave(
                            name,
                            hosts("$key.components", properties[ProfileKeys.slave(number, "components")]),
                            names(properties[ProfileKeys.slave(number, "types")]),
                            names(properties[ProfileKeys.slave(number, "loadable")]),
                            key,
                        )
                }
            }
            val recorded =
                if (masterPath != null && numbers.isEmpty()) {
                    listOf(
                        Slave(
                            DEFAULT_SLAVE,
                            simulated.filter { it !in masterComponents },
                            allTypes,
                            emptyList(),
                            ProfileKeys.MANAGER,
                        )
                    )
                } else {
                    slaves
                }
            val hosted = (masterComponents + recorded.flatMap { it.components }).toSet()
            return ManagerTopology(masterPath, masterComponents, recorded, simulated.filter { it !in hosted }, warnings)
        }

        private fun names(list: String?): List<String> =
            list.orEmpty().split(',').map { it.trim() }.filter { it.isNotEmpty() }

        /**
         * The naming contexts and name of a profile path, `host:port/ctx.host_cxt/name.rtc`, without its name server.
         */
        fun namingPath(pathUri: String): List<String> = pathUri.trim('/').split('/').drop(1).filter { it.isNotEmpty() }
    }
}
