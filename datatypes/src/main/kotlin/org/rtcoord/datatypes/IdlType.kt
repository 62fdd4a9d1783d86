package org.rtcoord.datatypes

/**
 * An IDL type as far as CDR needs it: what its bytes are, not how a language maps it. Standard types come from
 * [StandardDataTypes]; users' IDL is read into the same model. Typedefs stay as [Alias] so that a type prints under the
 * name its IDL gives it; they add nothing to the bytes.
 *
 * Values of each type, as [DataCodec] reads and writes them:
 *
 * |type                             |value                                                                                           |
 * |---------------------------------|------------------------------------------------------------------------------------------------|
 * |`boolean`                        |[Boolean]                                                                                       |
 * |`octet`, `char`, `wchar`         |[Byte], [Char], [Char]                                                                          |
 * |`short`, `unsigned short`        |[Short], [Int]                                                                                  |
 * |`long`, `unsigned long`          |[Int], [Long]                                                                                   |
 * |`long long`, `unsigned long long`|[Long], [java.math.BigInteger]                                                                  |
 * |`float`, `double`                |[Float], [Double]                                                                               |
 * |`string`, `wstring`              |[String]                                                                                        |
 * |sequence, array                  |[List] (written from a primitive array too)                                                     |
 * |struct                           |[Map] of member name to value, in declaration order                                             |
 * |enum                             |the enumerator's name, a [String]                                                               |
 * |union                            |[Map] of [UNION_DISCRIMINATOR] to the discriminator, and the selected member's name to its value|
 */
public sealed class IdlType {
    /** The type as IDL writes it: `double`, `sequence<RTC::Point2D>`, `RTC::RangeData`. */
    public abstract val name: String

    override fun toString(): String = name

    /** A basic type of fixed size: its CDR [size] is also its alignment. */
    public class Primitive private constructor(override val name: String, public val size: Int) : IdlType() {
        public companion object {
            @JvmField public val BOOLEAN: Primitive = Primitive("boolean", 1)
            @JvmField public val OCTET: Primitive = Primitive("octet", 1)
            @JvmField public val CHAR: Primitive = Primitive("char", 1)
            /** GIOP 1.2's: a length octet, then the character in UTF-16. */
            @JvmField public val WCHAR: Primitive = Primitive("wchar", 1)
            @JvmField public val SHORT: Primitive = Primitive("short", 2)
            @JvmField public val USHORT: Primitive = Primitive("unsigned short", 2)
            @JvmField public val LONG: Primitive = Primitive("long", 4)
            @JvmField public val ULONG: Primitive = Primitive("unsigned long", 4)
            @JvmField public val LONGLONG: Primitive = Primitive("long long", 8)
            @JvmField public val ULONGLONG: Primitive = Primitive("unsigned long long", 8)
            @JvmField public val FLOAT: Primitive = Primitive("float", 4)
            @JvmField public val DOUBLE: Primitive = Primitive("double", 8)
        }
    }

    /** `string` or `wstring` ([wide]), at most [bound] characters (0: unbounded). */
    public class StringType(public val wide: Boolean, public val bound: Int = 0) : IdlType() {
        override val name: String = (if (wide) "wstring" else "string") + if (bound > 0) "<$bound>" else ""
    }

    /** `sequence<element>`, at most [bound] elements (0: unbounded). */
    public class Sequence(public val element: IdlType, public val bound: Int = 0) : IdlType() {
        override val name: String
            get() = "sequence<${element.name}${if (bound > 0) ", $bound" else ""}>"
    }

    /** An array of exactly [length] elements (a multi-dimensional array is an array of arrays). */
    public class ArrayType(public val element: IdlType, public val length: Int) : IdlType() {
        override val name: String
            get() = "${element.name}[$length]"
    }

    /** A declared type, with its [repositoryId] (`IDL:RTC/RangeData:1.0`); [name] is its scoped name. */
    public sealed class Declared : IdlType() {
        public abstract val repositoryId: String
    }

    /** A struct: its members in declaration order. */
    public class Struct(
        override val name: String,
        override val repositoryId: String,
        public val members: List<Member>,
    ) : Declared()

    /** An enum: its enumerators in declaration order (their ordinals are what CDR carries). */
    public class Enum(
        override val name: String,
        override val repositoryId: String,
        public val enumerators: List<String>,
    ) : Declared()

    /** A union: the [discriminator]'s type and the [cases]; the one with no labels is `default`. */
    public class Union(
        override val name: String,
        override val repositoryId: String,
        public val discriminator: IdlType,
        public val cases: List<Case>,
    ) : Declared() {
        /** The case [discriminator] selects: a labelled one, else the default, else none. */
        public fun caseFor(discriminator: Any): Case? =
            cases.firstOrNull { case -> case.labels.any { it == discriminator } } ?: cases.firstOrNull { it.isDefault }
    }

    /** A typedef: another name for [type]. */
    public class Alias(override val name: String, override val repositoryId: String, public val type: IdlType) :
        Declared()

    /** A struct member. */
    public class Member(public val name: String, public val type: IdlType)

    /**
     * A union's case: the discriminator values that select it ([labels], as [DataCodec] reads the discriminator:
     * numbers, characters, booleans, enumerator names) or none for `default`.
     */
    public class Case(public val labels: List<Any>, public val name: String, public val type: IdlType) {
        /** Whether this is the `default` case. */
        public val isDefault: Boolean
            get() = labels.isEmpty()
    }

    public companion object {
        /** The key of a union's discriminator in its value. */
        public const val UNION_DISCRIMINATOR: String = "discriminator"
    }
}

/** This type with its typedefs looked through. */
public val IdlType.resolved: IdlType
    get() {
        var type = this
        while (type is IdlType.Alias) type = type.type
        return type
    }
