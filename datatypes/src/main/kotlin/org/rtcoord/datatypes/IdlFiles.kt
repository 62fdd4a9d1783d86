package org.rtcoord.datatypes

import java.nio.file.Files
import java.nio.file.Path
import java.util.logging.Handler
import java.util.logging.Level
import java.util.logging.LogRecord
import java.util.logging.Logger
import org.jacorb.idl.IDLTreeVisitor
import org.jacorb.idl.Spec
import org.jacorb.idl.parser

/**
 * Reads users' IDL at run time with JacORB's IDL compiler (its parser only: no code is generated): every struct, union,
 * enum and typedef the files declare, in nested modules and included files too. The standard data types' IDL
 * ([StandardDataTypes.FILES]) is on the include path, so a file can `#include "BasicDataType.idl"` for `RTC::Time` as
 * OpenRTM-aist's own IDL does.
 *
 * JacORB's parser keeps its state in static fields: one file is parsed at a time, in the whole JVM.
 */
public object IdlFiles {
    /**
     * The types the `.idl` files of [directories] declare (subdirectories left out), every directory on the include
     * path. A directory that is missing or holds no IDL, and a file that does not parse, are [IdlDefinitions.errors];
     * the other files' types are read all the same.
     */
    @JvmStatic
    public fun readDirectories(directories: List<Path>): IdlDefinitions {
        val errors = mutableListOf<String>()
        val files = directories.flatMap { directory ->
            val found =
                if (Files.isDirectory(directory)) {
                    Files.list(directory).use { paths ->
                        paths.filter { it.toString().endsWith(".idl") }.sorted().toList()
                    }
                } else {
                    errors += "$directory: not a directory"
                    emptyList()
                }
            if (found.isEmpty() && Files.isDirectory(directory)) errors += "$directory: no .idl file in it"
            found
        }
        val read = read(files, directories)
        return IdlDefinitions(read.types, errors + read.errors)
    }

    /** [readDirectories] of one directory. */
    @JvmStatic public fun readDirectory(directory: Path): IdlDefinitions = readDirectories(listOf(directory))

    /**
     * The types [files] declare, parsed with [includeDirectories] (then the standard types' IDL) on the include path; a
     * file that does not parse is one of the [IdlDefinitions.errors], the others are read.
     */
    @JvmStatic
    public fun read(files: List<Path>, includeDirectories: List<Path> = emptyList()): IdlDefinitions {
        val types = LinkedHashMap<String, IdlType.Declared>()
        val errors = mutableListOf<String>()
        for (file in files) {
            val reader = IdlTypeReader()
            try {
                parse(file, includeDirectories) { spec ->
                    try {
                        reader.definitions(spec.definitions.elements())
                    } catch (e: IllegalArgumentException) {
                        throw IdlException("$file: ${e.message}")
                    }
                }
                reader.declared.forEach { (id, type) -> types.putIfAbsent(id, type) }
            } catch (e: IdlException) {
                errors += e.message.orEmpty()
            }
        }
        return IdlDefinitions(types, errors)
    }

    private val standardIncludes: Path by lazy {
        val directory = Files.createTempDirectory("rtcoord-idl").toAbsolutePath()
        for (name in StandardDataTypes.FILES) {
            val target = directory.resolve(name)
            IdlFiles::class.java.classLoader.getResourceAsStream("${StandardDataTypes.RESOURCE_DIRECTORY}/$name").use {
                input ->
                checkNotNull(input) { "$name is missing from the class path (the rtcoord-idl jar)" }
                Files.copy(input, target)
            }
            target.toFile().deleteOnExit()
        }
        directory.toFile().deleteOnExit()
        directory
    }

    /** Parses [file] and hands its resolved syntax tree to [read], on the parser's lock. */
    private fun parse(file: Path, includeDirectories: List<Path>, read: (Spec) -> Unit) {
        if (!Files.isRegularFile(file)) throw IdlException("$file: no such file")
        val errors = ErrorCollector(file)
        synchronized(parser::class.java) {
            val logger =
                Logger.getAnonymousLogger().apply {
                    useParentHandlers = false
                    level = Level.WARNING
                    addHandler(errors)
                }
            parser.logger = logger
            // The lexer counts lines in a static field that nothing resets between files.
            LEXER_LINE.setInt(null, 1)
            var failure: Throwable? = null
            parser.setGenerator(SpecVisitor { spec -> failure = runCatching { read(spec) }.exceptionOrNull() })
            val arguments = (includeDirectories + listOf(standardIncludes)).map { "-I$it" } + file.toString()
            try {
                parser.compile(arguments.toTypedArray())
            } catch (e: IdlException) {
                throw e
            } catch (e: Exception) {
                throw IdlException(errors.first()?.let { "$it" } ?: "$file: ${e.message ?: e.javaClass.simpleName}")
            } finally {
                parser.logger = null
            }
            failure?.let { throw it }
            errors.first()?.let { throw IdlException(it) }
        }
    }

