package org.rtcoord.sim

/** The managers both profiles record ([ProfileKeys]), the master's path below its name server. */
internal class ManagerDifferences(private val live: Map<String, String>, private val simulated: Map<String, String>) {
    private val liveSlaves = slaves(live)
    private val simulatedSlaves = slaves(simulated)
    val count: Int
        get() = (if (ProfileKeys.MANAGER in live) 1 else 0) + liveSlaves.size

    fun differences(): List<String> {
        val found = mutableListOf<String>()
        val masterA = live[ProfileKeys.MANAGER]?.belowNameServer()
        val masterB = simulated[ProfileKeys.MANAGER]?.belowNameServer()
        if (masterA != masterB) found += "master manager: ${masterA.shown()} live, ${masterB.shown()} simulated"
        val master = "manager ${masterA ?: masterB}"
        compareSets(
            found,
            "$master: types it can create",
            live[ProfileKeys.MANAGER_TYPES],
            simulated[ProfileKeys.MANAGER_TYPES],
        )
        compareSets(
            found,
            "$master: components it hosts",
            live[ProfileKeys.MANAGER_COMPONENTS],
            simulated[ProfileKeys.MANAGER_COMPONENTS],
        )
        val startsA = !live[ProfileKeys.MANAGER_COMMAND].isNullOrBlank()
        val startsB = !simulated[ProfileKeys.MANAGER_COMMAND].isNullOrBlank()
        if (startsA != startsB)
            found += "$master: starts slaves with a command: ${yesNo(startsA)} live, ${yesNo(startsB)} simulated"
        for (name in (liveSlaves.keys + simulatedSlaves.keys).distinct()) {
            val slave = "slave manager ${masterA ?: masterB}/$name"
            val sa = liveSlaves[name]
            val sb = simulatedSlaves[name]
            if (sa == null || sb == null) {
                found +=
                    "$slave: ${if (sa == null) "none" else "one"} live, ${if (sb == null) "none" else "one"} simulated"
                continue
            }
            for (field in listOf("components", "types", "loadable")) compareSets(
                found,
                "$slave: $field",
                sa[field],
                sb[field],
            )
        }
        return found
    }

    private fun compareSets(found: MutableList<String>, what: String, a: String?, b: String?) {
        val sa = a.items()
        val sb = b.items()
        if (sa != sb)
            found +=
                "$what: ${sa.joinToString().ifEmpty { "none" }} live, ${sb.joinToString().ifEmpty { "none" }} simulated"
    }

    private companion object {
        /** Each slave's fields by its name (numbered names for slaves that share one). */
        fun slaves(properties: Map<String, String>): Map<String, Map<String, String>> {
            val numbered =
                properties
                    .filterKeys { it.startsWith(ProfileKeys.SLAVE_PREFIX) }
                    .entries
                    .groupBy(
                        { it.key.removePrefix(ProfileKeys.SLAVE_PREFIX).substringBefore('.') },
                        { it.key.substringAfterLast('.') to it.value },
                    )
                    .toSortedMap(compareBy { it.toIntOrNull() ?: Int.MAX_VALUE })
            val seen = mutableMapOf<String, Int>()
            return numbered.values.associate { fields ->
                val values = fields.toMap()
                val name = values["name"].orEmpty()
                val count = seen.merge(name, 1, Int::plus)!!
                (if (count == 1) name else "$name (#$count)") to values
            }
        }

        fun String?.items(): List<String> = orEmpty().split(',').map { it.trim() }.filter { it.isNotEmpty() }.sorted()

        fun yesNo(value: Boolean) = if (value) "yes" else "no"
    }
}
