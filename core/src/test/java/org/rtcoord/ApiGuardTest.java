package org.rtcoord;

import kotlin.jvm.JvmClassMappingKt;
import kotlin.reflect.KVisibility;
import org.junit.jupiter.api.Test;

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
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Guards core's public API as Java sees it (reflection over the compiled classes, so it is what javac
 * sees). The API is dumped into {@code core/api/core.api}: a change that is not in the dump fails the
 * build; after a deliberate change, regenerate it with
 * {@code mvn -pl core test -Dtest=ApiGuardTest -Drtcoord.api.update=true} and commit the file.
 * Besides, every Kotlin-only member (a suspend function, a Kotlin function type, a Flow) has a Java
 * sibling in a facade of {@code org.rtcoord.java}, and those facades show Java no Kotlin type; no
 * mangled name is visible.
 */
class ApiGuardTest {
    private static final Path DUMP = Paths.get("api", "core.api");

    /** The facades that stand in for each class's Kotlin-only members, for Java. */
    private static final Map<String, List<String>> FACADES = Map.ofEntries(
            Map.entry("org.rtcoord.RtcTree", List.of("org.rtcoord.java.JavaTree")),
            Map.entry("org.rtcoord.ComponentNode", List.of("org.rtcoord.java.JavaComponent", "org.rtcoord.java.JavaTree")),
            Map.entry("org.rtcoord.ManagerNode", List.of("org.rtcoord.java.JavaManager", "org.rtcoord.java.JavaTree")),
            Map.entry("org.rtcoord.Port", List.of("org.rtcoord.java.JavaPort")),
            Map.entry("org.rtcoord.ExecutionContextView", List.of("org.rtcoord.java.JavaExecutionContext")),
            Map.entry("org.rtcoord.profile.SystemProfiles", List.of("org.rtcoord.java.JavaSystemProfiles")),
            Map.entry("org.rtcoord.Node", List.of("org.rtcoord.java.JavaTree")),
            Map.entry("org.rtcoord.DirectoryNode", List.of("org.rtcoord.java.JavaTree")),
            Map.entry("org.rtcoord.NamingDirectory", List.of("org.rtcoord.java.JavaTree")),
            Map.entry("org.rtcoord.NameServerNode", List.of("org.rtcoord.java.JavaTree")),
            Map.entry("org.rtcoord.ContextNode", List.of("org.rtcoord.java.JavaTree")),
            Map.entry("org.rtcoord.RootNode", List.of("org.rtcoord.java.JavaTree")),
            Map.entry("org.rtcoord.UnknownNode", List.of("org.rtcoord.java.JavaTree")),
            Map.entry("org.rtcoord.ZombieNode", List.of("org.rtcoord.java.JavaTree")));

    /** Kotlin names whose Java sibling has another name. */
    private static final Map<String, String> SIBLINGS = Map.of(
            "on", "subscribe",
            "events", "subscribe",
            "onWatching", "subscribeWatching",
            "child", "node",
            "data", "tap");

    /** Kotlin-only by design: Java passes a {@code java.util.function.Predicate} to {@code JavaTree.find} instead. */
    private static final Set<String> KOTLIN_ONLY = Set.of("org.rtcoord.NodeFilters");

    @Test
    void theDumpMatchesThePublicApi() throws IOException {
        String dump = publicClasses().stream().map(ApiGuardTest::describe).collect(Collectors.joining("\n"));
        if (Boolean.getBoolean("rtcoord.api.update")) {
            Files.createDirectories(DUMP.getParent());
            Files.writeString(DUMP, dump + "\n", StandardCharsets.UTF_8);
        }
        assertTrue(Files.exists(DUMP), "no API dump at core/" + DUMP + ": run with -Drtcoord.api.update=true and commit it");
        assertEquals(Files.readString(DUMP, StandardCharsets.UTF_8), dump + "\n",
                "core's public API changed: if that is meant, run `mvn -pl core test -Dtest=ApiGuardTest -Drtcoord.api.update=true` and commit core/api/core.api");
    }

    @Test
    void javaSeesNoMangledName() {
        List<String> mangled = new ArrayList<>();
        for (Class<?> type : publicClasses()) {
            for (Method method : visibleMethods(type)) {
                // A data class's copy and componentN of a Duration property; Java reads its getters instead.
                if (method.getName().contains("-") && !method.getName().matches("(copy|component\\d+)-.*")) {
                    mangled.add(type.getName() + "." + method.getName());
                }
            }
        }
        assertEquals(List.of(), mangled);
    }

