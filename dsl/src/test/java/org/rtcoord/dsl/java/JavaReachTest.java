package org.rtcoord.dsl.java;

import org.junit.jupiter.api.Test;
import org.rtcoord.JavaReach;
import org.rtcoord.RtcTree;

import java.util.List;

/**
 * What javac lets a Java tool use of rtcoord ({@link JavaReach}): the three Java-facing packages,
 * {@code org.rtcoord.java}, {@code org.rtcoord.profile} and {@code org.rtcoord.dsl.java}, and every
 * rtcoord type they return, take, throw or extend, transitively, show no Kotlin type, no internal member,
 * no {@code Companion} field and no CORBA type: any leak fails the build, and none is tolerated.
 */
class JavaReachTest {
    @Test
    void javacReachesNoKotlinNoInternalsAndNoCorba() throws Exception {
        JavaReach.assertNone(List.of(RtcTree.class, JavaCoordinator.class), List.of("org.rtcoord.java", "org.rtcoord.profile", "org.rtcoord.dsl.java"));
    }
}
