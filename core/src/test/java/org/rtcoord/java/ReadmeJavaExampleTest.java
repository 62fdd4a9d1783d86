package org.rtcoord.java;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * javac compiles the Java example of the README's Embedding section against core as it is: the example
 * a tool author copies cannot drift from the API. It stands in a method whose parameters are the SWT
 * objects it names ({@code display}, {@code label}).
 */
class ReadmeJavaExampleTest {
    private static final Pattern JAVA_BLOCK = Pattern.compile("## Embedding.*?```java\\n(.*?)```", Pattern.DOTALL);

    @Test
    void theReadmeJavaExampleCompiles(@TempDir Path directory) throws IOException {
        Path readme = Paths.get(System.getProperty("rtcoord.root", ".."), "README.md");
        Matcher block = JAVA_BLOCK.matcher(Files.readString(readme, StandardCharsets.UTF_8));
        assertTrue(block.find(), "no ```java block in the Embedding section of " + readme);
        Path source = Files.writeString(directory.resolve("ReadmeExample.java"), String.join("\n",
                "import org.rtcoord.*;",
                "import org.rtcoord.java.*;",
                "import java.time.Duration;",
                "import java.util.List;",
                "import java.util.concurrent.TimeUnit;",
                "class ReadmeExample {",
                "    interface Display { void asyncExec(Runnable task); }",
                "    interface Label { void setText(String text); }",
                "    void run(Display display, Label label) throws Exception {",
                block.group(1),
                "    }",
                "}"));

        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        try (StandardJavaFileManager files = javac.getStandardFileManager(diagnostics, null, StandardCharsets.UTF_8)) {
            List<String> options = List.of("-classpath", System.getProperty("java.class.path"), "-d", directory.toString(), "-Xlint:none");
            boolean compiled = javac.getTask(null, files, diagnostics, options, null, files.getJavaFileObjects(source)).call();
            String errors = diagnostics.getDiagnostics().stream()
                    .filter(d -> d.getKind() == Diagnostic.Kind.ERROR)
                    .map(d -> "line " + d.getLineNumber() + ": " + d.getMessage(null))
                    .collect(Collectors.joining("\n"));
            assertTrue(compiled, "the README's Java example does not compile:\n" + errors);
        }
    }
}
