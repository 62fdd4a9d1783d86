import com.sun.source.tree.AnnotationTree;
import com.sun.source.tree.ClassTree;
import com.sun.source.tree.CompilationUnitTree;
import com.sun.source.tree.MethodTree;
import com.sun.source.tree.Tree;
import com.sun.source.tree.VariableTree;
import com.sun.source.util.JavacTask;
import com.sun.source.util.SourcePositions;
import com.sun.source.util.Trees;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.lang.model.element.Modifier;
import javax.tools.JavaCompiler;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/**
 * The Java API of Kotlin modules as Java sources, for javadoc and for the hovers of Java IDEs.
 *
 * <p>kapt's stubs (aptMode=stubs) carry the signatures javac sees: {@code void}, {@code int}, {@code throws},
 * one method per {@code @JvmOverloads} overload, with the KDoc as their doc comments. But what Kotlin keeps
 * internal is public there. This keeps the types the modules' API dumps declare (the dumps
 * {@code *ApiGuardTest} keeps) and, in them, the members a Java caller can use: not private ones, not those
 * whose name Kotlin mangled ({@code getCore$rtcoord_core}), not those whose signature names a type left out.
 * It also leaves out what is not Java: {@code @kotlin.Metadata}, and {@code @JvmName} on a file's class,
 * which javac refuses there.
 *
 * <p>Usage: {@code java ApiStubs.java OUT STUBS API_DUMP [STUBS API_DUMP]...}
 */
public final class ApiStubs {
    private static final Set<String> KINDS = Set.of("class", "interface", "enum");
    private static final Set<String> NOT_JAVA = Set.of("kotlin.Metadata", "kotlin.jvm.JvmName");

    private final Set<String> api = new HashSet<>();
    /** Canonical names ({@code org.rtcoord.dsl.Trigger}) of the stubs' types that are not API. */
    private final Set<String> leftOut = new HashSet<>();
    /** Matches a name of {@link #leftOut} (not a longer name that starts with one). */
    private Pattern namesLeftOut;
    private final List<CompilationUnitTree> units = new ArrayList<>();
    private SourcePositions positions;

