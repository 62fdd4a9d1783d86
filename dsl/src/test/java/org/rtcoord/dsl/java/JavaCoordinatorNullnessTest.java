package org.rtcoord.dsl.java;

import org.junit.jupiter.api.Test;
import org.rtcoord.ApiDump;
import org.rtcoord.JavaNullness;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The dsl's Java facade tells Java's null analysis what may be null ({@link JavaNullness}). */
class JavaCoordinatorNullnessTest {
    @Test
    void theFacadeMarksWhatMayBeNull() throws Exception {
        assertEquals(List.of(), JavaNullness.unmarked(ApiDump.publicClasses(JavaCoordinator.class), "org.rtcoord.dsl.java", JavaCoordinator.class.getClassLoader()));
    }
}
