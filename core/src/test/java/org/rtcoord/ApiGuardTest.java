package org.rtcoord;

import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.rtcoord.ApiDump.visibleMethods;

/**
 * Guards core's public API as Java sees it ({@link ApiDump}). The API is dumped into
 * {@code core/api/core.api}: a change that is not in the dump fails the build; after a deliberate
 * change, regenerate it with {@code mvn -pl core test -Dtest=ApiGuardTest -Drtcoord.api.update=true}
 * and commit the file.
 * Besides, every Kotlin-only member (a suspend function, a Kotlin function type, a Flow), visible to Java
 * or hidden from it with {@code @JvmSynthetic}, has a Java sibling in a facade of {@code org.rtcoord.java}, and those facades show Java no Kotlin type; no
 * mangled name is visible.
 */
class ApiGuardTest {
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
        ApiDump.assertMatches("core", publicClasses());
    }

    @Test
    void javaSeesNoMangledName() {
        assertEquals(List.of(), ApiDump.mangledNames(publicClasses()));
    }

    @Test
    void everyKotlinOnlyMemberHasAJavaSibling() throws ClassNotFoundException {
        List<String> missing = new ArrayList<>();
        for (Class<?> type : publicClasses()) {
            if (type.getPackageName().equals("org.rtcoord.java") || KOTLIN_ONLY.contains(type.getName())) continue;
            for (Method method : ApiDump.kotlinCallableMethods(type)) {
                boolean suspending = Arrays.stream(method.getParameterTypes()).anyMatch(p -> p.getName().equals("kotlin.coroutines.Continuation"));
                boolean kotlinTyped = Stream.concat(Arrays.stream(method.getParameterTypes()), Stream.of(method.getReturnType()))
                        .anyMatch(p -> p.getName().startsWith("kotlin.jvm.functions.") || p.getName().startsWith("kotlinx.coroutines.flow.Flow"));
                if (!suspending && !kotlinTyped) continue;
                // A mangled name (`activate-Kx4hsE0`, Kotlin-only) has its Java sibling under the plain name.
                String name = method.getName().replaceFirst("-.*", "");
                String sibling = SIBLINGS.getOrDefault(name, name);
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
        assertEquals(List.of(), ApiDump.kotlinTypesShown(publicClasses(), "org.rtcoord.java"));
    }

    private static List<Class<?>> publicClasses() {
        return ApiDump.publicClasses(RtcTree.class);
    }
}
