package org.rtcoord.cli.json

import kotlinx.serialization.Serializable

/**
 * A component as `cat --json` and the live view's `GET /api/component` give it: its profile, its place among
 * composites, its state (a LifeCycle name) and FSM, its execution contexts, its ports and, when asked for, its
 * configuration (hidden sets left out).
 */
@Serializable
internal class ComponentReportJson
private constructor(
    val path: String,
    /** Always `component`. */
    val kind: String,
    val instanceName: String,
    val typeName: String,
    val version: String,
    val vendor: String,
    val category: String,
    val description: String,
    /** The composite it is a member of, when it is one. */
    val parent: String?,
    /** `Monolithic` or `Composite`, with ` composite member` when it is one. */
    val type: String,
    val state: String,
    val fsm: FsmJson? = null,
    val properties: Map<String, String>,
    val contexts: List<ContextJson>,
    val ports: List<PortJson>,
    val configuration: ConfigurationJson? = null,
) {
    constructor(
        path: String,
        instanceName: String,
        typeName: String,
        version: String,
        vendor: String,
        category: String,
        description: String,
        parent: String?,
        type: String,
        state: String,
        fsm: FsmJson?,
        properties: Map<String, String>,
        contexts: List<ContextJson>,
        ports: List<PortJson>,
        configuration: ConfigurationJson?,
    ) : this(
        path,
        "component",
        instanceName,
        typeName,
        version,
        vendor,
        category,
        description,
        parent,
        type,
        state,
        fsm,
        properties,
        contexts,
        ports,
        configuration,
    )
}

/**
 * One of a component's execution contexts: whether it owns it, its kind, rate (Hz), whether it runs, the component's
 * state in it.
 */
@Serializable
internal class ContextJson(
    val handle: Int,
    val owned: Boolean,
    val kind: String,
    @Serializable(with = FiniteDouble::class) val rate: Double,
    val running: Boolean,
    val state: String,
    /** How many components take part in it. */
    val participants: Int,
    val properties: Map<String, String>,
)
