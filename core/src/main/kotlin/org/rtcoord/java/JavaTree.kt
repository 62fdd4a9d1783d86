package org.rtcoord.java

import java.util.concurrent.CompletableFuture
import java.util.concurrent.Executor
import java.util.function.Consumer
import java.util.function.Predicate
import kotlinx.coroutines.flow.toList
import org.jspecify.annotations.Nullable
import org.rtcoord.ConnectorSnapshot
import org.rtcoord.DEFAULT_LOG_ADDRESS
import org.rtcoord.DirectoryNode
import org.rtcoord.EventListener
import org.rtcoord.EventOptions
import org.rtcoord.LogInput
import org.rtcoord.LogRecord
import org.rtcoord.NameServerNode
import org.rtcoord.NamingDirectory
import org.rtcoord.RootNode
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.Subscription
import org.rtcoord.SystemSnapshot
import org.rtcoord.TreeConfig
import org.rtcoord.WrongKindException
import org.rtcoord.internal.JavaCalls
import org.rtcoord.internal.JavaListenerCall
import org.rtcoord.internal.runTask
import org.rtcoord.label

/**
 * An [RtcTree] for Java callers: every operation as a blocking call (which throws the [RtcException] the operation
 * failed with) and as a [CompletableFuture] (`...Async`), paths as strings, events delivered on an [Executor] the
 * caller chooses. Nodes come back as [JavaNode]s; operate on them through [JavaComponent], [JavaManager] and
 * [JavaPort]. Closing it closes the tree, and ends its threads. `new JavaTree(tree)` drives a tree Kotlin code made,
 * and closes it with the facade.
 *
 * ```java
 * try (JavaTree tree = new JavaTree(new TreeConfig(List.of("127.0.0.1:2809")))) {
 *     JavaComponent laser = tree.component("/127.0.0.1:2809/host.host_cxt/laser0.rtc");
 *     laser.deactivate();
 * }
 * ```
 */
