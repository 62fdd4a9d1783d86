package org.rtcoord;

import org.junit.jupiter.api.Test;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.spi.ToolProvider;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * What {@code javap} shows a Java tool of the API it uses: the facades of {@code org.rtcoord.java}, and
 * every rtcoord class their public signatures reach, show no Kotlin type ({@code kotlin.}, a
 * {@code Continuation}), no {@code Companion} and no mangled name, among the members javac lets Java use
 * (not the synthetic ones, nor those Kotlin's metadata says are internal).
 *
 * {@link #NOT_YET} lists the classes still reached that show Kotlin, each with what it shows: the test
 * fails when one is cleaned (take it out) or when anything else shows Kotlin.
 */
class JavaSurfaceTest {
    private static final Pattern RTCOORD_TYPE = Pattern.compile("\\borg\\.rtcoord\\.[\\w.$]*[\\w$]");
    private static final Pattern KOTLIN = Pattern.compile("\\bkotlin\\.|\\bkotlinx\\.|Continuation|Companion|\\b[\\w$]+-[\\w-]+\\(");
    private static final Pattern DECLARATION_NAME = Pattern.compile("([\\w$-]+)\\(|([\\w$]+);$");

    /**
     * Classes a facade reaches that still show Kotlin (issue 36), with the count of their javap lines that
     * do: the nodes and views an event's {@code source} and a listener reach (suspend members, flows),
     * companions ({@code DEFAULT}, {@code builder()}, {@code LOG}) and enums' {@code getEntries()}.
     */
    private static final Map<String, Integer> NOT_YET = Map.ofEntries(
            Map.entry("org.rtcoord.ComponentNode", 17),
            Map.entry("org.rtcoord.ConfigurationSnapshot", 1),
            Map.entry("org.rtcoord.ContextSelector", 1),
            Map.entry("org.rtcoord.ContextSelector$Companion", 1),
            Map.entry("org.rtcoord.DirectoryNode", 5),
            Map.entry("org.rtcoord.EventOptions", 1),
            Map.entry("org.rtcoord.EventOptions$Companion", 1),
            Map.entry("org.rtcoord.ExecutionContextView", 5),
            Map.entry("org.rtcoord.LifeCycle", 2),
            Map.entry("org.rtcoord.ListenerFailureHandler", 1),
            Map.entry("org.rtcoord.ListenerFailureHandler$Companion", 1),
            Map.entry("org.rtcoord.ManagerNode", 9),
            Map.entry("org.rtcoord.NamingDirectory", 1),
            Map.entry("org.rtcoord.Node", 1),
            Map.entry("org.rtcoord.NodeKind", 1),
            Map.entry("org.rtcoord.Overlap", 1),
            Map.entry("org.rtcoord.Port", 7),
            Map.entry("org.rtcoord.PortInterface$Polarity", 1),
            Map.entry("org.rtcoord.PortKind", 1),
            Map.entry("org.rtcoord.RtcPath", 1),
            Map.entry("org.rtcoord.RtcPath$Companion", 1),
            Map.entry("org.rtcoord.TreeConfig", 1),
            Map.entry("org.rtcoord.TreeConfig$Companion", 1),
            Map.entry("org.rtcoord.WatchMode", 1),
            Map.entry("org.rtcoord.profile.OrderedAction", 1),
            Map.entry("org.rtcoord.profile.OrderingKind", 1),
            Map.entry("org.rtcoord.profile.PortConnector", 1));

    @Test
    void javapShowsNoKotlinInWhatTheFacadesReach() throws Exception {
        Path classes = Paths.get(RtcTree.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        Deque<String> pending = new ArrayDeque<>(facades(classes));
        Set<String> seen = new HashSet<>();
        Map<String, List<String>> kotlin = new TreeMap<>();
        while (!pending.isEmpty()) {
            String name = pending.pop();
            if (!seen.add(name) || name.contains(".internal.")) continue;
            Class<?> type = Class.forName(name, false, RtcTree.class.getClassLoader());
            if (!ApiDump.isVisible(type)) continue;
            Set<String> usable = ApiDump.javaUsableMembers(type);
            String[] lines = javap(classes, name).split("\n");
            for (int i = 0; i < lines.length; i++) {
                String line = lines[i].trim();
                boolean member = i + 1 < lines.length && lines[i + 1].trim().startsWith("descriptor: ");
                if (member && !usable.contains(key(type, line, lines[i + 1].trim().substring("descriptor: ".length())))) continue;
                if (!member && !line.contains(" class ") && !line.contains(" interface ")) continue;
                if (KOTLIN.matcher(line).find()) kotlin.computeIfAbsent(name, k -> new ArrayList<>()).add(line);
                Matcher reached = RTCOORD_TYPE.matcher(line);
                while (reached.find()) pending.add(reached.group());
            }
        }
        Map<String, Integer> counts = new TreeMap<>();
        kotlin.forEach((name, shown) -> counts.put(name, shown.size()));
        assertEquals(new TreeMap<>(NOT_YET), counts, "javap shows Kotlin: " + kotlin);
    }

    /** How {@link ApiDump#javaUsableMembers} names the member javap declared in [line] with [descriptor]. */
    private static String key(Class<?> type, String line, String descriptor) {
        Matcher name = DECLARATION_NAME.matcher(line);
        if (!name.find()) return line;
        if (name.group(2) != null) return name.group(2);
        String method = name.group(1);
        String simpleName = type.getName().substring(type.getName().lastIndexOf('.') + 1);
        return (method.equals(simpleName) ? "<init>" : method) + descriptor;
    }

    /** The top-level classes of {@code org.rtcoord.java}, by binary name. */
    private static List<String> facades(Path classes) throws Exception {
        List<String> names = new ArrayList<>();
        try (Stream<Path> files = Files.list(classes.resolve("org/rtcoord/java"))) {
            files.map(f -> f.getFileName().toString())
                    .filter(f -> f.endsWith(".class") && !f.contains("$"))
                    .sorted()
                    .forEach(f -> names.add("org.rtcoord.java." + f.replaceAll("\\.class$", "")));
        }
        return names;
    }

    /** javap's listing of the public members of [name], each line followed by its descriptor. */
    private static String javap(Path classes, String name) {
        StringWriter out = new StringWriter();
        int status = ToolProvider.findFirst("javap").orElseThrow()
                .run(new PrintWriter(out), new PrintWriter(out), "-public", "-s", "-cp", classes.toString(), name);
        if (status != 0) throw new IllegalStateException("javap " + name + " failed: " + out);
        return out.toString();
    }
}
