@file:JvmName("RtcPaths")

package org.rtcoord

/**
 * The absolute path of a node of the RTC tree, optionally with a port of its last object, or a direct object reference:
 * `RtcPath("/host/ctx/laser0.rtc:laser")`, `RtcPath("/")` for the root.
 *
 * The tree is the root `/`, then name servers, then naming contexts (nested), then the objects bound in them:
 * components (`name.rtc`), managers (`name.mgr`) and others; below a manager come its slave managers and the components
 * it manages. The text forms its constructor reads:
 *
 * - `/host[:port]/ctx/.../name.kind[:port]`: the first segment is the name server address (port 2809 when absent), the
 *   others are names `id.kind` (the kind may be empty) made of any characters but `/` and `:`. Only the last segment
 *   may carry a `:port` suffix, naming a port of that object; the port name may contain dots. `/host:port` is the name
 *   server itself, `/` the root.
 * - A trailing slash marks a directory (see [isDirectory]) and names the same node.
 * - `.` and `..` are resolved; paths not starting with `/` are relative to a working directory.
 * - `corbaloc:iiop:host:port/NameService` is the name server `/host:port`, and
 *   `corbaloc:iiop:host:port/NameService#ctx/name.rtc:port` continues into it. Any other `corbaloc:` address is a
 *   direct object reference ([objectReference]) outside the tree.
 *
 * Instances are immutable. Equality, hashing and ordering follow the canonical text ([toString]); how the name server
 * address was written and [isDirectory] do not take part.
 */
