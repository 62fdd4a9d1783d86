package org.rtcoord.java

import java.util.concurrent.CompletableFuture
import org.jspecify.annotations.Nullable
import org.rtcoord.Connection
import org.rtcoord.ConnectorSnapshot
import org.rtcoord.DataListener
import org.rtcoord.Port
import org.rtcoord.PortSnapshot
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.Subscription
import org.rtcoord.internal.JavaCalls

/**
 * A [Port] for Java callers: each operation blocking, and as a [CompletableFuture] (`...Async`). [JavaTree.port] and
 * [JavaComponent.port] find one by name; `new JavaPort(port)` drives a port at hand.
 */
public class JavaPort(
    /** The port this facade drives. */
    @get:JvmSynthetic public val port: Port
) {
    private val calls = JavaCalls(port.component.core.scope)

    /** Where the port is: `/host:port/ctx/name.rtc:port`. */
    public val path: RtcPath
        get() = port.path

    /**
     * The port as last read.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun snapshot(): PortSnapshot = calls.await { port.snapshot() }

    /** [snapshot], when done; it fails with what [snapshot] throws. */
    public fun snapshotAsync(): CompletableFuture<PortSnapshot> = calls.future { port.snapshot() }

    /**
     * Connects this port to [others] with connector [properties] and [name] (made up when null), and returns the new
     * connector (see [Port.connect]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun connect(
        others: List<JavaPort>,
        properties: Map<String, String> = emptyMap(),
        name: @Nullable String? = null,
    ): ConnectorSnapshot = calls.await { port.connect(others.map { it.port }, properties, name) }

    /** [connect], when done; it fails with what [connect] throws. */
    @JvmOverloads
    public fun connectAsync(
        others: List<JavaPort>,
        properties: Map<String, String> = emptyMap(),
        name: @Nullable String? = null,
    ): CompletableFuture<ConnectorSnapshot> = calls.future { port.connect(others.map { it.port }, properties, name) }

    /**
     * Removes the connection [connectorId] from this port and its peers.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun disconnect(connectorId: String): Unit = calls.await { port.disconnect(connectorId) }

    /** [disconnect], when done; it fails with what [disconnect] throws. */
    public fun disconnectAsync(connectorId: String): CompletableFuture<Void?> = calls.done {
        port.disconnect(connectorId)
    }

    /**
     * Removes every connection of this port.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun disconnectAll(): Unit = calls.await { port.disconnectAll() }

    /** [disconnectAll], when done; it fails with what [disconnectAll] throws. */
    public fun disconnectAllAsync(): CompletableFuture<Void?> = calls.done { port.disconnectAll() }

    /**
     * This port's connections, read now.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun connections(): List<Connection> = calls.await { port.connections() }

    /** [connections], when done; it fails with what [connections] throws. */
    public fun connectionsAsync(): CompletableFuture<List<Connection>> = calls.future { port.connections() }

    /**
     * Subscribes [listener] to this out-port's data and returns once subscribed; cancel the returned [Subscription] to
     * stop (see [Port.tap]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun tap(listener: DataListener): Subscription = calls.await { port.tap(listener) }

    /** [tap], when subscribed. */
    public fun tapAsync(listener: DataListener): CompletableFuture<Subscription> = calls.future { port.tap(listener) }

    override fun toString(): String = port.toString()
}
