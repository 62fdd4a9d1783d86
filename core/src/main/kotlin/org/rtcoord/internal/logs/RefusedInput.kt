package org.rtcoord.internal.logs

/**
 * Thrown while reading a connection's input that must be refused: the connection is closed and [refusal] counted, with
 * [message] as the one-line reason.
 */
internal class RefusedInput(val refusal: ForwardRefusal, override val message: String) : Exception(message)
