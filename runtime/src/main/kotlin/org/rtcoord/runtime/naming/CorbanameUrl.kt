package org.rtcoord.runtime.naming

import org.omg.CosNaming.NamingContextExtPackage.InvalidAddress

/** NamingContextExt.to_url: `corbaname:<address list>#<stringified name, URL-escaped>`. */
internal object CorbanameUrl {
    /** `[major.minor@]host[:port]`, the whole of it optional as in the corbaloc grammar. */
    private val iiopAddress =
        Regex("""((\d+\.\d+@)?(\[[0-9A-Fa-f:.]+]|[A-Za-z0-9]([A-Za-z0-9.-]*[A-Za-z0-9])?)(:(\d{1,5}))?)?""")

    /** RFC 2396's unreserved and reserved characters; everything else is written as %XX. */
    private const val KEPT = ";/:?@&=+$,-_.!~*'()"

    fun of(addr: String, sn: String): String {
        StringifiedNames.parse(sn) // raises InvalidName for a malformed name
        if (!validAddressList(addr)) throw InvalidAddress()
        return "corbaname:$addr#${escape(sn)}"
    }

    /** `:` is short for `iiop:`. */
    private val iiopTokens = setOf("", "iiop")

    private fun validAddressList(addr: String): Boolean {
        if (addr == "rir:") return true
        return addr.split(',').all { address ->
            val colon = address.indexOf(':')
            colon >= 0 && address.substring(0, colon) in iiopTokens && validIiopAddress(address.substring(colon + 1))
        }
    }

    private fun validIiopAddress(text: String): Boolean {
        val match = iiopAddress.matchEntire(text) ?: return false
        val port = match.groups[6]?.value ?: return true
        return port.toInt() <= 65535
    }

    private fun escape(sn: String): String = buildString {
        for (byte in sn.toByteArray(Charsets.UTF_8)) {
            val c = (byte.toInt() and 0xff).toChar()
            val kept = c < '\u0080' && (c.isLetterOrDigit() || c in KEPT)
            if (kept) append(c) else append("%%%02X".format(c.code))
        }
    }
}
