package org.rtcoord.idl

/**
 * The canonical description of a set of IDL declarations, as the `canon` omniidl back end prints it: for each scoped
 * name, its fields (kind, repository id, members, operations, ...) and their values.
 */
internal class IdlListing(val declarations: Map<String, Map<String, String>>) {

    /**
     * One line per difference between this listing and [reference], for every declaration this listing holds;
     * declarations only the reference has are ignored. Names in [extras] are allowed to be missing from the reference.
     */
    fun differencesFrom(reference: IdlListing, extras: Set<String> = emptySet()): List<String> =
        declarations.flatMap { (name, ours) ->
            val theirs = reference.declarations[name]
            when {
                theirs != null ->
                    (ours.keys + theirs.keys).sorted().mapNotNull { field ->
                        val mine = ours[field]
                        val other = theirs[field]
                        when {
                            mine == other -> null
                            mine == null -> "$name: $field: missing here, reference has `$other`"
                            other == null -> "$name: $field: `$mine` is not in the reference"
                            else -> "$name: $field: `$mine` differs from the reference `$other`"
                        }
                    }
                name in extras -> emptyList()
                else -> listOf("$name: not declared by the reference IDL")
            }
        }

    companion object {
        /** Parses `name<TAB>field<TAB>value` lines. */
        fun parse(lines: Iterable<String>): IdlListing {
            val declarations = sortedMapOf<String, MutableMap<String, String>>()
            for (line in lines.filter { it.isNotBlank() }) {
                val parts = line.split('\t')
                require(parts.size == 3) { "not a listing line: $line" }
                val (name, field, value) = parts
                declarations.getOrPut(name) { sortedMapOf() }[field] = value
            }
            return IdlListing(declarations)
        }
    }
}
