package org.rtcoord

import OpenRTM.DataFlowComponentHelper
import RTM.ManagerHelper
import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.channels.awaitClose
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.callbackFlow
import kotlinx.coroutines.flow.flow
import org.rtcoord.internal.ComponentObject
import org.rtcoord.internal.NameServerIdentity
import org.rtcoord.internal.TreeCore
import org.rtcoord.internal.componentsFound
import org.rtcoord.internal.events.AfterSnapshot
import org.rtcoord.internal.logs.logInputAddress

/**
 * A live tree of an RT system, as rtctree-erl built it for the paper: the root, name servers, naming contexts, managers
 * and components, each node caching what it last read and re-reading on refresh.
 *
 * Discovery is concurrent and bounded by [TreeConfig.concurrency]; every remote call has a deadline; a dead, hung or
 * unreachable object becomes a [ZombieNode] without holding up the rest. Close the tree to release its ORB (unless the
 * host application supplied it). Java callers use it through [org.rtcoord.java.JavaTree].
 *
 * `RtcTree(config)` makes a tree configured by [config]; `RtcTree()` one with the defaults, whose name servers are
 * added later ([addNameServer]).
 */
public class RtcTree
@JvmOverloads
constructor(
    /** How the tree talks to the system. */
    public val config: TreeConfig = TreeConfig()
) : AutoCloseable {
    @get:JvmSynthetic internal val core = TreeCore(config) { ArrayList(servers) }
    // Read through copies: toList() and firstOrNull() read the size, then the elements, and a name server
    // removed in between fails them.
    private val servers = CopyOnWriteArrayList<NameServerNode>()

    /** The root node; its children are the name servers. */
    public val root: RootNode = RootNodeImpl(core) { ArrayList(servers) }

    init {
        config.nameServers.forEach(::addNameServer)
    }

    /**
     * How many poll ticks the tree missed since it was created: reads due at the periods asked for that it could not
     * make in time. When it cannot keep up, it reads every polled component at the same, lower rate (and logs that rate
     * once), so the missed ticks are spread evenly over the components.
     */
    public val missedPollTicks: Long
        get() = core.missedPollTicks.get()

    /** The name servers, in the order they were added. */
    public val nameServers: List<NameServerNode>
        get() = ArrayList(servers)

    /**
     * Adds a name server (`host`, `host:port` or `corbaloc:`), or returns it if the tree has it already, under this
     * spelling or another that reaches the same server (`localhost:2810` and `127.0.0.1:2810`): one name server is one
     * node, named as first given.
     */
    public fun addNameServer(address: String): NameServerNode {
        val path = nameServerPath(address)
        synchronized(servers) {
            known(path)?.let {
                return it
            }
            return NameServerNodeImpl(path, core).also {
                servers += it
                root.showSettled()
            }
        }
    }

    /** Removes the name server at [address] (or another spelling of it); returns whether the tree had it. */
    public fun removeNameServer(address: String): Boolean {
        val path = nameServerPath(address)
        synchronized(servers) {
            val server = known(path) ?: return false
            return servers.remove(server).also { root.showSettled() }
        }
    }

    /** The node of the name server at [path], under that spelling or another. */
    private fun known(path: RtcPath): NameServerNode? =
        servers.firstOrNull { it.path == path }
            ?: servers.firstOrNull { NameServerIdentity.same(it.path.nameServer!!, path.nameServer!!) }

    /**
     * The node at [path] (absolute, or relative to [workingDirectory]). A name server named in an absolute path is
     * added if the tree does not have it yet. Reads only what the path needs.
     */
    @JvmSynthetic
    public suspend fun node(path: String, workingDirectory: RtcPath? = null): Node =
        node(RtcPath(path, workingDirectory))

    /** The node at [path]; a port suffix is ignored (see [port]). */
    @JvmSynthetic
    public suspend fun node(path: RtcPath): Node {
        path.objectReference?.let {
            return objectNode(path, it)
        }
        if (path.isRoot) return root
        var node: Node = addNameServer(path.nameServer!!)
        for (name in path.names) {
            val directory =
                node as? DirectoryNode ?: throw WrongKindException(node.path.toString(), "directory", node.kind.label())
            node = directory.child(name) ?: throw NotFoundException(directory.path.child(name).toString())
        }
        return node
    }

    /** The component at [path]; fails if something else (or a dead registration) is there. */
    @JvmSynthetic
    public suspend fun component(path: String, workingDirectory: RtcPath? = null): ComponentNode =
        when (val node = node(path, workingDirectory)) {
            is ComponentNode -> node
            is ZombieNode -> throw node.cause
            else -> throw WrongKindException(node.path.toString(), "component", node.kind.label())
        }

    /**
     * The component named [name] (`laser0.rtc`, or `laser0`), wherever it is registered on the tree's name servers. One
     * component reachable by several paths (its naming context, below its manager) is one component; several different
     * ones are an [AmbiguousNameException] listing them.
     */
    @JvmSynthetic
    public suspend fun componentNamed(name: String): ComponentNode {
        val wanted = if ('.' in name) name else "$name.rtc"
        // At its naming path, where users look for a component, not below its manager.
        suspend fun search() = componentsFound(listOf(root)) { it.name == wanted }
        val distinct =
            search().ifEmpty {
                refresh(depth = Int.MAX_VALUE)
                search()
            }
        return when (distinct.size) {
            0 -> throw notFound(name)
            1 -> distinct.single()
            else -> throw AmbiguousNameException(name, distinct.map { it.path.toString() })
        }
    }

    /**
     * Why [name] was not found: no such component on the name servers that answered, or, when none answered, the first
     * one's failure; only a name server that answered can say a component is not there.
     */
    private suspend fun notFound(name: String): RtcException {
        val servers = nameServers.ifEmpty {
            return NotFoundException(name, "no such component on any name server (none configured)")
        }
        val failures = servers.mapNotNull { server ->
            try {
                server.relist()
                null
            } catch (e: RtcException) {
                server to e
            }
        }
        val answered = servers - failures.map { it.first }.toSet()
        if (answered.isEmpty()) return failures.first().second
        val silent = failures.joinToString { (server, e) -> "${server.address} did not answer (${e.reason})" }
        return NotFoundException(
            name,
            "no such component on ${answered.joinToString { it.address }}" + if (silent.isEmpty()) "" else "; $silent",
        )
    }

    /** The manager at [path]. */
    @JvmSynthetic
    public suspend fun manager(path: String, workingDirectory: RtcPath? = null): ManagerNode =
        when (val node = node(path, workingDirectory)) {
            is ManagerNode -> node
            is ZombieNode -> throw node.cause
            else -> throw WrongKindException(node.path.toString(), "manager", node.kind.label())
        }

    /** The port at `component.rtc:port`. */
    @JvmSynthetic
    public suspend fun port(path: String, workingDirectory: RtcPath? = null): Port {
        val parsed = RtcPath(path, workingDirectory)
        val port = parsed.port ?: throw BadPathException(path, parsed.names.size, "no port given (component.rtc:port)")
        return component(parsed.withPort(null).toString()).port(port)
    }

    /** Connects the ports at [from] and [to] (see [Port.connect]). */
    @JvmSynthetic
    public suspend fun connect(
        from: String,
        to: String,
        properties: Map<String, String> = emptyMap(),
        name: String? = null,
        workingDirectory: RtcPath? = null,
    ): ConnectorSnapshot = port(from, workingDirectory).connect(listOf(port(to, workingDirectory)), properties, name)

    /** Reads the subtree at [path] again, [depth] levels deep (the whole of it by default), concurrently. */
    @JvmSynthetic
    public suspend fun refresh(path: RtcPath = RtcPath("/"), depth: Int = Int.MAX_VALUE) {
        node(path).refresh(depth)
    }

    /**
     * Every node below [from] (included) for which [predicate] holds, in depth-first order, listing directories as the
     * walk reaches them. Unreachable branches are skipped. A component is found once: where it is bound in naming;
     * below a manager (an alias) only when its naming path is not found.
     */
    @JvmSynthetic
    public fun find(from: RtcPath = RtcPath("/"), predicate: suspend (Node) -> Boolean = { true }): Flow<Node> =
        find(from, Int.MAX_VALUE, predicate)

    /** As [find], going at most [maxDepth] levels below [from] ([from] is level 0), as rtfind's `-m`. */
    @JvmSynthetic
    public fun find(from: RtcPath, maxDepth: Int, predicate: suspend (Node) -> Boolean): Flow<Node> = flow {
        val found = HashSet<ComponentObject>()
        // Aliases wait until the walk is over: the naming path of their component may come later.
        val aliases = ArrayList<ComponentNode>()
        suspend fun walk(node: Node, depth: Int) {
            when {
                node is ComponentNode && node.path.isAlias -> aliases += node
                predicate(node) -> {
                    if (node is ComponentNode) found += node.component
                    emit(node)
                }
            }
            if (node is DirectoryNode && depth < maxDepth) {
                val children =
                    try {
                        node.children()
                    } catch (e: RtcException) {
                        emptyList()
                    }
                children.forEach { walk(it, depth + 1) }
            }
        }
        walk(node(from), 0)
        for (alias in aliases) if (alias.component !in found && predicate(alias))
            emit(alias).also { found += alias.component }
    }

    /**
     * Calls [handler] with every event of [type] from the node at [path]: a component's own events, or for a naming
     * context or manager its listing's events and those of every component below it, including components that appear
     * later. Handlers run in the tree's scope, never on the source node's update path, so they may operate on the node
     * that triggered them; what a handler throws goes to [TreeConfig.listenerFailures], and it keeps receiving events.
     * Cancel the returned [Subscription] to stop.
     */
    @JvmSynthetic
    public suspend fun <E : RtcEvent> on(
        path: String,
        type: Class<E>,
        options: EventOptions = EventOptions(),
        handler: suspend (E) -> Unit,
    ): Subscription = on(node(path), type, options, handler)

    /** [on] for a node already at hand. */
    @JvmSynthetic
    @Suppress("UNCHECKED_CAST")
    public suspend fun <E : RtcEvent> on(
        node: Node,
        type: Class<E>,
        options: EventOptions = EventOptions(),
        handler: suspend (E) -> Unit,
    ): Subscription =
        // Passed as it is, so that what it throws is reported as its own: the watcher delivers only events of [type].
        core.watcher.watch(node, setOf(type), options, handler as suspend (RtcEvent) -> Unit)

    /**
     * [on] for the events of any of [types] from [node]: one registration for what would take several, which reads the
     * node only for what [types] need.
     */
    @JvmSynthetic
    public suspend fun on(
        node: Node,
        types: Set<Class<out RtcEvent>>,
        options: EventOptions = EventOptions(),
        handler: suspend (RtcEvent) -> Unit,
    ): Subscription = core.watcher.watch(node, types, options, handler)

    /** [on] with the event type as a type argument: `tree.on<StateChanged>(path) { ... }`. */
    @JvmSynthetic
    public suspend inline fun <reified E : RtcEvent> on(
        path: String,
        options: EventOptions = EventOptions(),
        noinline handler: suspend (E) -> Unit,
    ): Subscription = on(path, E::class.java, options, handler)

    /**
     * Calls [handler] with how the tree watches each component it watches for any registration, once when it starts and
     * again when that changes ([WatchMethodChanged]; a new handler first hears how each is watched now), and once with
     * each manager hosting watched components that stops answering ([ManagerDied]) or answers again
     * ([ManagerReturned]). A manager counts once the tree has listed it. Cancel the returned [Subscription] to stop.
     */
    @JvmSynthetic
    public fun onWatching(handler: suspend (RtcEvent) -> Unit): Subscription = core.watcher.report(handler)

    /**
     * Starts a log input on [address] (`host:port`; port 0 for any free one): a Fluentd forward input (Message,
     * Forward, PackedForward and CompressedPackedForward, acknowledged when a sender asks, heartbeats answered), to
     * which OpenRTM-aist's components send their log records (`logger.logstream.fluentd.output0.port` in a Python
     * component's `rtc.conf`, an `output` of C++'s `fluentbit_stream`). Each record becomes a [LogRecord] event from
     * the component that logged it, heard through [on] and [follow] as every event is. With [sharedKey], senders must
     * pass Fluentd's shared-key handshake: set one for anything beyond loopback. Closed with the tree.
     *
     * @throws java.io.IOException when it cannot listen there, naming the address.
     */
    public fun listenForLogs(address: String = DEFAULT_LOG_ADDRESS, sharedKey: String? = null): LogInput =
        core.logs.listen(logInputAddress(address), sharedKey, root)

    /**
     * The tree's model of the system now, read without a remote call: every component its listings found, once each at
     * its canonical path, with its states as the tree's events last told them, and the name servers and managers it
     * cannot reach. See [SystemSnapshot].
     */
    public fun snapshot(): SystemSnapshot = core.model.snapshot(root)

    /**
     * Subscribes to the events of [types] from each of [nodes] as [on] does, then hands [start] the model as it is once
     * every subscription is in place, and [handler] every event after it, none missed and none twice: what a view needs
     * to show the system and keep showing it true. [handler] is first called once [start] has returned. Cancel the
     * returned [Subscription] to stop.
     */
    @JvmSynthetic
    public suspend fun follow(
        nodes: List<Node>,
        types: Set<Class<out RtcEvent>>,
        options: EventOptions = EventOptions(),
        start: suspend (SystemSnapshot) -> Unit,
        handler: suspend (RtcEvent) -> Unit,
    ): Subscription {
        val begun = CompletableDeferred<Long>()
        val subscriptions = mutableListOf<Subscription>()
        val all = Subscription { subscriptions.forEach(Subscription::cancel) }
        try {
            val after = AfterSnapshot(begun, handler)
            nodes.forEach { node -> subscriptions += on(node, types, options, after) }
            val snapshot = snapshot()
            try {
                start(snapshot)
            } finally {
                begun.complete(snapshot.sequence)
            }
        } catch (e: Throwable) {
            all.cancel()
            throw e
        }
        return all
    }

    /** Every event from the node at [path] (see [on]) while the flow is collected. */
    @JvmSynthetic
    public fun events(path: String, options: EventOptions = EventOptions()): Flow<RtcEvent> = callbackFlow {
        val subscription = on(path, RtcEvent::class.java, options) { send(it) }
        awaitClose { subscription.cancel() }
    }

    /**
     * Detaches every observer the tree attached, stops its work and releases its ORB (unless the host application
     * supplied the ORB). Blocks while observers are detached, each within the call deadline. Idempotent.
     */
    override fun close() {
        core.close()
    }

    private suspend fun objectNode(path: RtcPath, corbaloc: String): Node {
        val target = core.orb.orb.string_to_object(corbaloc)
        return when {
            core.remote.call(corbaloc, "_is_a") { target._is_a("IDL:omg.org/RTC/RTObject:1.0") } ->
                ComponentNodeImpl(
                    path,
                    core,
                    core.components.objectFor(DataFlowComponentHelper.unchecked_narrow(target)),
                )
            core.remote.call(corbaloc, "_is_a") { target._is_a("IDL:RTM/Manager:1.0") } ->
                ManagerNodeImpl(path, core, ManagerHelper.unchecked_narrow(target), null)
            else -> UnknownNodeImpl(path, core, target)
        }
    }
}

@JvmSynthetic internal fun NodeKind.label(): String = name.lowercase().replace('_', ' ')