public class RtcPath
private constructor(
    @get:JvmSynthetic internal val address: NameServerAddress?,
    names: List<String>,
    port: String?,
    objectReference: String?,
    isDirectory: Boolean,
) : Comparable<RtcPath> {
    /**
     * Reads [text] in one of the forms described above; a relative one resolves against [workingDirectory], a node of
     * the tree without a port.
     *
     * @throws BadPathException naming the offending segment when [text] does not follow the grammar or is relative
     *   without a working directory.
     */
    @JvmOverloads
    @Throws(BadPathException::class)
    public constructor(text: String, workingDirectory: RtcPath? = null) : this(PathParser.parse(text, workingDirectory))

    private constructor(
        parts: PathParts
    ) : this(parts.address, parts.names, parts.port, parts.objectReference, parts.isDirectory)

    /** The normalised `host:port` of the name server; null for the root and for object references. */
    public val nameServer: String? = address?.normalised

    /** The names after the name server, e.g. `["host.host_cxt", "laser0.rtc"]`; empty above them. */
    public val names: List<String> = names

    /** The port of the last object (the `:port` suffix), or null. */
    public val port: String? = port

    /** The `corbaloc:` address of a direct object reference, or null for a node of the tree. */
    public val objectReference: String? = objectReference

    /** Whether the text named a directory: a trailing slash, a final `.` or `..`, or the root. */
    public val isDirectory: Boolean = isDirectory

    /** Whether this is the root `/`. */
    public val isRoot: Boolean
        get() = address == null && objectReference == null

    /**
     * Whether the path reaches a component through a manager (`.mgr`) or an object reference: an alias, not where it is
     * bound in naming.
     */
    @get:JvmSynthetic
    internal val isAlias: Boolean
        get() = objectReference != null || names.any { it.endsWith(".mgr") }

    /**
     * The last name without its port; `/` for the root, the address as written for a name server (`localhost`, not
     * `localhost:2809`) and the whole `corbaloc:` text for an object reference.
     */
    public val name: String
        get() = names.lastOrNull() ?: address?.written ?: objectReference ?: "/"

    /** The kind of the last name: what follows its last dot (`rtc` for `a.b.rtc`), else empty. */
    public val kind: String
        get() = names.lastOrNull()?.substringAfterLast('.', "") ?: ""

    /**
     * The enclosing node: the component for a port path, the root for a name server; null for the root and for object
     * references.
     */
    public val parent: RtcPath?
        get() =
            when {
                isRoot || objectReference != null -> null
                port != null -> RtcPath(address, names, null, null, false)
                names.isEmpty() -> RtcPath(PathParts.ROOT)
                else -> RtcPath(address, names.dropLast(1), null, null, false)
            }

    private val text: String =
        objectReference
            ?: buildString {
                append('/')
                address?.let { append(it.normalised) }
                names.forEach { append('/').append(it) }
                port?.let { append(':').append(it) }
            }

    /**
     * The node [name] below this one: a name server address (`host[:port]`) below the root, else a name of a context or
     * object.
     *
     * @throws BadPathException if [name] is empty, `.` or `..`, contains `/`, or contains `:` below a name server
     *   (below the root, `:` starts the port of the address); or if this is a port path or an object reference.
     */
    @Throws(BadPathException::class)
    public fun child(name: String): RtcPath {
        val subject = text.removeSuffix("/") + "/" + name
        val position = if (isRoot) 0 else names.size + 1
        when {
            objectReference != null -> throw BadPathException(subject, position, "nothing below an object reference")
            port != null -> throw BadPathException(subject, position, "nothing below a port")
            address != null -> PathParser.checkName(subject, position, name)
            '/' in name || name == "." || name == ".." ->
                throw BadPathException(subject, position, "not a name server address")
            else -> return RtcPath(PathParser.address(subject, position, name), emptyList(), null, null, false)
        }
        return RtcPath(address, names + name, null, null, false)
    }

    /**
     * This object's port [port], or with null the object itself.
     *
     * @throws BadPathException if [port] is empty or contains `/` or `:`, or if this is not a named object (the root, a
     *   name server, an object reference).
     */
    @Throws(BadPathException::class)
    public fun withPort(port: String?): RtcPath {
        if (port == null) return if (this.port == null) this else RtcPath(address, names, null, null, false)
        val subject = "$text:$port"
        if (names.isEmpty()) throw BadPathException(subject, 0, "a port only on a named object")
        PathParser.checkPort(subject, names.size, port)
        return RtcPath(address, names, port, null, false)
    }

    /**
     * Whether [prefix] is this path or one of its ancestors. A component's port paths start with the component path;
     * every tree path starts with the root; an object reference only with itself.
     */
    public fun startsWith(prefix: RtcPath): Boolean =
        when {
            objectReference != null || prefix.objectReference != null -> this == prefix
            prefix.port != null -> this == prefix
            prefix.isRoot -> true
            else ->
                nameServer == prefix.nameServer &&
                    names.size >= prefix.names.size &&
                    names.subList(0, prefix.names.size) == prefix.names
        }

    /**
     * Tree order: the root, then each name server followed by everything below it (names compared one by one, a node
     * before its ports); object references last, by their text.
     */
    override fun compareTo(other: RtcPath): Int {
        if (objectReference != null || other.objectReference != null) {
            return compareValues(objectReference, other.objectReference)
        }
        val mine = listOfNotNull(nameServer) + names
        val theirs = listOfNotNull(other.nameServer) + other.names
        for (i in 0 until minOf(mine.size, theirs.size)) {
            val order = mine[i].compareTo(theirs[i])
            if (order != 0) return order
        }
        return mine.size.compareTo(theirs.size).takeIf { it != 0 } ?: compareValues(port, other.port)
    }

    override fun equals(other: Any?): Boolean = other is RtcPath && text == other.text

    override fun hashCode(): Int = text.hashCode()

    /**
     * The canonical text: absolute, name server normalised, no trailing slash, e.g.
     * `/127.0.0.1:2809/host.host_cxt/laser0.rtc:laser`; for an object reference its `corbaloc:` address.
     */
    override fun toString(): String = text
}

/**
 * The path of the name server at [address]: `host`, `host:port` or `corbaloc:iiop:host:port[/NameService]`, as
 * [TreeConfig.nameServers] takes it. Java: `RtcPaths.nameServerPath(address)`.
 *
 * @throws BadPathException naming [address] if it is none of these.
 */
@Throws(BadPathException::class)
public fun nameServerPath(address: String): RtcPath = RtcPath(PathParser.nameServer(address))
