package org.rtcoord;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * What javac lets a Java tool use of core ({@link JavaReach}): {@code org.rtcoord.java},
 * {@code org.rtcoord.profile} and every rtcoord type they reach show no Kotlin type, no internal member,
 * no {@code Companion} field and no CORBA type: any leak fails, and none is tolerated. The dsl's
 * {@code JavaReachTest} scans the dsl's facade with them.
 */
class JavaSurfaceTest {
    @Test
    void javacReachesNoKotlinNoInternalsAndNoCorbaFromCoresFacades() throws Exception {
        JavaReach.assertNone(List.of(RtcTree.class), List.of("org.rtcoord.java", "org.rtcoord.profile"));
    }

    /** The scan finds each kind of leak, in a package made of them (core's Kotlin tests, {@code org.rtcoord.leaky}, beside this class). */
    @Test
    void theScanFindsEachKindOfLeak() throws Exception {
        List<String> leaks = JavaReach.leaks(List.of(JavaSurfaceTest.class), List.of("org.rtcoord.leaky"));
        String all = String.join("\n", leaks);
        for (String expected : List.of(
                "org.rtcoord.leaky.Leaky.Companion: a Companion field",
                "org.rtcoord.leaky.Leaky.getCount$: a name Kotlin made for itself",
                "org.rtcoord.leaky.Leaky.<init>(int): internal in Kotlin, usable by javac",
                "org.rtcoord.leaky.Leaky.await(Continuation): names Kotlin's kotlin.coroutines.Continuation",
                "org.rtcoord.leaky.Leaky.state(): names CORBA's RTC.LifeCycleState",
                "org.rtcoord.leaky.Leaky.fields(): names rtcoord's internal org.rtcoord.internal.ValueFields",
                "org.rtcoord.leaky.Leaky.getFlow(): names Kotlin's kotlinx.coroutines.flow.Flow",
                "org.rtcoord.leaky.Hidden: javac can use this class, which Kotlin keeps internal or made for itself")) {
            // The module name Kotlin puts in an internal member's name is left out: it is the test compilation's.
            String[] parts = expected.split("\\$: ", 2);
            boolean found = parts.length == 1 ? leaks.contains(expected) : leaks.stream().anyMatch(l -> l.startsWith(parts[0] + "$") && l.endsWith(parts[1]));
            assertTrue(found, "the scan missed " + expected + " in:\n" + all);
        }
    }
}
