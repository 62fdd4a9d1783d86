package org.rtcoord

/**
 * Every failure the library reports: a one-line message naming the object ([subject], usually its path) and the reason.
 * Nothing is ignored: each `ReturnCode_t` other than `RTC_OK` and each CORBA or SDO exception becomes one of these.
 */
public sealed class RtcException(
    /** The object concerned: a path, an address or a name. */
    public val subject: String,
    /** Why, in a few words. */
    public val reason: String,
    cause: Throwable? = null,
) : Exception("$subject: $reason", cause) {
    /**
     * Whether the object this failed on is taken for dead: unreachable or hung. A directory shows such a child as a
     * [ZombieNode]; a tool reading one component can mark it dead the same way. Java: `isDead()`.
     */
    @get:JvmName("isDead")
    public val meansDead: Boolean
        get() = this is UnreachableException || this is TimedOutException
}

/** A path that does not follow the grammar; [position] is the index of the offending segment. */
public class BadPathException(path: String, public val position: Int, reason: String) :
    RtcException(path, "bad path: $reason (segment ${position + 1})")

/** Nothing exists at the path or under the name. */
public class NotFoundException(subject: String, reason: String = "not found") : RtcException(subject, reason)

/** A name matches several different objects; [candidates] are their paths, sorted. */
public class AmbiguousNameException(name: String, candidates: List<String>) :
    RtcException(name, "ambiguous: matches ${candidates.sorted().joinToString(", ")}") {
    /** The paths of the objects the name matches, sorted. */
    public val candidates: List<String> = candidates.sorted()
}

/** The object exists but is not of the kind the operation needs. */
public class WrongKindException(subject: String, public val expected: String, public val actual: String) :
    RtcException(subject, "is a $actual, not a $expected")

/** The object (or the name server holding it) did not answer: dead, refused or unreachable. */
public class UnreachableException(subject: String, cause: Throwable) :
    RtcException(subject, "unreachable (${cause.corbaName()})", cause)

/** The object did not answer within the deadline. */
public class TimedOutException(subject: String, public val operation: String, public val deadlineMillis: Long) :
    RtcException(subject, "$operation timed out after $deadlineMillis ms")

/** The object refused because it is not in a state that allows the operation (`PRECONDITION_NOT_MET`). */
public class PreconditionNotMetException(subject: String, public val operation: String, detail: String) :
    RtcException(subject, "$operation refused: $detail")

/** The object rejected an argument (`BAD_PARAMETER`, `InvalidParameter`). */
public class BadParameterException(subject: String, public val operation: String, detail: String) :
    RtcException(subject, "$operation rejected: $detail")

/** The object does not support the operation (`UNSUPPORTED`, `InterfaceNotImplemented`). */
public class OperationUnsupportedException(subject: String, public val operation: String) :
    RtcException(subject, "$operation is not supported")

/**
 * The object answered with a failure code ([returnCode], e.g. `RTC_ERROR`, `OUT_OF_RESOURCES`) or an SDO
 * `InternalError`/`NotAvailable`, or the end state after the operation was not the expected one.
 */
public class OperationFailedException(
    subject: String,
    public val operation: String,
    public val returnCode: String,
    detail: String? = null,
) : RtcException(subject, "$operation failed: $returnCode" + (detail?.let { " ($it)" } ?: ""))

private fun Throwable.corbaName(): String =
    when (this) {
        // JacORB's words for a connection that could not be made (it makes one try: OrbRecipe).
        is org.omg.CORBA.TRANSIENT ->
            message?.let { NO_CONNECTION.find(it) }?.let { "cannot connect to ${it.groupValues[1]}" }
                ?: "TRANSIENT" + (message?.takeIf { it.isNotBlank() }?.let { ": $it" } ?: "")
        is org.omg.CORBA.SystemException ->
            javaClass.simpleName + (message?.takeIf { it.isNotBlank() }?.let { ": $it" } ?: "")
        else -> toString()
    }

private val NO_CONNECTION = Regex("couldn't reconnect to (\\S+)")
