package org.rtcoord.dsl.java;

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
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * javac compiles every Java block of the README's Embedding section against core and the dsl as they
 * are: the examples a tool author copies cannot drift from the API. Each stands in a method of its own
 * whose parameters are the SWT objects it names ({@code display}, {@code label}) and, unless the block
 * makes its own, a {@code tree} and the {@code host} naming context.
 */
class ReadmeJavaExampleTest {
    private static final Pattern SECTION = Pattern.compile("## Embedding in Java tools(.*?)\\n## ", Pattern.DOTALL);
    private static final Pattern JAVA_BLOCK = Pattern.compile("```java\\n(.*?)```", Pattern.DOTALL);

    @Test
    void theReadmesJavaExamplesCompile(@TempDir Path directory) throws IOException {
        Path readme = Paths.get(System.getProperty("rtcoord.root", ".."), "README.md");
        Matcher section = SECTION.matcher(Files.readString(readme, StandardCharsets.UTF_8));
        assertTrue(section.find(), "no Embedding section in " + readme);
        List<String> methods = new ArrayList<>();
        Matcher block = JAVA_BLOCK.matcher(section.group(1));
        while (block.find()) {
            String code = block.group(1);
            String given = code.contains("JavaTree tree =") ? "" : ", JavaTree tree, String host";
            methods.add("    void example" + methods.size() + "(Display display, Label label" + given + ") throws Exception {\n" + code + "    }\n");
        }
        assertTrue(methods.size() >= 3, "the Embedding section has " + methods.size() + " Java blocks: listing, following and a coordinator at least");
        Path source = Files.writeString(directory.resolve("ReadmeExample.java"), String.join("\n",
                "import org.rtcoord.*;",
                "import org.rtcoord.java.*;",
                "import org.rtcoord.dsl.java.*;",
                "import java.nio.file.Path;",
                "import java.time.Duration;",
                "import java.util.List;",
                "import java.util.Set;",
                "import java.util.concurrent.TimeUnit;",
                "class ReadmeExample {",
                "    interface Display { void asyncExec(Runnable task); }",
                "    interface Label { void setText(String text); }",
                String.join("\n", methods),
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
            assertTrue(compiled, "the README's Java examples do not compile:\n" + errors + "\n" + Files.readString(source));
        }
    }
}
