package org.rtcoord;

import kotlin.Metadata;
import kotlin.metadata.Attributes;
import kotlin.metadata.KmClass;
import kotlin.metadata.KmConstructor;
import kotlin.metadata.KmDeclarationContainer;
import kotlin.metadata.KmFunction;
import kotlin.metadata.KmProperty;
import kotlin.metadata.Visibility;
import kotlin.metadata.jvm.JvmExtensionsKt;
import kotlin.metadata.jvm.JvmMethodSignature;
import kotlin.metadata.jvm.KotlinClassMetadata;

import java.io.IOException;
import java.lang.reflect.Constructor;
import java.lang.reflect.Executable;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.TreeMap;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A module's public API as Java sees it (reflection over the compiled classes, so it is what javac
 * sees, less what Kotlin's metadata says is {@code internal} or private: the bytecode leaves those public),
 * dumped one class and its members a block, and compared with the dump checked in at
 * {@code <module>/api/<module>.api}. Core's {@link ApiGuardTest} and the dsl's API guard share it (the
 * dsl through core's test jar). With {@code -Drtcoord.api.update=true} the dump is rewritten instead.
 */
public final class ApiDump {
    private ApiDump() {
    }

    /** Fails unless {@code api/<module>.api} (relative to the module's directory) holds [classes]' API. */
    public static void assertMatches(String module, List<Class<?>> classes) throws IOException {
        Path dump = Paths.get("api", module + ".api");
        String text = classes.stream().map(ApiDump::describe).collect(Collectors.joining("\n")) + "\n";
        String update = "mvn -pl " + module + " -am test -Dtest='*ApiGuardTest' -Dsurefire.failIfNoSpecifiedTests=false -Drtcoord.api.update=true";
        if (Boolean.getBoolean("rtcoord.api.update")) {
            Files.createDirectories(dump.getParent());
            Files.writeString(dump, text, StandardCharsets.UTF_8);
        }
        assertTrue(Files.exists(dump), "no API dump at " + module + "/" + dump + ": run `" + update + "` and commit it");
        assertEquals(Files.readString(dump, StandardCharsets.UTF_8), text,
                module + "'s public API changed: if that is meant, run `" + update + "` and commit " + module + "/" + dump);
    }

    /** The public classes outside internal packages in the class directory or jar [anchor] was loaded from. */
    public static List<Class<?>> publicClasses(Class<?> anchor) {
        try {
            Path root = Paths.get(anchor.getProtectionDomain().getCodeSource().getLocation().toURI());
            try (Stream<Path> files = Files.walk(root)) {
                List<Class<?>> classes = new ArrayList<>();
                for (Path file : files.filter(f -> f.toString().endsWith(".class")).sorted().collect(Collectors.toList())) {
                    String name = root.relativize(file).toString().replace(java.io.File.separatorChar, '.').replaceAll("\\.class$", "");
                    if (name.contains(".internal.") || name.endsWith("module-info")) continue;
                    Class<?> type = Class.forName(name, false, anchor.getClassLoader());
                    if (isVisible(type) && !isEmptyFacade(type)) classes.add(type);
                }
                return classes;
            }
        } catch (IOException | URISyntaxException | ClassNotFoundException e) {
            throw new IllegalStateException("cannot read the classes beside " + anchor.getName() + ": " + e, e);
        }
    }

    /** Visible methods whose names Kotlin mangled, but for a data class's copy and componentN (Java reads the getters). */
    public static List<String> mangledNames(List<Class<?>> classes) {
        List<String> mangled = new ArrayList<>();
        for (Class<?> type : classes) {
            for (Method method : visibleMethods(type)) {
                if (method.getName().contains("-") && !method.getName().matches("(copy|component\\d+)-.*")) {
                    mangled.add(type.getName() + "." + method.getName());
                }
            }
        }
        return mangled;
    }

    /** The data classes among [classes], by binary name, as Kotlin's metadata says. */
    public static List<String> dataClasses(List<Class<?>> classes) {
        return classes.stream()
                .filter(type -> metadata(type) instanceof KotlinClassMetadata.Class && Attributes.isData(((KotlinClassMetadata.Class) metadata(type)).getKmClass()))
                .map(Class::getName)
                .collect(Collectors.toList());
    }

    /** The visible methods of the classes of [packageName] that show Java a Kotlin type (a Continuation, Unit, a function type). */
    public static List<String> kotlinTypesShown(List<Class<?>> classes, String packageName) {
        List<String> kotlin = new ArrayList<>();
        for (Class<?> type : classes) {
            if (!type.getPackageName().equals(packageName)) continue;
            for (Method method : visibleMethods(type)) {
                if (method.toGenericString().matches(".*\\bkotlin\\..*")) kotlin.add(method.toGenericString());
            }
        }
        return kotlin;
    }

    /** Public to Java and, for a Kotlin class, not `internal` (which the bytecode leaves public). */
    static boolean isVisible(Class<?> type) {
        for (Class<?> t = type; t != null; t = t.getDeclaringClass()) {
            if (!Modifier.isPublic(t.getModifiers()) || t.isSynthetic() || t.isAnonymousClass() || t.isLocalClass()) return false;
            Object metadata = metadata(t);
            if (metadata instanceof KotlinClassMetadata.Class && !isPublic(Attributes.getVisibility(((KotlinClassMetadata.Class) metadata).getKmClass()))) return false;
            if (metadata instanceof KotlinClassMetadata.SyntheticClass) return false;
        }
        return true;
    }

    /** A class of top-level declarations (`RtcTreeKt`) that are all internal: nothing of it is API. */
    private static boolean isEmptyFacade(Class<?> type) {
        return metadata(type) instanceof KotlinClassMetadata.FileFacade && visibleMethods(type).isEmpty()
                && Arrays.stream(type.getDeclaredFields()).noneMatch(f -> isVisible(f.getModifiers()) && !f.isSynthetic());
    }

    private static boolean isVisible(int modifiers) {
        return Modifier.isPublic(modifiers) || Modifier.isProtected(modifiers);
    }

    static boolean isPublic(Visibility visibility) {
        return visibility == Visibility.PUBLIC || visibility == Visibility.PROTECTED;
    }

    /** Kotlin's metadata of [type], or null for a Java class. */
    static KotlinClassMetadata metadata(Class<?> type) {
        Metadata annotation = type.getAnnotation(Metadata.class);
        return annotation == null ? null : KotlinClassMetadata.readLenient(annotation);
    }

    /**
     * The JVM signatures (name and descriptor) of the members of [type] that Kotlin declares `internal` or
     * private: public in the bytecode, but not part of the API.
     */
    static Set<String> hiddenByKotlin(Class<?> type) {
        Set<String> hidden = new HashSet<>();
        KotlinClassMetadata metadata = metadata(type);
        KmDeclarationContainer container = null;
        if (metadata instanceof KotlinClassMetadata.Class) {
            KmClass kotlinClass = ((KotlinClassMetadata.Class) metadata).getKmClass();
            container = kotlinClass;
            for (KmConstructor constructor : kotlinClass.getConstructors()) {
                if (!isPublic(Attributes.getVisibility(constructor))) add(hidden, JvmExtensionsKt.getSignature(constructor));
            }
            String companion = kotlinClass.getCompanionObject();
            if (companion != null && !isVisible(nested(type, companion))) hidden.add(companion);
        } else if (metadata instanceof KotlinClassMetadata.FileFacade) {
            container = ((KotlinClassMetadata.FileFacade) metadata).getKmPackage();
        } else if (metadata instanceof KotlinClassMetadata.MultiFileClassPart) {
            container = ((KotlinClassMetadata.MultiFileClassPart) metadata).getKmPackage();
        }
        if (container == null) return hidden;
        for (KmFunction function : container.getFunctions()) {
            if (!isPublic(Attributes.getVisibility(function))) add(hidden, JvmExtensionsKt.getSignature(function));
        }
        for (KmProperty property : container.getProperties()) {
            if (!isPublic(Attributes.getVisibility(property))) {
                add(hidden, JvmExtensionsKt.getGetterSignature(property));
                add(hidden, JvmExtensionsKt.getSetterSignature(property));
                if (JvmExtensionsKt.getFieldSignature(property) != null) hidden.add(JvmExtensionsKt.getFieldSignature(property).getName());
            } else if (property.getSetter() != null && !isPublic(Attributes.getVisibility(property.getSetter()))) {
                add(hidden, JvmExtensionsKt.getSetterSignature(property));
            }
        }
        return hidden;
    }

    /** The class nested in [type] as [name]: Kotlin's metadata names a companion this way. */
    private static Class<?> nested(Class<?> type, String name) {
        try {
            return Class.forName(type.getName() + "$" + name, false, type.getClassLoader());
        } catch (ClassNotFoundException e) {
            throw new IllegalStateException("the metadata of " + type.getName() + " names a companion " + name + " that is not there", e);
        }
    }

    private static void add(Set<String> signatures, JvmMethodSignature signature) {
        if (signature != null) signatures.add(signature.toString());
    }

    static String signature(Executable member) {
        StringBuilder descriptor = new StringBuilder(member instanceof Constructor ? "<init>" : member.getName()).append('(');
        for (Class<?> parameter : member.getParameterTypes()) descriptor.append(parameter.descriptorString());
        descriptor.append(')').append(member instanceof Method ? ((Method) member).getReturnType().descriptorString() : "V");
        return descriptor.toString();
    }

    /** Kotlin's `internal` members keep public bytecode: the metadata says which they are; `$module` names or internal types give away the rest. */
    private static boolean isKotlinInternal(Executable member, Set<String> hidden) {
        return hidden.contains(signature(member)) || member.getName().contains("$") || member.toGenericString().contains(".internal.");
    }

    /**
     * What javac lets Java use of [type]: its visible constructors and methods as name and descriptor
     * ({@code <init>(Ljava/lang/String;)V}), and its visible fields by name.
     */
    public static Set<String> javaUsableMembers(Class<?> type) {
        Set<String> hidden = hiddenByKotlin(type);
        Set<String> usable = new HashSet<>();
        for (Constructor<?> constructor : type.getDeclaredConstructors()) {
            if (isVisible(constructor.getModifiers()) && !constructor.isSynthetic() && !isKotlinInternal(constructor, hidden)) usable.add(signature(constructor));
        }
        for (Method method : visibleMethods(type)) usable.add(signature(method));
        for (Field field : type.getDeclaredFields()) {
            if (isVisible(field.getModifiers()) && !field.isSynthetic() && !hidden.contains(field.getName())) usable.add(field.getName());
        }
        return usable;
    }

    /** The methods of [type] Java can call. */
    public static List<Method> visibleMethods(Class<?> type) {
        Set<String> hidden = hiddenByKotlin(type);
        return Arrays.stream(type.getDeclaredMethods())
                .filter(m -> isVisible(m.getModifiers()) && !m.isSynthetic() && !m.isBridge() && !isKotlinInternal(m, hidden))
                .collect(Collectors.toList());
    }

    /**
     * The methods of [type] Kotlin callers can call: the visible ones and those {@code @JvmSynthetic} hides
     * from Java (not what the compiler adds, whose names hold a {@code $}).
     */
    public static List<Method> kotlinCallableMethods(Class<?> type) {
        Set<String> hidden = hiddenByKotlin(type);
        return Arrays.stream(type.getDeclaredMethods())
                .filter(m -> isVisible(m.getModifiers()) && !m.isBridge() && !isKotlinInternal(m, hidden))
                .collect(Collectors.toList());
    }

    /** One class and its visible members, one per line, sorted: what javac can use. */
    private static String describe(Class<?> type) {
        TreeMap<String, String> members = new TreeMap<>();
        Set<String> hidden = hiddenByKotlin(type);
        for (Constructor<?> constructor : type.getDeclaredConstructors()) {
            if (isVisible(constructor.getModifiers()) && !constructor.isSynthetic() && !isKotlinInternal(constructor, hidden)) members.put(constructor.toGenericString(), "");
        }
        for (Method method : visibleMethods(type)) members.put(method.toGenericString(), "");
        for (Field field : type.getDeclaredFields()) {
            if (isVisible(field.getModifiers()) && !field.isSynthetic() && !hidden.contains(field.getName())) members.put(field.toGenericString(), "");
        }
        StringBuilder text = new StringBuilder(header(type)).append(" {\n");
        members.keySet().forEach(member -> text.append("  ").append(member).append('\n'));
        return text.append("}").toString();
    }

    private static String header(Class<?> type) {
        String kind = type.isInterface() ? "interface" : type.isEnum() ? "enum" : "class";
        StringBuilder text = new StringBuilder(Modifier.toString(type.getModifiers() & ~Modifier.INTERFACE)).append(' ').append(kind).append(' ').append(type.getName());
        if (type.getGenericSuperclass() != null && type.getSuperclass() != Object.class && !type.isEnum()) text.append(" extends ").append(type.getGenericSuperclass().getTypeName());
        if (type.getGenericInterfaces().length > 0) {
            text.append(" implements ").append(Arrays.stream(type.getGenericInterfaces()).map(java.lang.reflect.Type::getTypeName).collect(Collectors.joining(", ")));
        }
        return text.toString();
    }
}
