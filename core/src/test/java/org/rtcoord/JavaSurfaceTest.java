package org.rtcoord;

import org.junit.jupiter.api.Test;

import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * What {@code javap} shows a Java tool of core's API ({@link JavaSurface}): the facades of
 * {@code org.rtcoord.java}, and every rtcoord class their public signatures reach, show no Kotlin type,
 * no {@code Continuation}, no {@code Companion} and no mangled name.
 */
class JavaSurfaceTest {
    @Test
    void javapShowsNoKotlinInWhatTheFacadesReach() throws Exception {
        assertEquals(Map.of(), JavaSurface.kotlinShown(RtcTree.class, "org.rtcoord.java"));
    }
}
