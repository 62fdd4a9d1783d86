package org.rtcoord.sim.test

import kotlin.time.Duration

/**
 * One fault of the vocabulary on one [target] (a component's instance name, a manager's name, none for
 * [FaultKind.RESTART_NAMING]): what an explored schedule is made of, and what a found test writes.
 */
internal class Fault(val kind: FaultKind, val target: String?) {
    /** Applies the fault through [faults], as an `at(...) { }` step would. */
    fun applyTo(faults: Faults) {
        val name = target.orEmpty()
        when (kind) {
            FaultKind.FAIL -> faults.fail(name)
            FaultKind.BREAK_DOWN -> faults.breakDown(name)
            FaultKind.REPAIR -> faults.repair(name)
            FaultKind.FREEZE -> faults.freeze(name)
            FaultKind.HANG -> faults.hang(name)
            FaultKind.EXIT -> faults.exit(name)
            FaultKind.LOSE_CONNECTORS -> faults.loseConnectors(name)
            FaultKind.KILL_MANAGER -> faults.killManager(name)
            FaultKind.RESTART_NAMING -> faults.restartNaming()
        }
    }

    /** As a test writes it: `fail("laser0")`, `restartNaming()`. */
    val written: String
        get() = "${kind.word}(${target?.let { "\"$it\"" }.orEmpty()})"

    /** This fault on [other] instead. */
    fun on(other: String?): Fault = Fault(kind, other)

    override fun equals(other: Any?): Boolean = other is Fault && other.kind == kind && other.target == target

    override fun hashCode(): Int = kind.hashCode() * 31 + target.hashCode()

    /** `fail laser0`, as the timeline shows a fault. */
    override fun toString(): String = listOfNotNull(kind.word, target).joinToString(" ")
}

/** The kinds of [Fault], each with the word a test writes it with and what it is on. */
internal enum class FaultKind(val word: String, val on: On) {
    FAIL("fail", On.COMPONENT),
    BREAK_DOWN("breakDown", On.COMPONENT),
    REPAIR("repair", On.COMPONENT),
    FREEZE("freeze", On.COMPONENT),
    HANG("hang", On.COMPONENT),
    EXIT("exit", On.COMPONENT),
    LOSE_CONNECTORS("loseConnectors", On.COMPONENT),
    KILL_MANAGER("killManager", On.MANAGER),
    RESTART_NAMING("restartNaming", On.SYSTEM);

    /** What a fault of this kind is on. */
    enum class On {
        COMPONENT,
        MANAGER,
        SYSTEM,
    }

    /** Whether [repair][REPAIR] ends a fault of this kind. */
    val repairable: Boolean
        get() = this == BREAK_DOWN || this == FREEZE || this == HANG
}

/** A [fault] at [time] from the scenario's start. */
internal class ScheduledFault(val time: Duration, val fault: Fault) {
    /** As a test writes it: `at(1500.milliseconds) { fail("laser0") }`. */
    val written: String
        get() = "at(${kotlin(time)}) { ${fault.written} }"

    override fun equals(other: Any?): Boolean = other is ScheduledFault && other.time == time && other.fault == fault

    override fun hashCode(): Int = time.hashCode() * 31 + fault.hashCode()

    /** `1.500 s fail laser0`. */
    override fun toString(): String = "${TimelineEntry.seconds(time)} $fault"

    companion object {
        /** [time] as Kotlin writes it: `3.seconds`, `1500.milliseconds`. */
        fun kotlin(time: Duration): String {
            val ms = time.inWholeMilliseconds
            return if (ms % 1000 == 0L) "${ms / 1000}.seconds" else "$ms.milliseconds"
        }
    }
}
