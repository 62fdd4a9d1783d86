package org.rtcoord.profile

import org.jspecify.annotations.Nullable
import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields

/** One component of a profile, found on the live system by its [pathUri]. */
public class ProfileComponent
@JvmOverloads
constructor(
    /** `RTC:vendor:category:type:version`. */
    public val id: String,
    /** The name-server path without its leading slash: `host:port/ctx.host_cxt/comp0.rtc`. */
    public val pathUri: String,
    public val instanceName: String,
    /** The configuration set to activate; empty for none. */
    public val activeConfigurationSet: String = "",
    /** `None`, `PeriodicECShared`, `PeriodicStateShared`, `Grouping`, `FsmECShared` or `FsmStateShared`. */
    public val compositeType: String = "None",
    /** Whether restoring fails when the component is missing. */
    public val isRequired: Boolean = false,
    public val dataPorts: List<ProfilePort> = emptyList(),
    public val servicePorts: List<ProfilePort> = emptyList(),
    public val configurationSets: List<ConfigurationSet> = emptyList(),
    public val executionContexts: List<ExecutionContext> = emptyList(),
    /** Members of a composite component. */
    public val participants: List<TargetComponent> = emptyList(),
    public val ext: Extension = Extension(),
) : ValueObject() {
    /** The configuration set [id], or null. */
    public fun configurationSet(id: String): @Nullable ConfigurationSet? = configurationSets.firstOrNull { it.id == id }

    /** This component under another component [id] (`RTC:vendor:category:type:version`). */
    public fun withId(id: String): ProfileComponent = copy(id = id)

    /** This component as another instance, [instanceName], found at [pathUri]. */
    public fun withInstance(instanceName: String, pathUri: String): ProfileComponent =
        copy(instanceName = instanceName, pathUri = pathUri)

    /** This component with [configurationSets] instead of its own. */
    public fun withConfigurationSets(configurationSets: List<ConfigurationSet>): ProfileComponent =
        copy(configurationSets = configurationSets)

    /** This component with another [ext]. */
    public fun withExt(ext: Extension): ProfileComponent = copy(ext = ext)

    private fun copy(
        id: String = this.id,
        pathUri: String = this.pathUri,
        instanceName: String = this.instanceName,
        configurationSets: List<ConfigurationSet> = this.configurationSets,
        ext: Extension = this.ext,
    ) =
        ProfileComponent(
            id,
            pathUri,
            instanceName,
            activeConfigurationSet,
            compositeType,
            isRequired,
            dataPorts,
            servicePorts,
            configurationSets,
            executionContexts,
            participants,
            ext,
        )

    override fun fields(): ValueFields =
        ValueFields(
            "id" to id,
            "pathUri" to pathUri,
            "instanceName" to instanceName,
            "activeConfigurationSet" to activeConfigurationSet,
            "compositeType" to compositeType,
            "isRequired" to isRequired,
            "dataPorts" to dataPorts,
            "servicePorts" to servicePorts,
            "configurationSets" to configurationSets,
            "executionContexts" to executionContexts,
            "participants" to participants,
            "ext" to ext,
        )
}

/** A data or service port of a component, by its short name. */
public class ProfilePort @JvmOverloads constructor(public val name: String, public val ext: Extension = Extension()) :
    ValueObject() {
    override fun fields(): ValueFields = ValueFields("name" to name, "ext" to ext)
}

/** A configuration set: its id and its parameters' values in file order. */
public class ConfigurationSet
@JvmOverloads
constructor(
    public val id: String,
    public val data: Map<String, String> = emptyMap(),
    public val ext: Extension = Extension(),
) : ValueObject() {
    /** This set with [data] as its parameters' values. */
    public fun withData(data: Map<String, String>): ConfigurationSet = ConfigurationSet(id, data, ext)

    override fun fields(): ValueFields = ValueFields("id" to id, "data" to data, "ext" to ext)
}

/** An execution context of a component: id (the component's handle), kind, rate in Hz, participants. */
public class ExecutionContext
@JvmOverloads
constructor(
    public val id: String,
    public val kind: String = "PERIODIC",
    public val rate: @Nullable Double? = null,
    public val participants: List<TargetComponent> = emptyList(),
    public val ext: Extension = Extension(),
) : ValueObject() {
    override fun fields(): ValueFields =
        ValueFields("id" to id, "kind" to kind, "rate" to rate, "participants" to participants, "ext" to ext)
}
