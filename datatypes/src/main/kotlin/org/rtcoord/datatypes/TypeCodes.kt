package org.rtcoord.datatypes

import org.omg.CORBA.TCKind
import org.omg.CORBA.TypeCode

/**
 * CORBA TypeCodes read into [IdlType]s. The standard types' TypeCodes are those idlj generated from our IDL at build
 * time (`RTC.RangeDataHelper.type()`), so the standard types need no IDL parsing at run time.
 */
internal object TypeCodes {
    /**
     * [code] as an [IdlType]; throws [IllegalArgumentException] for what data ports cannot carry (object references,
     * `any`, ...).
     */
    fun read(code: TypeCode): IdlType =
        when (code.kind().value()) {
            TCKind._tk_boolean -> IdlType.Primitive.BOOLEAN
            TCKind._tk_octet -> IdlType.Primitive.OCTET
            TCKind._tk_char -> IdlType.Primitive.CHAR
            TCKind._tk_wchar -> IdlType.Primitive.WCHAR
            TCKind._tk_short -> IdlType.Primitive.SHORT
            TCKind._tk_ushort -> IdlType.Primitive.USHORT
            TCKind._tk_long -> IdlType.Primitive.LONG
            TCKind._tk_ulong -> IdlType.Primitive.ULONG
            TCKind._tk_longlong -> IdlType.Primitive.LONGLONG
            TCKind._tk_ulonglong -> IdlType.Primitive.ULONGLONG
            TCKind._tk_float -> IdlType.Primitive.FLOAT
            TCKind._tk_double -> IdlType.Primitive.DOUBLE
            TCKind._tk_string -> IdlType.StringType(wide = false, bound = code.length())
            TCKind._tk_wstring -> IdlType.StringType(wide = true, bound = code.length())
            TCKind._tk_sequence -> IdlType.Sequence(read(code.content_type()), code.length())
            TCKind._tk_array -> IdlType.ArrayType(read(code.content_type()), code.length())
            TCKind._tk_alias -> IdlType.Alias(scopedName(code.id()), code.id(), read(code.content_type()))
            TCKind._tk_enum ->
                IdlType.Enum(scopedName(code.id()), code.id(), List(code.member_count()) { code.member_name(it) })
            TCKind._tk_struct ->
                IdlType.Struct(
                    scopedName(code.id()),
                    code.id(),
                    List(code.member_count()) { IdlType.Member(code.member_name(it), read(code.member_type(it))) },
                )
            TCKind._tk_union -> union(code)
            else -> throw IllegalArgumentException("a data port cannot carry ${code.kind().value().let(::kindName)}")
        }

    private fun union(code: TypeCode): IdlType.Union {
        val discriminator = read(code.discriminator_type())
        val default = code.default_index()
        val cases =
            (0 until code.member_count())
                .groupBy { code.member_name(it) }
                .map { (name, indices) ->
                    val labels = indices.filter { it != default }.map { label(code.member_label(it), discriminator) }
                    IdlType.Case(labels, name, read(code.member_type(indices.first())))
                }
        return IdlType.Union(scopedName(code.id()), code.id(), discriminator, cases)
    }

    /** A case label as [DataCodec] compares discriminators: integers as Long, enumerators by name. */
    private fun label(any: org.omg.CORBA.Any, discriminator: IdlType): Any =
        when (val type = discriminator.resolved) {
            is IdlType.Enum -> type.enumerators[any.create_input_stream().read_ulong()]
            IdlType.Primitive.BOOLEAN -> any.extract_boolean()
            IdlType.Primitive.CHAR -> any.extract_char()
            IdlType.Primitive.WCHAR -> any.extract_wchar()
            IdlType.Primitive.SHORT -> any.extract_short().toLong()
            IdlType.Primitive.USHORT -> any.extract_ushort().toLong() and 0xffff
            IdlType.Primitive.LONG -> any.extract_long().toLong()
            IdlType.Primitive.ULONG -> any.extract_ulong().toLong() and 0xffffffffL
            IdlType.Primitive.LONGLONG -> any.extract_longlong()
            IdlType.Primitive.ULONGLONG -> any.extract_ulonglong()
            else -> throw IllegalArgumentException("a union cannot be discriminated by ${type.name}")
        }

    /** `RTC::RangeData` from `IDL:RTC/RangeData:1.0` (a prefix such as `omg.org/` left out). */
    fun scopedName(repositoryId: String): String =
        repositoryId.removePrefix("IDL:").substringBeforeLast(':').split('/').let { parts ->
            parts.dropWhile { it.contains('.') && parts.size > 1 }.joinToString("::")
        }

    private fun kindName(kind: Int): String =
        when (kind) {
            TCKind._tk_objref -> "object references"
            TCKind._tk_any -> "any"
            TCKind._tk_TypeCode -> "TypeCodes"
            TCKind._tk_longdouble -> "long double"
            TCKind._tk_fixed -> "fixed"
            TCKind._tk_value,
            TCKind._tk_value_box -> "valuetypes"
            else -> "values of TypeCode kind $kind"
        }
}
