package org.rtcoord.osgi;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The bundle's javadoc is written for Java: signatures as javac sees them, only the API, nothing of Kotlin's
 * machinery; and its sources jar has the Java view an IDE shows on hover. The javadoc is built before the
 * tests (process-test-classes) by a build with -Ddocs (CI's second step); without it, this is skipped.
 */
class BundleJavadocTest {
    /** Given when the build makes the javadoc (-Ddocs). */
    private static final String API_DOCS_PROPERTY = System.getProperty("rtcoord.apidocs");
    /** The packages written for Java callers; the others are Kotlin's, where a suspend function takes a continuation. */
    private static final Pattern JAVA_FACING = Pattern.compile("org/rtcoord/(java|profile|dsl/java)/[^/]+\\.html");
    private static final Path SOURCES = Path.of(System.getProperty("rtcoord.bundleSources", "target/bundle-sources"));

    private static Path apiDocs;

    @BeforeAll
    static void built() {
        assumeTrue(API_DOCS_PROPERTY != null, "the javadoc is built with -Ddocs");
        apiDocs = Path.of(API_DOCS_PROPERTY);
        assertTrue(Files.isDirectory(apiDocs.resolve("org/rtcoord")), "no javadoc in " + apiDocs);
    }

    @Test
    void signaturesAreJava() throws IOException {
        String component = text("org/rtcoord/java/JavaComponent.html");
        assertTrue(Pattern.compile("public\\s+final\\s+void\\s+refresh\\(\\)\\s+throws\\s+RtcException,\\s+InterruptedException")
            .matcher(component).find(), "JavaComponent.refresh() as javac sees it");
        assertTrue(component.contains("state(ContextSelector"), "the @JvmOverloads overload with a context");
        String coordinator = text("org/rtcoord/dsl/java/JavaCoordinator.html");
        assertFalse(coordinator.isEmpty(), "the dsl's Java facade is documented");
    }

    @Test
    void onlyTheApi() throws IOException {
        assertFalse(Files.exists(apiDocs.resolve("org/rtcoord/internal")), "internal packages");
        assertFalse(Files.exists(apiDocs.resolve("org/rtcoord/ComponentEntryImpl.html")), "an internal class of an API package");
        List<String> leaks;
        try (Stream<Path> pages = Files.walk(apiDocs.resolve("org/rtcoord"))) {
            leaks = pages.filter(page -> page.toString().endsWith(".html"))
                .filter(page -> {
                    String html = read(page);
                    return html.contains("$rtcoord_") || html.contains("kotlin.Metadata") || html.contains("TODO")
                        || JAVA_FACING.matcher(apiDocs.relativize(page).toString()).matches() && html.contains("Continuation");
                })
                .map(apiDocs::relativize).map(Path::toString).collect(Collectors.toList());
        }
        assertEquals(List.of(), leaks, "pages naming mangled members, Kotlin metadata or placeholders, or Java-facing pages naming continuations");
    }

    @Test
    void sourcesHoldTheJavaView() throws IOException {
        String facade = read(SOURCES.resolve("org/rtcoord/java/JavaTree.java"));
        assertTrue(facade.contains("public final class JavaTree"), facade);
        assertFalse(facade.contains("kotlin.Metadata"), "Kotlin's metadata is not Java to read");
    }

    private static String text(String page) {
        return read(apiDocs.resolve(page)).replaceAll("<[^>]+>", "").replace("&nbsp;", " ").replace("&lt;", "<").replace("&gt;", ">");
    }

    private static String read(Path file) {
        try {
            return Files.readString(file);
        } catch (IOException e) {
            throw new AssertionError("cannot read " + file, e);
        }
    }
}