    public static void main(String[] args) throws IOException {
        if (args.length < 3 || args.length % 2 == 0) {
            System.err.println("usage: java ApiStubs.java OUT STUBS API_DUMP [STUBS API_DUMP]...");
            System.exit(2);
        }
        ApiStubs stubs = new ApiStubs();
        List<Path> files = new ArrayList<>();
        for (int i = 1; i < args.length; i += 2) {
            files.addAll(javaFiles(Path.of(args[i])));
            stubs.api.addAll(apiTypes(Path.of(args[i + 1])));
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        try (StandardJavaFileManager fileManager = javac.getStandardFileManager(null, null, null)) {
            JavacTask task = (JavacTask) javac.getTask(null, fileManager, null, List.of("-proc:none"), null,
                    fileManager.getJavaFileObjectsFromPaths(files));
            stubs.positions = Trees.instance(task).getSourcePositions();
            task.parse().forEach(stubs.units::add);
            int written = stubs.write(Path.of(args[0]));
            System.out.println("ApiStubs: " + written + " API types written to " + args[0]);
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }

    /** The binary names of the types the dump declares: {@code public [modifiers] class|interface|enum NAME ...}. */
    private static Set<String> apiTypes(Path dump) throws IOException {
        Set<String> names = new HashSet<>();
        for (String line : Files.readAllLines(dump)) {
            if (line.isEmpty() || Character.isWhitespace(line.charAt(0))) continue;
            String[] words = line.split(" ");
            for (int i = 0; i + 1 < words.length; i++) {
                if (KINDS.contains(words[i])) {
                    names.add(words[i + 1]);
                    break;
                }
            }
        }
        if (names.isEmpty()) throw new IllegalStateException(dump + ": declares no type");
        return names;
    }

    private static List<Path> javaFiles(Path stubs) throws IOException {
        try (Stream<Path> walk = Files.walk(stubs)) {
            List<Path> files = walk.filter(p -> p.toString().endsWith(".java")).sorted().collect(Collectors.toList());
            if (files.isEmpty()) throw new IllegalStateException(stubs + ": no stubs (did kapt run?)");
            return files;
        }
    }

    private int write(Path out) throws IOException {
        for (CompilationUnitTree unit : units) {
            for (Tree type : unit.getTypeDecls()) {
                if (type instanceof ClassTree) findLeftOut((ClassTree) type, packageOf(unit), packageOf(unit));
            }
        }
        // An empty alternation would match everywhere: with nothing left out, nothing is named.
        namesLeftOut = leftOut.isEmpty() ? Pattern.compile("(?!)")
                : Pattern.compile(leftOut.stream().map(Pattern::quote).collect(Collectors.joining("|", "(?:", ")(?![\\w$])")));
        int written = 0;
        for (CompilationUnitTree unit : units) {
            List<int[]> cuts = new ArrayList<>();
            boolean isApi = false;
            for (Tree type : unit.getTypeDecls()) {
                if (!(type instanceof ClassTree)) continue;
                String name = packageOf(unit) + ((ClassTree) type).getSimpleName();
                if (api.contains(name)) {
                    isApi = true;
                    cut(unit, (ClassTree) type, name, cuts);
                }
            }
            if (!isApi) continue;
            StringBuilder kept = new StringBuilder(source(unit));
            cuts.sort(Comparator.comparingInt((int[] c) -> c[0]).reversed());
            for (int[] c : cuts) kept.delete(c[0], c[1]);
            String fileName = Path.of(unit.getSourceFile().getName()).getFileName().toString();
            Path target = out.resolve(packageOf(unit).replace('.', '/')).resolve(fileName);
            Files.createDirectories(target.getParent());
            Files.writeString(target, kept);
            written++;
        }
        return written;
    }

    private static String packageOf(CompilationUnitTree unit) {
        return unit.getPackageName() == null ? "" : unit.getPackageName() + ".";
    }

    private void findLeftOut(ClassTree type, String binaryPrefix, String canonicalPrefix) {
        String binary = binaryPrefix + type.getSimpleName();
        String canonical = canonicalPrefix + type.getSimpleName();
        if (!api.contains(binary)) leftOut.add(canonical);
        for (Tree member : type.getMembers()) {
            if (member instanceof ClassTree) findLeftOut((ClassTree) member, binary + "$", canonical + ".");
        }
    }

    /** Adds to {@code cuts} what of {@code type} (binary name {@code name}) is not its Java API. */
    private void cut(CompilationUnitTree unit, ClassTree type, String name, List<int[]> cuts) {
        for (AnnotationTree annotation : type.getModifiers().getAnnotations()) {
            if (NOT_JAVA.contains(annotation.getAnnotationType().toString())) cuts.add(span(unit, annotation));
        }
        for (Tree member : type.getMembers()) {
            if (member instanceof ClassTree) {
                String nested = name + "$" + ((ClassTree) member).getSimpleName();
                if (api.contains(nested)) cut(unit, (ClassTree) member, nested, cuts);
                else cuts.add(withComment(unit, span(unit, member)));
            } else if (!isJavaApi(unit, member)) {
                cuts.add(withComment(unit, span(unit, member)));
            }
        }
    }

    private boolean isJavaApi(CompilationUnitTree unit, Tree member) {
        Set<Modifier> modifiers;
        String name;
        if (member instanceof VariableTree) {
            modifiers = ((VariableTree) member).getModifiers().getFlags();
            name = ((VariableTree) member).getName().toString();
        } else if (member instanceof MethodTree) {
            modifiers = ((MethodTree) member).getModifiers().getFlags();
            name = ((MethodTree) member).getName().toString();
        } else {
            return true;
        }
        if (modifiers.contains(Modifier.PRIVATE) || name.contains("$")) return false;
        int[] span = span(unit, member);
        String signature = source(unit).substring(span[0], span[1]);
        return !signature.contains(".internal.") && !namesLeftOut.matcher(signature).find();
    }

    private int[] span(CompilationUnitTree unit, Tree tree) {
        return new int[] {(int) positions.getStartPosition(unit, tree), (int) positions.getEndPosition(unit, tree)};
    }

    private static String source(CompilationUnitTree unit) {
        try {
            return unit.getSourceFile().getCharContent(true).toString();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** {@code span} with the doc comment right before it, which would otherwise document the next member. */
    private static int[] withComment(CompilationUnitTree unit, int[] span) {
        String text = source(unit);
        int open = text.lastIndexOf("/**", span[0]);
        int close = open < 0 ? -1 : text.indexOf("*/", open);
        boolean adjacent = close >= 0 && close < span[0] && text.substring(close + 2, span[0]).isBlank();
        return new int[] {adjacent ? open : span[0], span[1]};
    }
}
