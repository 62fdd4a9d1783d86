package org.rtcoord.java

import java.util.concurrent.CompletableFuture
import org.jspecify.annotations.Nullable
import org.rtcoord.ManagerNode
import org.rtcoord.RtcException
import org.rtcoord.internal.JavaCalls

/**
 * A [ManagerNode] for Java callers: each operation blocking, and as a [CompletableFuture] (`...Async`).
 * [JavaTree.manager] finds one by path; `new JavaManager(node)` drives a manager at hand, such as an event's source
 * ([org.rtcoord.ManagerDied.source]).
 */
public class JavaManager(
    /** The manager this facade drives. */
    @get:JvmSynthetic public val node: ManagerNode
) {
    private val calls = JavaCalls(node.core.scope)

    /**
     * Its slave managers and the components it hosts itself, listed now if they never were.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun children(): List<JavaNode> = calls.await { node.children().map(::JavaNode) }

    /** [children], when done; it fails with what [children] throws. */
    public fun childrenAsync(): CompletableFuture<List<JavaNode>> = calls.future { node.children().map(::JavaNode) }

    /**
     * The manager's profile properties (`instance_name`, `pid`, ...).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun profile(): Map<String, String> = calls.await { node.profile() }

    /** [profile], when done; it fails with what [profile] throws. */
    public fun profileAsync(): CompletableFuture<Map<String, String>> = calls.future { node.profile() }

    /**
     * Whether it is a master manager.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun isMaster(): Boolean = calls.await { node.isMaster() }

    /** [isMaster], when done; it fails with what [isMaster] throws. */
    public fun isMasterAsync(): CompletableFuture<Boolean> = calls.future { node.isMaster() }

    /**
     * Creates a component of [type], named [instanceName] (or as the manager names it when null), with creation
     * [options] (see [ManagerNode.create]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun create(
        type: String,
        instanceName: @Nullable String? = null,
        options: Map<String, String> = emptyMap(),
    ): JavaComponent = calls.await { JavaComponent(node.create(type, instanceName, options)) }

    /** [create], when done; it fails with what [create] throws. */
    @JvmOverloads
    public fun createAsync(
        type: String,
        instanceName: @Nullable String? = null,
        options: Map<String, String> = emptyMap(),
    ): CompletableFuture<JavaComponent> = calls.future { JavaComponent(node.create(type, instanceName, options)) }

    /**
     * Deletes component [instanceName] through the manager that hosts it (see [ManagerNode.delete]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun delete(instanceName: String): Unit = calls.await { node.delete(instanceName) }

    /** [delete], when done; it fails with what [delete] throws. */
    public fun deleteAsync(instanceName: String): CompletableFuture<Void?> = calls.done { node.delete(instanceName) }

    /**
     * Loads module [path], calling [initFunction] in it if the manager needs one.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun loadModule(path: String, initFunction: String = ""): Unit = calls.await {
        node.loadModule(path, initFunction)
    }

    /** [loadModule], when done; it fails with what [loadModule] throws. */
    @JvmOverloads
    public fun loadModuleAsync(path: String, initFunction: String = ""): CompletableFuture<Void?> = calls.done {
        node.loadModule(path, initFunction)
    }

    /**
     * Unloads module [path].
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun unloadModule(path: String): Unit = calls.await { node.unloadModule(path) }

    /** [unloadModule], when done; it fails with what [unloadModule] throws. */
    public fun unloadModuleAsync(path: String): CompletableFuture<Void?> = calls.done { node.unloadModule(path) }

    /**
     * Modules the manager could load, as their profile properties.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun loadableModules(): List<Map<String, String>> = calls.await { node.loadableModules() }

    /** [loadableModules], when done; it fails with what [loadableModules] throws. */
    public fun loadableModulesAsync(): CompletableFuture<List<Map<String, String>>> = calls.future {
        node.loadableModules()
    }

    /**
     * Modules the manager has loaded.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun loadedModules(): List<Map<String, String>> = calls.await { node.loadedModules() }

    /** [loadedModules], when done; it fails with what [loadedModules] throws. */
    public fun loadedModulesAsync(): CompletableFuture<List<Map<String, String>>> = calls.future {
        node.loadedModules()
    }

    /**
     * The component types the manager can create, as their factory profiles.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun factories(): List<Map<String, String>> = calls.await { node.factories() }

    /** [factories], when done; it fails with what [factories] throws. */
    public fun factoriesAsync(): CompletableFuture<List<Map<String, String>>> = calls.future { node.factories() }

    override fun toString(): String = node.toString()
}
