package org.rtcoord.dsl

/**
 * Which components a supervisor restarts when one of them fails, as Erlang/OTP supervisors do. The others it restarts
 * are stopped (deactivated) in reverse declared order first, then every one is started again in declared order, the
 * failed one recovered in its turn.
 */
public enum class Strategy(private val text: String) {
    /** Only the failed component. */
    ONE_FOR_ONE("oneForOne"),

    /** Every supervised component. */
    ONE_FOR_ALL("oneForAll"),

    /** The failed component and those declared after it: they depend on it. */
    REST_FOR_ONE("restForOne");

    /** The name a script writes. */
    override fun toString(): String = text
}
