package org.rtcoord.dsl.java;

import org.junit.jupiter.api.Test;
import org.rtcoord.JavaSurface;

import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * What {@code javap} shows a Java tool of the dsl's Java facade ({@link JavaSurface}): {@link JavaCoordinator}
 * and every rtcoord class its public signatures reach show no Kotlin type (a {@code StateFlow}, a
 * {@code kotlin.time.Duration}), no {@code Continuation}, no {@code Companion} and no mangled name.
 */
class JavaCoordinatorSurfaceTest {
    @Test
    void javapShowsNoKotlinInWhatTheFacadeReaches() throws Exception {
        assertEquals(Map.of(), JavaSurface.kotlinShown(JavaCoordinator.class, "org.rtcoord.dsl.java"));
    }
}
