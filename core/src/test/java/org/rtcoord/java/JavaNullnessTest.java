package org.rtcoord.java;

import org.junit.jupiter.api.Test;
import org.rtcoord.ApiDump;
import org.rtcoord.JavaNullness;
import org.rtcoord.RtcTree;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The Java-facing packages tell Java's null analysis what may be null ({@link JavaNullness}). */
class JavaNullnessTest {
    @Test
    void theFacadesMarkWhatMayBeNull() throws Exception {
        assertEquals(List.of(), JavaNullness.unmarked(ApiDump.publicClasses(RtcTree.class), "org.rtcoord.java", RtcTree.class.getClassLoader()));
    }

    @Test
    void profilesMarkWhatMayBeNull() throws Exception {
        assertEquals(List.of(), JavaNullness.unmarked(ApiDump.publicClasses(RtcTree.class), "org.rtcoord.profile", RtcTree.class.getClassLoader()));
    }
}
