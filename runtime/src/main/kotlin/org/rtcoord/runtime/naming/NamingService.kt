package org.rtcoord.runtime.naming

import java.util.concurrent.atomic.AtomicBoolean
import org.rtcoord.idl.OrbRecipe
import org.rtcoord.runtime.RuntimeOrb
import org.slf4j.LoggerFactory

private val log = LoggerFactory.getLogger(NamingService::class.java)

/**
 * A CORBA naming service (CosNaming `NamingContextExt`) in this JVM, on 127.0.0.1 unless told otherwise, that tools
 * written by others (omniORB's `nameclt`, rtshell) use as they use omniNames: its root context answers at [corbaloc].
 * Contexts and bindings live in memory; [snapshot] and [start] carry them over a restart.
 */
public class NamingService
private constructor(
    private val orb: RuntimeOrb,
    private val registry: ContextRegistry,
) : AutoCloseable {
    /** The port it listens on. */
    public val port: Int
        get() = orb.port

    /** The root context's address, `corbaloc:iiop:HOST:PORT/NameService`. */
    public val corbaloc: String
        get() = orb.corbaloc(KEY)

    /** `HOST:PORT`, the form rtshell paths (`/127.0.0.1:PORT/`) and `-n` options take. */
    public val address: String
        get() = "${orb.host}:${orb.port}"

    private val closed = AtomicBoolean()

    /** Every context and binding as they are now; take it before [close]. */
    public fun snapshot(): NamingSnapshot {
        check(!closed.get()) { "the naming service on $address is closed: take the snapshot before closing it" }
        return registry.capture()
    }

    /** Stops the service and its ORB; the port is free again when this returns. Idempotent. */
    override fun close() {
        if (!closed.compareAndSet(false, true)) return
        orb.close()
        log.info("Naming service on {} stopped", address)
    }

    /** Starts naming services. */
    public companion object {
        private const val KEY = "NameService"

        /**
         * Starts a naming service on [host]:[port] (port 0: one the system chooses), empty or with the contexts and
         * bindings of [restore]. Its ORB keeps [idleRequestThreads] request threads when idle ([RuntimeOrb.start]).
         */
        @JvmOverloads
        public fun start(
            port: Int = 0,
            restore: NamingSnapshot? = null,
            host: String = "127.0.0.1",
            idleRequestThreads: Int = OrbRecipe.REQUEST_THREADS,
        ): NamingService {
            val orb = RuntimeOrb.start(port, host, idleRequestThreads = idleRequestThreads)
            try {
                val registry = ContextRegistry(orb)
                restore?.let(registry::restore)
                orb.bindKey(KEY, registry.root.reference)
                val service = NamingService(orb, registry)
                log.info("Naming service at {} ({})", service.corbaloc, restore ?: "empty")
                return service
            } catch (e: Throwable) {
                orb.close()
                throw e
            }
        }
    }
}