public class JavaTree(
    /** The tree this facade drives; Kotlin code shares it with the suspend API. */
    @get:JvmSynthetic public val tree: RtcTree
) : AutoCloseable {
    /** A tree configured by [config] (the defaults unless given), with its facade. */
    @JvmOverloads public constructor(config: TreeConfig = TreeConfig()) : this(RtcTree(config))

    /** How the tree talks to the system. */
    public val config: TreeConfig
        get() = tree.config

    private val calls = JavaCalls(tree.core.scope)

    /**
     * The node at [path] (absolute; a name server it names is added).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun node(path: String): JavaNode = calls.await { JavaNode(tree.node(path)) }

    /** [node], when done; it fails with what [node] throws. */
    public fun nodeAsync(path: String): CompletableFuture<JavaNode> = calls.future { JavaNode(tree.node(path)) }

    /**
     * The children of the naming context, name server, manager or root at [path], listed now if they never were.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun children(path: String): List<JavaNode> = calls.await { directory(path).children().map(::JavaNode) }

    /** [children], when done; it fails with what [children] throws. */
    public fun childrenAsync(path: String): CompletableFuture<List<JavaNode>> = calls.future {
        directory(path).children().map(::JavaNode)
    }

    /**
     * The component at [path].
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun component(path: String): JavaComponent = calls.await { JavaComponent(tree.component(path)) }

    /** [component], when done; it fails with what [component] throws. */
    public fun componentAsync(path: String): CompletableFuture<JavaComponent> = calls.future {
        JavaComponent(tree.component(path))
    }

    /**
     * The component named [name] (`laser0.rtc` or `laser0`) wherever it is registered (see [RtcTree.componentNamed]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun componentNamed(name: String): JavaComponent = calls.await { JavaComponent(tree.componentNamed(name)) }

    /** [componentNamed], when done; it fails with what [componentNamed] throws. */
    public fun componentNamedAsync(name: String): CompletableFuture<JavaComponent> = calls.future {
        JavaComponent(tree.componentNamed(name))
    }

    /**
     * The manager at [path].
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun manager(path: String): JavaManager = calls.await { JavaManager(tree.manager(path)) }

    /** [manager], when done; it fails with what [manager] throws. */
    public fun managerAsync(path: String): CompletableFuture<JavaManager> = calls.future {
        JavaManager(tree.manager(path))
    }

    /**
     * The port at `component.rtc:port`.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun port(path: String): JavaPort = calls.await { JavaPort(tree.port(path)) }

    /** [port], when done; it fails with what [port] throws. */
    public fun portAsync(path: String): CompletableFuture<JavaPort> = calls.future { JavaPort(tree.port(path)) }

    /**
     * Connects the ports at [from] and [to] with connector [properties] (see [RtcTree.connect]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun connect(from: String, to: String, properties: Map<String, String> = emptyMap()): ConnectorSnapshot =
        calls.await {
            tree.connect(from, to, properties)
        }

    /** [connect], when done; it fails with what [connect] throws. */
    @JvmOverloads
    public fun connectAsync(
        from: String,
        to: String,
        properties: Map<String, String> = emptyMap(),
    ): CompletableFuture<ConnectorSnapshot> = calls.future { tree.connect(from, to, properties) }

    /**
     * Reads the naming context, name server, manager or root at [path] and everything below it down to [depth] levels,
     * concurrently (see [DirectoryNode.survey]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun survey(path: String, depth: Int = Int.MAX_VALUE): Unit = calls.await { directory(path).survey(depth) }

    /** [survey], when done; it fails with what [survey] throws. */
    @JvmOverloads
    public fun surveyAsync(path: String, depth: Int = Int.MAX_VALUE): CompletableFuture<Void?> = calls.done {
        directory(path).survey(depth)
    }

    /**
     * Removes the binding at [path] from its naming context, whatever it is bound to, dead or alive (as `rtdel`).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun unbind(path: String): Unit = calls.await { unbindAt(path) }

    /** [unbind], when done; it fails with what [unbind] throws. */
    public fun unbindAsync(path: String): CompletableFuture<Void?> = calls.done { unbindAt(path) }

    /**
     * Reads the subtree at [path] again, [depth] levels deep (the whole of it by default).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun refresh(path: String, depth: Int = Int.MAX_VALUE): Unit = calls.await {
        tree.refresh(RtcPath(path), depth)
    }

    /** [refresh], when done; it fails with what [refresh] throws. */
    @JvmOverloads
    public fun refreshAsync(path: String, depth: Int = Int.MAX_VALUE): CompletableFuture<Void?> = calls.done {
        tree.refresh(RtcPath(path), depth)
    }

    /**
     * Every node below [from] (included), at most [maxDepth] levels down, that [filter] accepts, in depth-first order
     * (see [RtcTree.find]). [filter] sees each node as it was last read. Unreachable contexts and managers below are
     * skipped; [from], or a name server the walk reaches, that cannot be listed fails the call as [children] does: a
     * search of a dead name server is not an empty one.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun find(from: String, filter: Predicate<JavaNode>, maxDepth: Int = Int.MAX_VALUE): List<JavaNode> =
        calls.await {
            findAll(from, filter, maxDepth)
        }

    /** [find], when done; it fails with what [find] throws. */
    @JvmOverloads
    public fun findAsync(
        from: String,
        filter: Predicate<JavaNode>,
        maxDepth: Int = Int.MAX_VALUE,
    ): CompletableFuture<List<JavaNode>> = calls.future { findAll(from, filter, maxDepth) }

    /**
     * Calls [listener] on [executor] with every event of [type] from the node at [path] (see [RtcTree.on]), one event
     * at a time: the next waits until the listener has returned, so [EventOptions.overlap] holds. A UI passes its
     * toolkit's executor (SWT: `display::asyncExec`) and touches its widgets in the listener. What the listener throws
     * goes to [TreeConfig.listenerFailures], naming it and the event. Returns once the node is watched; close the
     * [Subscription] to stop.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun <E : RtcEvent> subscribe(
        path: String,
        type: Class<E>,
        executor: Executor,
        listener: EventListener<E>,
        options: EventOptions = EventOptions(),
    ): Subscription = calls.await { on(path, type, executor, listener, options) }

    /** [subscribe], when the node is watched. */
    @JvmOverloads
    public fun <E : RtcEvent> subscribeAsync(
        path: String,
        type: Class<E>,
        executor: Executor,
        listener: EventListener<E>,
        options: EventOptions = EventOptions(),
    ): CompletableFuture<Subscription> = calls.future { on(path, type, executor, listener, options) }

    /**
     * Calls [listener] on [executor] with how the tree watches each watched component and with managers that die or
     * return (see [RtcTree.onWatching]). Close the [Subscription] to stop.
     */
    public fun subscribeWatching(executor: Executor, listener: EventListener<RtcEvent>): Subscription =
        tree.onWatching(JavaListenerCall(listener, executor, RtcEvent::class.java))

    /**
     * Starts a log input on [address] (`host:port`, port 0 for any free one) that OpenRTM-aist's components send their
     * log records to, each a [LogRecord] event to [subscribe] to; with [sharedKey], senders must pass Fluentd's
     * shared-key handshake (see [RtcTree.listenForLogs]). Closed with the tree.
     *
     * @throws java.io.IOException when it cannot listen there, naming the address.
     */
    @JvmOverloads
    public fun listenForLogs(
        address: String = DEFAULT_LOG_ADDRESS,
        sharedKey: @Nullable String? = null,
    ): LogInput = tree.listenForLogs(address, sharedKey)

    /** The tree's model of the system now, read without a remote call (see [RtcTree.snapshot]). */
    public fun snapshot(): SystemSnapshot = tree.snapshot()

    /**
     * Subscribes to the events of [type] from the nodes at [paths], then calls [start] on [executor] with the model as
     * it is once they are watched, and [listener] with every later event, one at a time, none missed and none twice
     * (see [RtcTree.follow]): what a view needs to draw the system and keep it true. Returns once [start] was called;
     * close the [Subscription] to stop. [follow] with a set of types follows several kinds of event from one snapshot.
     *
     * @throws RtcException when a path names nothing or cannot be watched; nothing is left subscribed.
     * @throws java.util.concurrent.RejectedExecutionException when [executor] refuses [start]'s task.
     * @throws InterruptedException when the calling thread is interrupted while it waits.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun <E : RtcEvent> follow(
        paths: List<String>,
        type: Class<E>,
        executor: Executor,
        start: Consumer<SystemSnapshot>,
        listener: EventListener<in E>,
        options: EventOptions = EventOptions(),
    ): Subscription = calls.await { followed(paths, setOf(type), type, executor, start, listener, options) }

    /** [follow], once [start] was called. */
    @JvmOverloads
    public fun <E : RtcEvent> followAsync(
        paths: List<String>,
        type: Class<E>,
        executor: Executor,
        start: Consumer<SystemSnapshot>,
        listener: EventListener<in E>,
        options: EventOptions = EventOptions(),
    ): CompletableFuture<Subscription> = calls.future {
        followed(paths, setOf(type), type, executor, start, listener, options)
    }

    /**
     * [follow] for the events of every one of [types] (`Set.of(StateChanged.class, PortTraffic.class)`), from one
     * snapshot: [listener] gets them in the order they happened, whatever their type.
     *
     * @throws RtcException when a path names nothing or cannot be watched; nothing is left subscribed.
     * @throws java.util.concurrent.RejectedExecutionException when [executor] refuses [start]'s task.
     * @throws InterruptedException when the calling thread is interrupted while it waits.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun follow(
        paths: List<String>,
        types: Set<Class<out RtcEvent>>,
        executor: Executor,
        start: Consumer<SystemSnapshot>,
        listener: EventListener<RtcEvent>,
        options: EventOptions = EventOptions(),
    ): Subscription = calls.await { followed(paths, types, RtcEvent::class.java, executor, start, listener, options) }

    /** [follow] of several [types], once [start] was called. */
    @JvmOverloads
    public fun followAsync(
        paths: List<String>,
        types: Set<Class<out RtcEvent>>,
        executor: Executor,
        start: Consumer<SystemSnapshot>,
        listener: EventListener<RtcEvent>,
        options: EventOptions = EventOptions(),
    ): CompletableFuture<Subscription> = calls.future {
        followed(paths, types, RtcEvent::class.java, executor, start, listener, options)
    }

    /** Closes the tree (see [RtcTree.close]). */
    override fun close() {
        tree.close()
    }

    private suspend fun directory(path: String): DirectoryNode =
        when (val node = tree.node(path)) {
            is DirectoryNode -> node
            else -> throw WrongKindException(node.path.toString(), "directory", node.kind.label())
        }

    private suspend fun unbindAt(path: String) {
        val parsed = RtcPath(path)
        val parent = parsed.parent?.let { tree.node(it) }
        if (parent !is NamingDirectory)
            throw WrongKindException(
                path,
                "binding in a naming context",
                "child of ${parent?.kind?.label() ?: "nothing"}",
            )
        parent.unbind(parsed.name)
    }

    private suspend fun findAll(from: String, filter: Predicate<JavaNode>, maxDepth: Int): List<JavaNode> {
        val start = tree.node(from)
        // Listed first, so that their failure is thrown: the walk skips what it cannot list.
        if (maxDepth > 0) {
            (start as? DirectoryNode)?.children()
            if (start is RootNode && maxDepth > 1) start.children().forEach { (it as? NameServerNode)?.children() }
        }
        return tree.find(start.path, maxDepth) { filter.test(JavaNode(it)) }.toList().map(::JavaNode)
    }

    private suspend fun <E : RtcEvent> followed(
        paths: List<String>,
        types: Set<Class<out E>>,
        type: Class<E>,
        executor: Executor,
        start: Consumer<SystemSnapshot>,
        listener: EventListener<in E>,
        options: EventOptions,
    ): Subscription {
        require(types.isNotEmpty()) { "follow needs at least one event type" }
        return tree.follow(
            paths.map { tree.node(it) },
            types,
            options,
            { snapshot -> executor.runTask { start.accept(snapshot) } },
            JavaListenerCall(listener, executor, type),
        )
    }

    private suspend fun <E : RtcEvent> on(
        path: String,
        type: Class<E>,
        executor: Executor,
        listener: EventListener<E>,
        options: EventOptions,
    ): Subscription = tree.on(tree.node(path), setOf(type), options, JavaListenerCall(listener, executor, type))
}
