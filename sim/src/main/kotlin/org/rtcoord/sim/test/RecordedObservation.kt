package org.rtcoord.sim.test

import kotlinx.coroutines.CancellationException
import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.LifeCycle
import org.rtcoord.NodeFilters

/** One read a condition made: the expression it wrote, and what that returned. */
internal class Reading(val expression: String, val value: String) {
    override fun toString(): String = "$expression was $value"
}

/**
 * An [Observation] that reads through [reads] and records each read with what it returned, in the order made: what a
 * failure shows of its condition, as Kotlin's power-assert shows the sub-expressions of an assertion. One is made for
 * each reading of a condition.
 */
internal class RecordedObservation(private val reads: SystemReads) : Observation {
    private val recorded = mutableListOf<Reading>()

    /** The reads made so far, each expression once with its last value. */
    val readings: List<Reading>
        get() = recorded.associateBy { it.expression }.values.toList()

    override fun component(name: String): ObservedComponent = Component(name.removeSuffix(".rtc"))

    override suspend fun components(pattern: String): List<ObservedComponent> {
        val glob = NodeFilters.glob(pattern.removeSuffix(".rtc"))
        return record("components(\"$pattern\")", { names -> names.joinToString(prefix = "[", postfix = "]") }) {
                reads.names().filter(glob::matches).sorted()
            }
            .map(::Component)
    }

    override fun modeOf(machine: String): String? =
        record("modeOf(\"$machine\")", { it ?: "null (no mode yet)" }) { reads.modeOf(machine) }

    override val log: List<String>
        get() =
            record(
                "log",
                { lines -> if (lines.isEmpty()) "empty" else "${lines.size} lines, the last: ${lines.last()}" },
            ) {
                reads.log
            }

    private inline fun <T> record(expression: String, shown: (T) -> String = { it.toString() }, read: () -> T): T {
        val value =
            try {
                read()
            } catch (e: CancellationException) {
                throw e
            } catch (e: Exception) {
                recorded += Reading(expression, "not read: ${e.message ?: e.javaClass.simpleName}")
                throw e
            }
        recorded += Reading(expression, shown(value))
        return value
    }

    private inner class Component(override val name: String) : ObservedComponent {
        private val written = "component(\"$name\")"

        /** The observation, named: both are [TestDsl] receivers, which hide each other's members. */
        private val owner = this@RecordedObservation

        override suspend fun state(): LifeCycle =
            owner.record("$written.state()", { it?.toString() ?: "${LifeCycle.UNKNOWN} (no such component)" }) {
                owner.reads.state(name)
            } ?: LifeCycle.UNKNOWN

        override suspend fun exists(): Boolean = owner.record("$written.exists()") { owner.reads.exists(name) }

        override suspend fun snapshot(): ComponentSnapshot =
            owner.record(
                "$written.snapshot()",
                { "type ${it.typeName}, ${it.state}, ports ${it.ports.joinToString { port -> port.name }}" },
            ) {
                owner.reads.snapshot(name)
            }

        override suspend fun node(): ComponentNode = owner.reads.node(name)
    }
}

/** What a condition reads of the system and the coordinator: the live ones, or a model of them at one event. */
internal interface SystemReads {
    /** The state of [component] in its default context; null while the system has no such component. */
    suspend fun state(component: String): LifeCycle?

    suspend fun exists(component: String): Boolean

    suspend fun snapshot(component: String): ComponentSnapshot

    suspend fun node(component: String): ComponentNode

    /** The instance names of the system's components. */
    suspend fun names(): Set<String>

    fun modeOf(machine: String): String?

    val log: List<String>
}
