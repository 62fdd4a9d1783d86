package org.rtcoord;

import java.io.File;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.spi.ToolProvider;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * What {@code javap} shows a Java tool of the API it uses: starting from a module's Java facades, every
 * rtcoord class their public signatures reach, and in each the lines that show Kotlin ({@code kotlin.},
 * a {@code Continuation}, a {@code Companion}, a mangled name), among the members javac lets Java use
 * (not the synthetic ones, nor those Kotlin's metadata says are internal). Core's {@code JavaSurfaceTest}
 * and the dsl's share it.
 *
 * Two things Kotlin always compiles are not counted, since no annotation or compiler option takes them
 * away and Java never needs them: the {@code Companion} field of a companion whose every member Java
 * reaches as a static of the outer class ({@code @JvmStatic}, {@code @JvmField}); and the
 * {@code getEntries()} Kotlin 1.9 and later gives every enum (Kotlin 2.3 refuses
 * {@code -XXLanguage:-EnumEntries}), beside which Java has {@code values()}.
 */
public final class JavaSurface {
    private static final Pattern RTCOORD_TYPE = Pattern.compile("\\borg\\.rtcoord\\.[\\w.$]*[\\w$]");
    private static final Pattern KOTLIN = Pattern.compile("\\bkotlin\\.|\\bkotlinx\\.|Continuation|Companion|\\b[\\w$]+-[\\w-]+\\(");
    private static final Pattern DECLARATION_NAME = Pattern.compile("([\\w$-]+)\\(|([\\w$]+);$");
    private static final Pattern ENUM_ENTRIES = Pattern.compile("public static kotlin\\.enums\\.EnumEntries<[\\w.$]+> getEntries\\(\\);");

    private JavaSurface() {
    }

    /**
     * The classes reached from the top-level classes of [facadePackage] (in the class directory [anchor]
     * was loaded from) that show Java Kotlin, each with the javap lines that do.
     */
    public static Map<String, List<String>> kotlinShown(Class<?> anchor, String facadePackage) throws Exception {
        Path classes = location(anchor);
        String classPath = Stream.of(classes, location(RtcTree.class)).distinct().map(Path::toString).collect(Collectors.joining(File.pathSeparator));
        Deque<String> pending = new ArrayDeque<>(facades(classes, facadePackage));
        Set<String> seen = new HashSet<>();
        Map<String, List<String>> kotlin = new TreeMap<>();
        while (!pending.isEmpty()) {
            String name = pending.pop();
            if (!seen.add(name) || name.contains(".internal.")) continue;
            Class<?> type = Class.forName(name, false, anchor.getClassLoader());
            if (!ApiDump.isVisible(type)) continue;
            Set<String> usable = ApiDump.javaUsableMembers(type);
            usable.removeAll(kotlinResidue(type));
            String[] lines = javap(classPath, name).split("\n");
            for (int i = 0; i < lines.length; i++) {
                String line = lines[i].trim();
                boolean member = i + 1 < lines.length && lines[i + 1].trim().startsWith("descriptor: ");
                if (member && !usable.contains(key(type, line, lines[i + 1].trim().substring("descriptor: ".length())))) continue;
                if (!member && !line.contains(" class ") && !line.contains(" interface ")) continue;
                if (type.isEnum() && ENUM_ENTRIES.matcher(line).matches()) continue;
                if (KOTLIN.matcher(line).find()) kotlin.computeIfAbsent(name, k -> new ArrayList<>()).add(line);
                Matcher reached = RTCOORD_TYPE.matcher(line);
                while (reached.find()) pending.add(reached.group());
            }
        }
        return kotlin;
    }

    /** The {@code Companion} field of [type] when Java reaches all its companion offers as statics of [type]. */
    private static Set<String> kotlinResidue(Class<?> type) {
        for (Class<?> nested : type.getDeclaredClasses()) {
            if (!nested.getSimpleName().equals("Companion")) continue;
            for (Method method : ApiDump.visibleMethods(nested)) {
                try {
                    Method twin = type.getDeclaredMethod(method.getName(), method.getParameterTypes());
                    if (!Modifier.isStatic(twin.getModifiers())) return Set.of();
                } catch (NoSuchMethodException e) {
                    return Set.of();
                }
            }
            boolean fieldsOnCompanion = Arrays.stream(nested.getDeclaredFields()).anyMatch(f -> Modifier.isPublic(f.getModifiers()) && !f.isSynthetic());
            return fieldsOnCompanion ? Set.of() : Set.of("Companion");
        }
        return Set.of();
    }

    /** How {@link ApiDump#javaUsableMembers} names the member javap declared in [line] with [descriptor]. */
    private static String key(Class<?> type, String line, String descriptor) {
        Matcher name = DECLARATION_NAME.matcher(line);
        if (!name.find()) return line;
        if (name.group(2) != null) return name.group(2);
        String method = name.group(1);
        String simpleName = type.getName().substring(type.getName().lastIndexOf('.') + 1);
        return (method.equals(simpleName) ? "<init>" : method) + descriptor;
    }

    /** The top-level classes of [facadePackage] under [classes], by binary name. */
    private static List<String> facades(Path classes, String facadePackage) throws Exception {
        List<String> names = new ArrayList<>();
        try (Stream<Path> files = Files.list(classes.resolve(facadePackage.replace('.', '/')))) {
            files.map(f -> f.getFileName().toString())
                    .filter(f -> f.endsWith(".class") && !f.contains("$") && !f.equals("package-info.class"))
                    .sorted()
                    .forEach(f -> names.add(facadePackage + "." + f.replaceAll("\\.class$", "")));
        }
        return names;
    }

    private static Path location(Class<?> type) throws Exception {
        return Paths.get(type.getProtectionDomain().getCodeSource().getLocation().toURI());
    }

    /** javap's listing of the public members of [name], each line followed by its descriptor. */
    private static String javap(String classPath, String name) {
        StringWriter out = new StringWriter();
        int status = ToolProvider.findFirst("javap").orElseThrow()
                .run(new PrintWriter(out), new PrintWriter(out), "-public", "-s", "-cp", classPath, name);
        if (status != 0) throw new IllegalStateException("javap " + name + " failed: " + out);
        return out.toString();
    }
}
