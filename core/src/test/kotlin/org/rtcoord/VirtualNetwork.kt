package org.rtcoord

import java.util.concurrent.TimeUnit

/**
 * Simulated hosts on one LAN: a network namespace per host, each with an `eth0` at `10.77.0.N/24` plugged into a bridge
 * in a namespace of its own, the switch. Namespace names carry this JVM's pid, so runs never share them, and namespaces
 * left by runs that died are removed on the way in. Needs root (or CAP_SYS_ADMIN and CAP_NET_ADMIN); [close] removes
 * every namespace, which takes its links with it.
 */
class VirtualNetwork(hosts: List<String>) : AutoCloseable {
    private val prefix = "rtco${ProcessHandle.current().pid()}-"
    private val switch = "${prefix}switch"
    private val addresses = hosts.withIndex().associate { (index, host) -> host to "10.77.0.${index + 1}" }
    private val created = mutableListOf<String>()

    init {
        removeAbandoned()
        try {
            add(switch)
            ip("-n", switch, "link", "add", "br0", "type", "bridge")
            ip("-n", switch, "link", "set", "br0", "up")
            for (host in hosts) {
                val namespace = namespace(host)
                add(namespace)
                ip("-n", switch, "link", "add", port(host), "type", "veth", "peer", "name", "eth0", "netns", namespace)
                ip("-n", switch, "link", "set", port(host), "master", "br0", "up")
                ip("-n", namespace, "addr", "add", "${address(host)}/24", "dev", "eth0")
                ip("-n", namespace, "link", "set", "eth0", "up")
                ip("-n", namespace, "link", "set", "lo", "up")
            }
        } catch (e: Exception) {
            close()
            throw e
        }
    }

    /** [host]'s address. */
    fun address(host: String): String = addresses.getValue(host)

    /** The command prefix that runs a program on [host]: `ip netns exec NAMESPACE`. */
    fun on(host: String): List<String> = listOf("ip", "netns", "exec", namespace(host))

    /** Unplugs [host]'s cable: nothing passes either way, and no connection is reset. */
    fun cut(host: String) = ip("-n", switch, "link", "set", port(host), "down")

    /** Plugs [host]'s cable back in. */
    fun heal(host: String) = ip("-n", switch, "link", "set", port(host), "up")

    override fun close() {
        created.reversed().forEach { runCatching { ip("netns", "del", it) } }
        created.clear()
    }

    private fun namespace(host: String) = "$prefix$host"

    private fun port(host: String) = "p-$host".take(15)

    private fun add(namespace: String) {
        ip("netns", "add", namespace)
        created += namespace
    }

    /** Namespaces of earlier runs whose JVM is gone (killed before it could close them). */
    private fun removeAbandoned() {
        val names = run("ip", "netns", "list").lines().map { it.substringBefore(' ') }
        names
            .filter { name ->
                val pid = Regex("""^rtco(\d+)-""").find(name)?.groupValues?.get(1)?.toLongOrNull()
                pid != null && ProcessHandle.of(pid).map { !it.isAlive }.orElse(true)
            }
            .forEach { runCatching { ip("netns", "del", it) } }
    }

    companion object {
        /** Why namespaces cannot be made here, or null when they can: tries to add (and remove) one. */
        fun unavailable(): String? {
            val probe = "rtco${ProcessHandle.current().pid()}-probe"
            return try {
                run("ip", "netns", "add", probe)
                run("ip", "netns", "del", probe)
                null
            } catch (e: Exception) {
                e.message
            }
        }

        private fun ip(vararg arguments: String) {
            run("ip", *arguments)
        }

        /** Runs [command]; returns its output, or throws with its error output when it fails. */
        private fun run(vararg command: String): String {
            val process =
                try {
                    ProcessBuilder(*command).redirectErrorStream(true).start()
                } catch (e: java.io.IOException) {
                    throw IllegalStateException("${command.first()}: ${e.message}")
                }
            val output = process.inputStream.bufferedReader().readText()
            check(process.waitFor(30, TimeUnit.SECONDS)) { "${command.joinToString(" ")} did not end" }
            check(process.exitValue() == 0) { "${command.joinToString(" ")}: ${output.trim()}" }
            return output
        }
    }
}
