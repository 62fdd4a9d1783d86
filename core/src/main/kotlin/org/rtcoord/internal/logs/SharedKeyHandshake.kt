package org.rtcoord.internal.logs

import java.security.MessageDigest
import java.security.SecureRandom
import org.msgpack.core.MessagePacker
import org.msgpack.value.ValueType

/**
 * The forward protocol's shared-key handshake, the server's side, as in_forward does it:
 *
 * 1. the server sends `["HELO", {"nonce": bin, "auth": bin, "keepalive": true}]`;
 * 2. the client answers `["PING", client_hostname, shared_key_salt, sha512_hex(shared_key_salt + client_hostname +
 *    nonce + shared_key), username, password_digest]`;
 * 3. the server checks the digest and answers `["PONG", authenticated, reason, self_hostname,
 *    sha512_hex(shared_key_salt + self_hostname + nonce + shared_key)]`, the digest empty when it refuses, and closes
 *    the connection after a refusal.
 *
 * User and password authentication is not offered: HELO's `auth` salt is empty, which tells the client none is
 * required, and a PING's username and password are ignored, as in_forward ignores them without `user_auth`. A client
 * whose hostname is this end's is refused, as in_forward refuses it: the two ends of one Fluentd are configured wrong.
 */
internal class SharedKeyHandshake(
    private val sharedKey: String,
    private val selfHostname: String,
    random: SecureRandom,
) {
    private val nonce = ByteArray(NONCE_BYTES).also(random::nextBytes)

    /** Writes HELO. */
    fun helo(packer: MessagePacker) {
        packer.packArrayHeader(2).packString("HELO").packMapHeader(3)
        packer.packString("nonce").packBinaryHeader(nonce.size).writePayload(nonce)
        packer.packString("auth").packBinaryHeader(0)
        packer.packString("keepalive").packBoolean(true)
        packer.flush()
    }

    /**
     * Reads the client's PING from [values] and writes PONG to [packer]; throws a [RefusedInput] of
     * [ForwardRefusal.WRONG_KEY] after a refusing PONG. A PING that is not MessagePack, or whose fields are not
     * strings, is [ForwardRefusal.MALFORMED].
     */
    fun ping(values: BoundedValues, packer: MessagePacker) {
        val verdict = check(values)
        packer.packArrayHeader(PONG_SIZE).packString("PONG").packBoolean(verdict.problem == null)
        packer.packString(verdict.problem ?: "").packString(selfHostname)
        packer.packString(verdict.salt?.let { digest(it, selfHostname) } ?: "")
        packer.flush()
        verdict.problem?.let { throw RefusedInput(ForwardRefusal.WRONG_KEY, it) }
    }

    /** The PING's salt when it is right, or why it is refused. */
    private class Verdict(val salt: ByteArray?, val problem: String?)

    private fun check(values: BoundedValues): Verdict {
        // The connection is closed after a refusal: what is left of a wrong frame need not be read.
        if (values.nextType() != ValueType.ARRAY) return Verdict(null, "expected PING before anything else")
        val size = values.arrayHeader("PING")
        if (size != PING_SIZE || values.value() != "PING") return Verdict(null, "expected PING before anything else")
        val hostname = values.text("PING's hostname")
        val salt = values.raw("PING's shared key salt")
        val digest = values.text("PING's digest")
        // Username and password: no user authentication is offered (HELO's auth is empty).
        values.value()
        values.value()
        values.checkUsed()
        if (hostname == selfHostname)
            return Verdict(null, "same hostname between input and output: invalid configuration")
        val expected = digest(salt, hostname).toByteArray()
        if (!MessageDigest.isEqual(expected, digest.lowercase().toByteArray())) {
            return Verdict(null, "shared key mismatch from $hostname")
        }
        return Verdict(salt, null)
    }

    /** sha512_hex(salt + hostname + nonce + shared_key). */
    private fun digest(salt: ByteArray, hostname: String): String {
        val sha = MessageDigest.getInstance("SHA-512")
        sha.update(salt)
        sha.update(hostname.toByteArray(Charsets.UTF_8))
        sha.update(nonce)
        sha.update(sharedKey.toByteArray(Charsets.UTF_8))
        return sha.digest().joinToString("") { "%02x".format(it) }
    }

    private companion object {
        const val NONCE_BYTES = 16
        const val PING_SIZE = 6
        const val PONG_SIZE = 5
    }
}
