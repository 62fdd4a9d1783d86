package org.rtcoord

/** Ready-made predicates for [RtcTree.find], in the spirit of rtfind; combine them with [and]. */
public object NodeFilters {
    /** Nodes of [kind]. */
    public fun kind(kind: NodeKind): suspend (Node) -> Boolean = { it.kind == kind }

    /** Nodes whose name matches the glob [pattern] (`*` any run of characters, `?` one character). */
    public fun name(pattern: String): suspend (Node) -> Boolean {
        val regex = glob(pattern)
        return { regex.matches(it.name) }
    }

    /** The glob [pattern] (`*` any run of characters, `?` one character) as a regular expression of whole names. */
    public fun glob(pattern: String): Regex =
        Regex(pattern.split('*').joinToString(".*") { part -> part.split('?').joinToString(".") { Regex.escape(it) } })

    /** Components in [state] in their default context. */
    public fun state(state: LifeCycle): suspend (Node) -> Boolean = {
        it is ComponentNode && it.snapshot().state == state
    }

    /** Components with a port named [port], of data type [dataType] when given (full id or short name). */
    public fun hasPort(port: String, dataType: String? = null): suspend (Node) -> Boolean = { node ->
        val found = (node as? ComponentNode)?.snapshot()?.port(port)
        found != null && (dataType == null || found.dataType == dataType || found.dataType == "IDL:RTC/$dataType:1.0")
    }

    /** Nodes at or below [prefix]. */
    public fun under(prefix: RtcPath): suspend (Node) -> Boolean = { it.path.startsWith(prefix) }

    /** Both predicates. */
    public infix fun (suspend (Node) -> Boolean).and(other: suspend (Node) -> Boolean): suspend (Node) -> Boolean = {
        this(it) && other(it)
    }
}