    @Test
    void everyKotlinOnlyMemberHasAJavaSibling() throws ClassNotFoundException {
        List<String> missing = new ArrayList<>();
        for (Class<?> type : publicClasses()) {
            if (type.getPackageName().equals("org.rtcoord.java") || KOTLIN_ONLY.contains(type.getName())) continue;
            for (Method method : visibleMethods(type)) {
                boolean suspending = Arrays.stream(method.getParameterTypes()).anyMatch(p -> p.getName().equals("kotlin.coroutines.Continuation"));
                boolean kotlinTyped = Stream.concat(Arrays.stream(method.getParameterTypes()), Stream.of(method.getReturnType()))
                        .anyMatch(p -> p.getName().startsWith("kotlin.jvm.functions.") || p.getName().startsWith("kotlinx.coroutines.flow.Flow"));
                if (!suspending && !kotlinTyped) continue;
                String sibling = SIBLINGS.getOrDefault(method.getName(), method.getName());
                boolean found = false;
                for (String facade : FACADES.getOrDefault(type.getName(), List.of())) {
                    Set<String> names = visibleMethods(Class.forName(facade)).stream().map(Method::getName).collect(Collectors.toSet());
                    found |= names.contains(sibling) && (!suspending || names.contains(sibling + "Async"));
                }
                if (!found) missing.add(type.getName() + "." + method.getName() + " (wants " + sibling + (suspending ? " and " + sibling + "Async" : "") + " in a facade)");
            }
        }
        assertEquals(List.of(), missing.stream().distinct().sorted().collect(Collectors.toList()));
    }

    @Test
    void theFacadesShowJavaNoKotlinType() {
        List<String> kotlin = new ArrayList<>();
        for (Class<?> type : publicClasses()) {
            if (!type.getPackageName().equals("org.rtcoord.java")) continue;
            for (Method method : visibleMethods(type)) {
                if (method.toGenericString().matches(".*\\bkotlin\\..*")) kotlin.add(method.toGenericString());
            }
        }
        assertEquals(List.of(), kotlin);
    }

    /** Core's public classes outside internal packages, by name, as loaded from its class directory or jar. */
    private static List<Class<?>> publicClasses() {
        try {
            Path root = Paths.get(RtcTree.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            try (Stream<Path> files = Files.walk(root)) {
                List<Class<?>> classes = new ArrayList<>();
                for (Path file : files.filter(f -> f.toString().endsWith(".class")).sorted().collect(Collectors.toList())) {
                    String name = root.relativize(file).toString().replace(java.io.File.separatorChar, '.').replaceAll("\\.class$", "");
                    if (name.contains(".internal.") || name.endsWith("module-info")) continue;
                    Class<?> type = Class.forName(name, false, ApiGuardTest.class.getClassLoader());
                    if (isVisible(type)) classes.add(type);
                }
                return classes;
            }
        } catch (IOException | URISyntaxException | ClassNotFoundException e) {
            throw new IllegalStateException("cannot read core's classes: " + e, e);
        }
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

    private static List<Method> visibleMethods(Class<?> type) {
        return Arrays.stream(type.getDeclaredMethods())
                .filter(m -> isVisible(m.getModifiers()) && !m.isSynthetic() && !m.isBridge() && !isKotlinInternal(m))
                .collect(Collectors.toList());
    }

    /** One class and its visible members, one per line, sorted: what javac can use. */
    private static String describe(Class<?> type) {
        TreeMap<String, String> members = new TreeMap<>();
        for (Constructor<?> constructor : type.getDeclaredConstructors()) {
            if (isVisible(constructor.getModifiers()) && !constructor.isSynthetic() && !isKotlinInternal(constructor)) members.put(signature(constructor), "");
        }
        for (Method method : visibleMethods(type)) members.put(signature(method), "");
        for (Field field : type.getDeclaredFields()) {
            if (isVisible(field.getModifiers()) && !field.isSynthetic()) members.put(field.toGenericString(), "");
        }
        StringBuilder text = new StringBuilder(header(type)).append(" {\n");
        members.keySet().forEach(member -> text.append("  ").append(member).append('\n'));
        return text.append("}").toString();
    }

    private static String signature(Executable member) {
        return member.toGenericString();
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
