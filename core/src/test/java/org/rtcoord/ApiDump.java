package org.rtcoord;

import kotlin.jvm.JvmClassMappingKt;
import kotlin.reflect.KVisibility;

import java.io.IOException;
import java.lang.reflect.Constructor;
import java.lang.reflect.Executable;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.TreeMap;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A module's public API as Java sees it (reflection over the compiled classes, so it is what javac
 * sees), dumped one class and its members a block, and compared with the dump checked in at
 * {@code <module>/api/<module>.api}. Core's {@link ApiGuardTest} and the dsl's API guard share it (the
 * dsl through core's test jar). With {@code -Drtcoord.api.update=true} the dump is rewritten instead.
 */
public final class ApiDump {
    private ApiDump() {
    }

    /** Fails unless {@code api/<module>.api} (relative to the module's directory) holds [classes]' API. */
    public static void assertMatches(String module, List<Class<?>> classes) throws IOException {
        Path dump = Paths.get("api", module + ".api");
        String text = classes.stream().map(ApiDump::describe).collect(Collectors.joining("\n")) + "\n";
        String update = "mvn -pl " + module + " -am test -Dtest='*ApiGuardTest' -Dsurefire.failIfNoSpecifiedTests=false -Drtcoord.api.update=true";
        if (Boolean.getBoolean("rtcoord.api.update")) {
            Files.createDirectories(dump.getParent());
            Files.writeString(dump, text, StandardCharsets.UTF_8);
        }
        assertTrue(Files.exists(dump), "no API dump at " + module + "/" + dump + ": run `" + update + "` and commit it");
        assertEquals(Files.readString(dump, StandardCharsets.UTF_8), text,
                module + "'s public API changed: if that is meant, run `" + update + "` and commit " + module + "/" + dump);
    }

    /** The public classes outside internal packages in the class directory or jar [anchor] was loaded from. */
    public static List<Class<?>> publicClasses(Class<?> anchor) {
        try {
            Path root = Paths.get(anchor.getProtectionDomain().getCodeSource().getLocation().toURI());
            try (Stream<Path> files = Files.walk(root)) {
                List<Class<?>> classes = new ArrayList<>();
                for (Path file : files.filter(f -> f.toString().endsWith(".class")).sorted().collect(Collectors.toList())) {
                    String name = root.relativize(file).toString().replace(java.io.File.separatorChar, '.').replaceAll("\\.class$", "");
                    if (name.contains(".internal.") || name.endsWith("module-info")) continue;
                    Class<?> type = Class.forName(name, false, anchor.getClassLoader());
                    if (isVisible(type)) classes.add(type);
                }
                return classes;
            }
        } catch (IOException | URISyntaxException | ClassNotFoundException e) {
            throw new IllegalStateException("cannot read the classes beside " + anchor.getName() + ": " + e, e);
        }
    }

    /** Visible methods whose names Kotlin mangled, but for a data class's copy and componentN (Java reads the getters). */
    public static List<String> mangledNames(List<Class<?>> classes) {
        List<String> mangled = new ArrayList<>();
        for (Class<?> type : classes) {
            for (Method method : visibleMethods(type)) {
                if (method.getName().contains("-") && !method.getName().matches("(copy|component\\d+)-.*")) {
                    mangled.add(type.getName() + "." + method.getName());
                }
            }
        }
        return mangled;
    }

    /** The visible methods of the classes of [packageName] that show Java a Kotlin type (a Continuation, Unit, a function type). */
    public static List<String> kotlinTypesShown(List<Class<?>> classes, String packageName) {
        List<String> kotlin = new ArrayList<>();
        for (Class<?> type : classes) {
            if (!type.getPackageName().equals(packageName)) continue;
            for (Method method : visibleMethods(type)) {
                if (method.toGenericString().matches(".*\\bkotlin\\..*")) kotlin.add(method.toGenericString());
            }
        }
        return kotlin;
    }

    /** Public to Java and, for a Kotlin class, not `internal` (which the bytecode leaves public). */
    private static boolean isVisible(Class<?> type) {
        for (Class<?> t = type; t != null; t = t.getDeclaringClass()) {
            if (!Modifier.isPublic(t.getModifiers()) || t.isSynthetic() || t.isAnonymousClass() || t.isLocalClass()) return false;
            if (t.isAnnotationPresent(kotlin.Metadata.class) && JvmClassMappingKt.getKotlinClass(t).getVisibility() != KVisibility.PUBLIC) return false;
        }
        return true;
    }

    private static boolean isVisible(int modifiers) {
        return Modifier.isPublic(modifiers) || Modifier.isProtected(modifiers);
    }

    /** Kotlin's `internal` members keep public bytecode but get a `$module` suffix, or take internal types. */
    private static boolean isKotlinInternal(Executable member) {
        return member.getName().contains("$") || member.toGenericString().contains(".internal.");
    }

    /** The methods of [type] Java can call. */
    public static List<Method> visibleMethods(Class<?> type) {
        return Arrays.stream(type.getDeclaredMethods())
                .filter(m -> isVisible(m.getModifiers()) && !m.isSynthetic() && !m.isBridge() && !isKotlinInternal(m))
                .collect(Collectors.toList());
    }

    /** One class and its visible members, one per line, sorted: what javac can use. */
    private static String describe(Class<?> type) {
        TreeMap<String, String> members = new TreeMap<>();
        for (Constructor<?> constructor : type.getDeclaredConstructors()) {
            if (isVisible(constructor.getModifiers()) && !constructor.isSynthetic() && !isKotlinInternal(constructor)) members.put(constructor.toGenericString(), "");
        }
        for (Method method : visibleMethods(type)) members.put(method.toGenericString(), "");
        for (Field field : type.getDeclaredFields()) {
            if (isVisible(field.getModifiers()) && !field.isSynthetic()) members.put(field.toGenericString(), "");
        }
        StringBuilder text = new StringBuilder(header(type)).append(" {\n");
        members.keySet().forEach(member -> text.append("  ").append(member).append('\n'));
        return text.append("}").toString();
    }

    private static String header(Class<?> type) {
        String kind = type.isInterface() ? "interface" : type.isEnum() ? "enum" : "class";
        StringBuilder text = new StringBuilder(Modifier.toString(type.getModifiers() & ~Modifier.INTERFACE)).append(' ').append(kind).append(' ').append(type.getName());
        if (type.getGenericSuperclass() != null && type.getSuperclass() != Object.class && !type.isEnum()) text.append(" extends ").append(type.getGenericSuperclass().getTypeName());
        if (type.getGenericInterfaces().length > 0) {
            text.append(" implements ").append(Arrays.stream(type.getGenericInterfaces()).map(java.lang.reflect.Type::getTypeName).collect(Collectors.joining(", ")));
        }
        return text.toString();
    }
}
