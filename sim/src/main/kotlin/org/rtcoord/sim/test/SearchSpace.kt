package org.rtcoord.sim.test

import kotlin.time.Duration

/**
 * What `rtcoord test --explore` may draw faults from, as a test's `explore { }` narrows it: by default every fault of
 * the vocabulary on every component and manager of the system, at moments within each scenario's time, in every
 * scenario. Each word narrows it further; written twice, the second replaces the first (but [exclude]s add up).
 */
@TestDsl
public class SearchSpace internal constructor() {
    internal var scenarios: List<String>? = null
    internal var components: List<String>? = null
    internal var managers: List<String>? = null
    internal val only = mutableListOf<FaultPattern>()
    internal val excluded = mutableListOf<FaultPattern>()
    internal var window: ClosedRange<Duration>? = null

    /** Only these scenarios (by name) are explored. */
    public fun scenarios(vararg names: String) {
        scenarios = names.toList()
    }

    /** Faults on components only on these (`laser0` or `laser0.rtc`); they may be ones the coordinator creates. */
    public fun components(vararg names: String) {
        components = names.map { it.removeSuffix(".rtc") }
    }

    /** `killManager` only on these managers (a slave's name, or the master's). */
    public fun managers(vararg names: String) {
        managers = names.toList()
    }

    /** Only the faults [patterns] names are drawn: `faults { fail(); breakDown("laser0") }`. */
    public fun faults(patterns: FaultPatterns.() -> Unit) {
        only += FaultPatterns().apply(patterns).patterns
    }

    /** The faults [patterns] names are out of scope, never drawn: `exclude { killManager() }`. */
    public fun exclude(patterns: FaultPatterns.() -> Unit) {
        excluded += FaultPatterns().apply(patterns).patterns
    }

    /** Faults are drawn at moments from [from] to [to] after the coordinator's start. */
    public fun window(from: Duration, to: Duration) {
        require(!from.isNegative() && to > from) {
            "window($from, $to): give a start at or after 0 and an end after it"
        }
        window = from..to
    }
}

/**
 * Faults named by kind, each on one target or (with none given) on any: the words of `faults { }` and `exclude { }` in
 * a test's `explore { }`.
 */
@TestDsl
public class FaultPatterns internal constructor() {
    internal val patterns = mutableListOf<FaultPattern>()

    private fun add(kind: FaultKind, target: String?) {
        patterns += FaultPattern(kind, target?.removeSuffix(".rtc"))
    }

    /** `fail` on [component], or on any when null. */
    public fun fail(component: String? = null): Unit = add(FaultKind.FAIL, component)

    /** `breakDown` on [component], or on any when null. */
    public fun breakDown(component: String? = null): Unit = add(FaultKind.BREAK_DOWN, component)

    /** `repair` of [component], or of any when null. */
    public fun repair(component: String? = null): Unit = add(FaultKind.REPAIR, component)

    /** `freeze` of [component], or of any when null. */
    public fun freeze(component: String? = null): Unit = add(FaultKind.FREEZE, component)

    /** `hang` of [component], or of any when null. */
    public fun hang(component: String? = null): Unit = add(FaultKind.HANG, component)

    /** `exit` of [component], or of any when null. */
    public fun exit(component: String? = null): Unit = add(FaultKind.EXIT, component)

    /** `loseConnectors` of [component], or of any when null. */
    public fun loseConnectors(component: String? = null): Unit = add(FaultKind.LOSE_CONNECTORS, component)

    /** `killManager` of the manager [name], or of any (the master and every slave) when null. */
    public fun killManager(name: String? = null): Unit = add(FaultKind.KILL_MANAGER, name)

    /** `restartNaming`. */
    public fun restartNaming(): Unit = add(FaultKind.RESTART_NAMING, null)
}

/** A fault of [kind] on [target], or on any target when it is null. */
internal class FaultPattern(val kind: FaultKind, val target: String?) {
    fun matches(fault: Fault): Boolean = fault.kind == kind && (target == null || target == fault.target)
}
