package org.rtcoord.datatypes

/** A type written out whole, every declared type it uses expanded once: two models compare as text. */
internal fun IdlType.describe(seen: MutableSet<String> = mutableSetOf()): String =
    when (this) {
        is IdlType.Primitive,
        is IdlType.StringType -> name
        is IdlType.Sequence -> "sequence<${element.describe(seen)}, $bound>"
        is IdlType.ArrayType -> "${element.describe(seen)}[$length]"
        is IdlType.Declared ->
            if (!seen.add(repositoryId)) repositoryId
            else
                when (this) {
                    is IdlType.Struct ->
                        "struct $repositoryId $name {${members.joinToString("; ") { "${it.type.describe(seen)} ${it.name}" }}}"
                    is IdlType.Enum -> "enum $repositoryId $name {${enumerators.joinToString()}}"
                    is IdlType.Union ->
                        "union $repositoryId $name switch(${discriminator.describe(seen)}) {" +
                            cases.joinToString("; ") {
                                "${if (it.isDefault) "default" else it.labels.joinToString()}: ${it.type.describe(seen)} ${it.name}"
                            } +
                            "}"
                    is IdlType.Alias -> "typedef $repositoryId $name ${type.describe(seen)}"
                }
    }