    /**
     * The parser's first error, as `file:line: reason` on one line, the [parsed] file named by the path it was given
     * as.
     */
    private class ErrorCollector(private val parsed: Path) : Handler() {
        private val messages = mutableListOf<String>()

        override fun publish(record: LogRecord) {
            if (record.level.intValue() >= Level.SEVERE.intValue()) messages += oneLine(record.message.orEmpty())
        }

        fun first(): String? = messages.firstOrNull()

        override fun flush() = Unit

        override fun close() = Unit

        /** JacORB writes `FILE, line: N(COLUMN): REASON` and the line's text below it. */
        private fun oneLine(message: String): String {
            val first = message.lineSequence().first().removeSuffix(" Can't recover from previous error(s), giving up.")
            val located = LOCATION.find(first) ?: return first
            val (file, line, reason) = located.destructured
            val named = if (file == parsed.fileName.toString()) parsed.toString() else file
            return "$named:$line: ${reason.trim()}"
        }
    }

    private val LEXER_LINE =
        org.jacorb.idl.lexer::class.java.getDeclaredField("current_line").apply { isAccessible = true }

    /** JacORB's position prefix, `/path/file.idl, line: 12(5): `; its own format, not IDL. */
    private val LOCATION = Regex("""^(.*?), line: ?(\d+)\(\d+\): (.*)$""")

    /** A code generator that generates nothing: it hands the resolved syntax tree on. */
    private class SpecVisitor(private val spec: (Spec) -> Unit) : IDLTreeVisitor {
        override fun visitSpec(spec: Spec) = spec(spec)

        override fun visitModule(mod: org.jacorb.idl.Module) = Unit

        override fun visitInterface(intf: org.jacorb.idl.Interface) = Unit

        override fun visitInterfaceBody(body: org.jacorb.idl.InterfaceBody) = Unit

        override fun visitDefinitions(defs: org.jacorb.idl.Definitions) = Unit

        override fun visitDefinition(def: org.jacorb.idl.Definition) = Unit

        override fun visitDeclaration(decl: org.jacorb.idl.Declaration) = Unit

        override fun visitOpDecl(decl: org.jacorb.idl.OpDecl) = Unit

        override fun visitMethod(m: org.jacorb.idl.Method) = Unit

        override fun visitParamDecl(param: org.jacorb.idl.ParamDecl) = Unit

        override fun visitStruct(struct: org.jacorb.idl.StructType) = Unit

        override fun visitUnion(union: org.jacorb.idl.UnionType) = Unit

        override fun visitEnum(enumType: org.jacorb.idl.EnumType) = Unit

        override fun visitNative(_native: org.jacorb.idl.NativeType) = Unit

        override fun visitTypeDef(typedef: org.jacorb.idl.TypeDef) = Unit

        override fun visitAlias(alias: org.jacorb.idl.AliasTypeSpec) = Unit

        override fun visitValue(value: org.jacorb.idl.Value) = Unit

        override fun visitTypeDeclaration(typeDecl: org.jacorb.idl.TypeDeclaration) = Unit

        override fun visitConstrTypeSpec(typeDecl: org.jacorb.idl.ConstrTypeSpec) = Unit

        override fun visitSimpleTypeSpec(typeDecl: org.jacorb.idl.SimpleTypeSpec) = Unit

        override fun visitVectorType(typeDecl: org.jacorb.idl.VectorType) = Unit
    }
}

/** What a set of IDL files declares: its data types, by repository ID, and what could not be read. */
public class IdlDefinitions(types: Map<String, IdlType.Declared>, errors: List<String> = emptyList()) {
    /** Every struct, union, enum and typedef, by repository ID, in declaration order. */
    public val types: Map<String, IdlType.Declared> = types.toMap()

    /** One line for each file or directory that could not be read: `file:line: reason`. */
    public val errors: List<String> = errors.toList()

    /** The type [name] (a repository ID, `Module::Type`, or a name in module RTC) means, or null. */
    public fun named(name: String): IdlType? = types[DataTypeName.repositoryId(name)]
}

/** IDL that cannot be read: the message names the file, the line where known, and the reason, on one line. */
internal class IdlException(message: String) : Exception(message)
