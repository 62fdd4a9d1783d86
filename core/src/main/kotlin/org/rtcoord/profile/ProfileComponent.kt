package org.rtcoord.profile

import org.jspecify.annotations.Nullable

/** One component of a profile, found on the live system by its [pathUri]. */
public data class ProfileComponent(
    /** `RTC:vendor:category:type:version`. */
    val id: String,
    /** The name-server path without its leading slash: `host:port/ctx.host_cxt/comp0.rtc`. */
    val pathUri: String,
    val instanceName: String,
    /** The configuration set to activate; empty for none. */
    val activeConfigurationSet: String = "",
    /** `None`, `PeriodicECShared`, `PeriodicStateShared`, `Grouping`, `FsmECShared` or `FsmStateShared`. */
    val compositeType: String = "None",
    /** Whether restoring fails when the component is missing. */
    val isRequired: Boolean = false,
    val dataPorts: List<ProfilePort> = emptyList(),
    val servicePorts: List<ProfilePort> = emptyList(),
    val configurationSets: List<ConfigurationSet> = emptyList(),
    val executionContexts: List<ExecutionContext> = emptyList(),
    /** Members of a composite component. */
    val participants: List<TargetComponent> = emptyList(),
    val ext: Extension = Extension(),
) {
    /** The configuration set [id], or null. */
    public fun configurationSet(id: String): @Nullable ConfigurationSet? = configurationSets.firstOrNull { it.id == id }
}

/** A data or service port of a component, by its short name. */
public data class ProfilePort(val name: String, val ext: Extension = Extension())

/** A configuration set: its id and its parameters' values in file order. */
public data class ConfigurationSet(val id: String, val data: Map<String, String> = emptyMap(), val ext: Extension = Extension())

/** An execution context of a component: id (the component's handle), kind, rate in Hz, participants. */
public data class ExecutionContext(
    val id: String,
    val kind: String = "PERIODIC",
    val rate: @Nullable Double? = null,
    val participants: List<TargetComponent> = emptyList(),
    val ext: Extension = Extension(),
)
