package org.rtcoord.cli.serve

import java.nio.file.Path

/**
 * Where and how the live view is served: on [address]:[port] (0: a free port), requiring [token] in API requests when
 * there is one, letting the page operate components when [operate], writing what it shows to [record] when there is
 * one.
 */
internal data class ServeSettings(
    val address: String = "127.0.0.1",
    val port: Int = 0,
    val token: String? = null,
    val operate: Boolean = false,
    val record: Path? = null,
) {
    /** What to warn about before serving, or null: a page on a non-loopback address without a token. */
    fun exposure(): String? =
        if (token == null && !isLoopback())
            "the page on $address has no authentication: anyone who reaches it sees the system" +
                (if (operate) " and can operate it" else "") +
                "; add a token to require one"
        else null

    private fun isLoopback(): Boolean = address == "localhost" || address.startsWith("127.") || address == "::1"
}
