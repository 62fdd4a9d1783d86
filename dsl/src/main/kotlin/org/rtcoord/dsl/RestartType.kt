package org.rtcoord.dsl

/** When a supervised component is restarted, as Erlang/OTP's child restart types say. */
public enum class RestartType(private val text: String) {
    /** Always: after a failure and after it exited by itself. */
    PERMANENT("permanent"),

    /** Only after a failure (ERROR, lost, killed), not after it exited by itself. */
    TRANSIENT("transient"),

    /** Never: when it fails or exits, the supervisor lets it go and stops watching it. */
    TEMPORARY("temporary");

    /** The name a script writes. */
    override fun toString(): String = text
}
