package org.rtcoord.datatypes

import java.util.Enumeration
import org.jacorb.idl.AliasTypeSpec
import org.jacorb.idl.ArrayTypeSpec
import org.jacorb.idl.ConstExpr
import org.jacorb.idl.ConstrTypeSpec
import org.jacorb.idl.Definition
import org.jacorb.idl.EnumType
import org.jacorb.idl.Member
import org.jacorb.idl.ScopedName
import org.jacorb.idl.SequenceType
import org.jacorb.idl.StringType
import org.jacorb.idl.StructType
import org.jacorb.idl.SwitchBody
import org.jacorb.idl.TypeDeclaration
import org.jacorb.idl.TypeDef
import org.jacorb.idl.TypeSpec
import org.jacorb.idl.UnionType

/**
 * Reads the type declarations of one JacORB IDL syntax tree ([org.jacorb.idl.Spec], after JacORB resolved its names)
 * into [IdlType]s, by repository ID. Primitive types map through their TypeCode kind, as [TypeCodes] maps the standard
 * types' TypeCodes, so both give the same model.
 */
internal class IdlTypeReader {
    /** Every struct, union, enum and typedef declared, by repository ID, in declaration order. */
    val declared = LinkedHashMap<String, IdlType.Declared>()
    private val building = HashSet<String>()

    /** Reads the definitions [elements] enumerates (a file's or a module's). */
    fun definitions(elements: Enumeration<*>) {
        for (element in elements) {
            val declaration = (element as? Definition)?.get_declaration() ?: continue
            when (declaration) {
                is org.jacorb.idl.Module -> definitions(declaration.getDefinitions().getElements())
                is TypeDeclaration -> typeDeclaration(declaration.type_decl ?: declaration)
            }
        }
    }

    private fun typeDeclaration(declaration: TypeDeclaration) {
        when (declaration) {
            is TypeDef -> declaration.getTypeSpecs().forEach { alias(it as AliasTypeSpec) }
            is StructType -> if (!declaration.isException) struct(declaration)
            is UnionType -> union(declaration)
            is EnumType -> enumType(declaration)
        }
    }

    private fun type(spec: TypeSpec): IdlType =
        when (val inner = spec.typeSpec()) {
            is ScopedName -> type(inner.resolvedTypeSpec())
            is AliasTypeSpec -> alias(inner)
            is ConstrTypeSpec ->
                when (val declaration = inner.c_type_spec.declaration()) {
                    is StructType -> struct(declaration)
                    is UnionType -> union(declaration)
                    is EnumType -> enumType(declaration)
                    else -> throw IllegalArgumentException("${inner.full_name()}: a data port cannot carry it")
                }
            is SequenceType -> IdlType.Sequence(type(inner.elementTypeSpec()), inner.length())
            is ArrayTypeSpec ->
                IdlType.ArrayType(type(inner.elementTypeSpec()), inner.dims[ARRAY_DIMENSION.getInt(inner)])
            is StringType -> IdlType.StringType(inner.isWide(), inner.max?.pos_int_const() ?: 0)
            else -> primitive(inner)
        }

    private fun primitive(spec: TypeSpec): IdlType {
        val kind =
            try {
                spec.getTCKind()
            } catch (e: RuntimeException) {
                throw IllegalArgumentException("${spec.typeName()}: a data port cannot carry it")
            }
        return TypeCodes.read(org.omg.CORBA.ORB.init().get_primitive_tc(org.omg.CORBA.TCKind.from_int(kind)))
    }

    private fun alias(spec: AliasTypeSpec): IdlType.Alias =
        declare(spec.id()) { id ->
            IdlType.Alias(TypeCodes.scopedName(id), id, type(spec.originalType()))
        }

    private fun struct(struct: StructType): IdlType.Struct =
        declare(struct.id()) { id ->
            val members =
                struct.memberlist?.elements()?.toList().orEmpty().map { element ->
                    val member = element as Member
                    IdlType.Member(member.declarator.name(), type(member.type_spec))
                }
            IdlType.Struct(TypeCodes.scopedName(id), id, members)
        }

    private fun enumType(enum: EnumType): IdlType.Enum =
        declare(enum.id()) { id ->
            IdlType.Enum(TypeCodes.scopedName(id), id, enum.enumlist.elements().toList().map { it.toString() })
        }

    private fun union(union: UnionType): IdlType.Union =
        declare(union.id()) { id ->
            val discriminator = type(UNION_SWITCH_TYPE.get(union) as TypeSpec)
            val body = UNION_SWITCH_BODY.get(union) as SwitchBody
            val cases =
                body.caseListVector
                    .map { it as org.jacorb.idl.Case }
                    .map { case ->
                        val labels = case.case_label_list.elements().toList()
                        IdlType.Case(
                            labels.filterNotNull().map { label(it, discriminator) },
                            case.element_spec.declarator.name(),
                            type(case.element_spec.typeSpec),
                        )
                    }
            // A case that lists `default` among its labels is the default whatever else it lists.
            val defaults =
                body.caseListVector
                    .map { it as org.jacorb.idl.Case }
                    .map { it.case_label_list.elements().toList().contains(null) }
            IdlType.Union(
                TypeCodes.scopedName(id),
                id,
                discriminator,
                cases.mapIndexed { index, case ->
                    if (defaults[index]) IdlType.Case(emptyList(), case.name, case.type) else case
                },
            )
        }

    /** A case label as [TypeCodes] reads one: integers as Long, characters, booleans, enumerator names. */
    private fun label(label: Any, discriminator: IdlType): Any {
        if (label is ScopedName) return label.resolvedName().substringAfterLast('.')
        val text = (label as ConstExpr).toString().trim()
        return when (val type = discriminator.resolved) {
            is IdlType.Enum -> text.substringAfterLast("::").substringAfterLast('.')
            IdlType.Primitive.BOOLEAN -> text.equals("TRUE", ignoreCase = true)
            IdlType.Primitive.CHAR,
            IdlType.Primitive.WCHAR -> text.removePrefix("L").trim('\'').single()
            else -> integer(text) ?: throw IllegalArgumentException("${type.name} case label $text: not a whole number")
        }
    }

    private fun integer(text: String): Long? =
        when {
            text.startsWith("0x", ignoreCase = true) -> text.substring(2).toLongOrNull(16)
            text.startsWith("-0x", ignoreCase = true) -> text.substring(3).toLongOrNull(16)?.let { -it }
            else -> text.toLongOrNull()
        }

    /** The type [id] declares, built once; a type that contains itself is refused rather than followed forever. */
    private fun <T : IdlType.Declared> declare(id: String, build: (String) -> T): T {
        @Suppress("UNCHECKED_CAST")
        declared[id]?.let {
            return it as T
        }
        require(building.add(id)) {
            "${TypeCodes.scopedName(id)}: a recursive type, which the simulation cannot make values of"
        }
        try {
            return build(id).also { declared[id] = it }
        } finally {
            building.remove(id)
        }
    }

    private companion object {
        /** Fields JacORB keeps package-private; its own code generator reads them. */
        val UNION_SWITCH_TYPE = UnionType::class.java.getDeclaredField("switch_type_spec").apply { isAccessible = true }
        val UNION_SWITCH_BODY = UnionType::class.java.getDeclaredField("switch_body").apply { isAccessible = true }
        val ARRAY_DIMENSION = ArrayTypeSpec::class.java.getDeclaredField("my_dim").apply { isAccessible = true }
    }
}
