package org.rtcoord

/** A name server address: [normalised] `host:port`, and as the user [written] it, for display. */
internal class NameServerAddress(val normalised: String, val written: String)

/** What [PathParser] reads of a path's text: the fields of an [RtcPath], which only that class makes. */
internal class PathParts(
    val address: NameServerAddress?,
    val names: List<String>,
    val port: String?,
    val objectReference: String?,
    val isDirectory: Boolean,
) {
    companion object {
        val ROOT = PathParts(null, emptyList(), null, null, true)
    }
}

/** The text forms of [RtcPath], described on that class. */
internal object PathParser {
    private const val DEFAULT_PORT = 2809
    private const val CORBALOC = "corbaloc:"
    private const val NAME_SERVICE = "NameService"
    private val IIOP_VERSION = Regex("""^\d+\.\d+@""")

    fun parse(text: String, workingDirectory: RtcPath?): PathParts {
        require(
            workingDirectory == null || (workingDirectory.objectReference == null && workingDirectory.port == null)
        ) {
            "working directory $workingDirectory is not a node of the tree"
        }
        if (text.isEmpty()) throw BadPathException(text, 0, "empty path")
        // rtctree writes a name server address that holds a '/' below the root, then '#': accept that slash.
        val corbaloc = text.removePrefix("/")
        return when {
            text == "/" -> PathParts.ROOT
            corbaloc.startsWith(CORBALOC, ignoreCase = true) -> parseCorbaloc(text, corbaloc)
            text.startsWith('/') -> walk(text, PathParts.ROOT, corbaloc, 0)
            workingDirectory == null -> throw BadPathException(text, 0, "relative path without a working directory")
            else -> walk(text, PathParts(workingDirectory.address, workingDirectory.names, null, null, true), text, 0)
        }
    }

    /**
     * The name server at [address] (`host`, `host:port` or `corbaloc:iiop:host:port[/NameService]`) as the text of its
     * path, `/host[:port]` as written.
     */
    fun nameServer(address: String): String {
        val server =
            when {
                address.startsWith(CORBALOC, ignoreCase = true) ->
                    parseCorbaloc(address, if ('/' in address) address else "$address/$NAME_SERVICE")
                        .takeIf { it.names.isEmpty() }
                        ?.address
                '/' in address -> null
                else -> address(address, 0, address)
            }
        return "/" + (server ?: throw BadPathException(address, 0, "not a name server address")).written
    }

    /** Parses `host[:port]`, the segment at [position] of [subject]. */
    fun address(subject: String, position: Int, written: String): NameServerAddress {
        if (written.isEmpty()) throw BadPathException(subject, position, "empty name server address")
        val host = written.substringBefore(':')
        if (host.isEmpty()) throw BadPathException(subject, position, "empty host in '$written'")
        val port = if (':' in written) portNumber(subject, position, written.substringAfter(':')) else DEFAULT_PORT
        return NameServerAddress("$host:$port", written)
    }

    fun checkName(subject: String, position: Int, name: String) {
        val problem =
            when {
                name.isEmpty() -> "empty name"
                name == "." || name == ".." -> "'$name' is not a name"
                '/' in name -> "'/' in a name"
                ':' in name -> "':' in a name"
                else -> return
            }
        throw BadPathException(subject, position, problem)
    }

    fun checkPort(subject: String, position: Int, port: String) {
        val problem =
            when {
                port.isEmpty() -> "empty port name"
                '/' in port || ':' in port -> "bad port name '$port'"
                else -> return
            }
        throw BadPathException(subject, position, problem)
    }

    private fun portNumber(subject: String, position: Int, port: String): Int =
        port.takeIf { it.isNotEmpty() && it.all { c -> c in '0'..'9' } }?.toIntOrNull()?.takeIf { it in 1..65535 }
            ?: throw BadPathException(subject, position, "bad port '$port'")

    /** [corbaloc] is [subject] without the leading slash rtctree may add. */
    private fun parseCorbaloc(subject: String, corbaloc: String): PathParts {
        val reference = corbaloc.substringBefore('#')
        val addresses = reference.substring(CORBALOC.length).substringBefore('/')
        val key = reference.substringAfter('/', "")
        if (key.isEmpty()) throw BadPathException(subject, 0, "corbaloc without an object key")
        val server = if (key == NAME_SERVICE) iiopAddress(subject, addresses) else null
        val continuation = corbaloc.substringAfter('#', "").takeIf { '#' in corbaloc }
        return when {
            server != null && continuation != null ->
                walk(subject, PathParts(server, emptyList(), null, null, false), continuation, 1)
            server != null -> PathParts(server, emptyList(), null, null, false)
            continuation != null ->
                throw BadPathException(subject, 0, "'#' follows only a corbaloc:iiop:host:port/NameService")
            else -> PathParts(null, emptyList(), null, reference, false)
        }
    }

    /** The one IIOP address of a corbaloc address list, or null for other protocols or several addresses. */
    private fun iiopAddress(subject: String, addresses: String): NameServerAddress? {
        val protocol =
            when {
                ',' in addresses -> return null
                addresses.startsWith("iiop:", ignoreCase = true) -> "iiop:".length
                addresses.startsWith(":") -> 1
                else -> return null
            }
        return address(subject, 0, addresses.substring(protocol).replaceFirst(IIOP_VERSION, ""))
    }

    /**
     * Applies the `/`-separated segments of [body], numbered from [first] in messages, to [base]. The first segment
     * below the root is a name server address.
     */
    private fun walk(subject: String, base: PathParts, body: String, first: Int): PathParts {
        val directory = body.endsWith('/')
        val segments = body.removeSuffix("/").split('/')
        var server = base.address
        val names = base.names.toMutableList()
        var port: String? = null
        segments.forEachIndexed { i, segment ->
            val position = first + i
            when {
                segment.isEmpty() -> throw BadPathException(subject, position, "empty segment")
                segment == "." -> Unit
                segment == ".." ->
                    when {
                        names.isNotEmpty() -> names.removeAt(names.lastIndex)
                        server != null -> server = null
                        else -> throw BadPathException(subject, position, "'..' above the root")
                    }
                server == null -> server = address(subject, position, segment)
                ':' !in segment -> names += segment.also { checkName(subject, position, it) }
                i != segments.lastIndex ->
                    throw BadPathException(subject, position, "port suffix only on the last segment")
                directory -> throw BadPathException(subject, position, "port suffix on a directory")
                else -> {
                    names += segment.substringBefore(':').also { checkName(subject, position, it) }
                    port = segment.substringAfter(':').also { checkPort(subject, position, it) }
                }
            }
        }
        val isDirectory = directory || segments.last() == "." || segments.last() == ".."
        return server?.let { PathParts(it, names, port, null, isDirectory) } ?: PathParts.ROOT
    }
}
