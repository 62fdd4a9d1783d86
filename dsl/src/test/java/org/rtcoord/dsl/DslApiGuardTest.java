package org.rtcoord.dsl;

import org.junit.jupiter.api.Test;
import org.rtcoord.ApiDump;

import java.io.IOException;
import java.util.List;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * Guards the dsl's public API as Java sees it, as core's {@code ApiGuardTest} guards core's: dumped into
 * {@code dsl/api/dsl.api}; no mangled name where Java goes (the Java facade {@code org.rtcoord.dsl.java},
 * the runtime it hands out, the script host), and the facade shows Java no Kotlin type. The vocabulary
 * in {@code org.rtcoord.dsl} is for Kotlin scripts: its suspend handlers, function types and
 * {@code Duration} parameters (mangled for Java) are dumped, not refused. After a deliberate change:
 * {@code mvn -pl dsl -am test -Dtest='*ApiGuardTest' -Dsurefire.failIfNoSpecifiedTests=false -Drtcoord.api.update=true}.
 */
class DslApiGuardTest {
    private static List<Class<?>> publicClasses() {
        return ApiDump.publicClasses(Coordination.class);
    }

    @Test
    void theDumpMatchesThePublicApi() throws IOException {
        ApiDump.assertMatches("dsl", publicClasses());
    }

    @Test
    void javaSeesNoMangledName() {
        List<Class<?>> java = publicClasses().stream().filter(type -> !type.getPackageName().equals("org.rtcoord.dsl")).collect(Collectors.toList());
        assertEquals(List.of(), ApiDump.mangledNames(java));
    }

    @Test
    void theJavaFacadeShowsJavaNoKotlinType() {
        assertEquals(List.of(), ApiDump.kotlinTypesShown(publicClasses(), "org.rtcoord.dsl.java"));
    }
}
