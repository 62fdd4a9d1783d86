package org.rtcoord;

import java.lang.reflect.Constructor;
import java.lang.reflect.Executable;
import java.lang.reflect.Field;
import java.lang.reflect.GenericArrayType;
import java.lang.reflect.Member;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.Type;
import java.lang.reflect.TypeVariable;
import java.lang.reflect.WildcardType;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * What javac lets a Java tool use of rtcoord, and every part of it that shows the tool Kotlin, rtcoord's
 * internals or CORBA. It starts from every class file of the given packages (nested, anonymous and
 * compiler-made ones included: javac sees them all) and follows, transitively, every rtcoord type their
 * usable members and supertypes name: what they return, take, throw and extend. A member is usable when
 * it is public (or protected, in a class Java can extend) and not synthetic: javac ignores synthetic
 * members, which is what {@code @JvmSynthetic} makes a member; Kotlin's {@code internal} is not
 * synthetic, so javac can call it.
 *
 * A leak is one line: a class javac can use that Kotlin keeps internal or made for itself (a lambda, an
 * inlined operator); a member whose name Kotlin mangled ({@code -}) or made internal ({@code $});
 * a member Kotlin declares {@code internal} or private; a {@code Companion} field; a signature naming a
 * {@code kotlin.*} or {@code kotlinx.*} type (a {@code Continuation}, a {@code Function}, a {@code Flow},
 * {@code Unit}), a CORBA type (OMG's, JacORB's, or an IDL type of {@code rtcoord-idl}), an rtcoord
 * {@code internal} package's type or any type outside the JDK, JSpecify and rtcoord's API. There is no
 * list of exceptions; the one rule that lets something through is Kotlin's: the static
 * {@code getEntries()} of every enum, which Kotlin 2 compiles whatever a library says (Java has
 * {@code values()}).
 */
public final class JavaReach {
    private final ClassLoader loader;
    private final Set<String> seen = new HashSet<>();
    private final Deque<Class<?>> pending = new ArrayDeque<>();
    private final Set<String> leaks = new TreeSet<>();
    private final Path idl;

    /**
     * Fails, listing them, if javac reaches any leak from the classes in [packages] of the class directories
     * (or jars) [anchors] were loaded from: there is no list of leaks tolerated.
     */
    public static void assertNone(List<Class<?>> anchors, List<String> packages) throws Exception {
        List<String> leaks = leaks(anchors, packages);
        if (!leaks.isEmpty()) {
            throw new AssertionError("javac reaches what it should not from " + packages + ":\n" + String.join("\n", leaks));
        }
    }

    private JavaReach(ClassLoader loader) throws Exception {
        this.loader = loader;
        this.idl = location(Class.forName("RTC.LifeCycleState", false, loader));
    }

    /**
     * The leaks of the classes in [packages], found in the class directories (or jars) [anchors] were
     * loaded from, and of every rtcoord type they reach; each a line {@code class: what}, sorted.
     */
    public static List<String> leaks(List<Class<?>> anchors, List<String> packages) throws Exception {
        JavaReach reach = new JavaReach(anchors.get(0).getClassLoader());
        for (Class<?> anchor : anchors) {
            Path root = location(anchor);
            for (String packageName : packages) {
                Path directory = root.resolve(packageName.replace('.', '/'));
                if (!Files.isDirectory(directory)) continue;
                try (Stream<Path> files = Files.list(directory)) {
                    for (Path file : files.sorted().collect(Collectors.toList())) {
                        String name = file.getFileName().toString();
                        if (!name.endsWith(".class") || name.equals("package-info.class")) continue;
                        reach.add(Class.forName(packageName + "." + name.substring(0, name.length() - ".class".length()), false, reach.loader));
                    }
                }
            }
        }
        reach.run();
        return new ArrayList<>(reach.leaks);
    }

    private void run() {
        while (!pending.isEmpty()) scan(pending.pop());
    }

    private void add(Class<?> type) {
        while (type.isArray()) type = type.getComponentType();
        if (type.isPrimitive() || !type.getName().startsWith("org.rtcoord.") || !seen.add(type.getName())) return;
        pending.add(type);
    }

    private void scan(Class<?> type) {
        try {
            scanClass(type);
        } catch (IncompatibleClassChangeError e) {
            // A class Kotlin copied out of an inline function (`$inlined$`): its InnerClasses attribute names an
            // outer class that does not list it, which reflection refuses. javac reads it as a top-level class.
            if (Modifier.isPublic(type.getModifiers())) leaks.add(type.getName() + ": javac can use this class, which Kotlin made for itself");
        }
    }

    private void scanClass(Class<?> type) {
        if (!javacCanUse(type)) return;
        String name = type.getName();
        if (!ApiDump.isVisible(type) || type.isAnonymousClass() || type.isLocalClass() || type.isSynthetic()) {
            leaks.add(name + ": javac can use this class, which Kotlin keeps internal or made for itself");
        }
        if (isInternal(name)) leaks.add(name + ": javac reaches this class of an internal package");
        Set<String> hidden = ApiDump.hiddenByKotlin(type);
        // Protected members count only where Java can extend the class: not final, with a constructor javac can call.
        boolean extensible = !Modifier.isFinal(type.getModifiers()) && !type.isEnum() && !type.isInterface()
                && Stream.of(type.getDeclaredConstructors()).anyMatch(c -> usable(c, true));
        types(name, type.getGenericSuperclass());
        for (Type implemented : type.getGenericInterfaces()) types(name, implemented);
        for (Class<?> nested : type.getDeclaredClasses()) add(nested);
        for (Constructor<?> constructor : type.getDeclaredConstructors()) {
            if (usable(constructor, extensible)) executable(type, constructor, hidden);
        }
        for (Method method : type.getDeclaredMethods()) {
            if (!usable(method, extensible)) continue;
            if (type.isEnum() && method.getName().equals("getEntries") && Modifier.isStatic(method.getModifiers()) && method.getParameterCount() == 0) continue;
            executable(type, method, hidden);
        }
        for (Field field : type.getDeclaredFields()) {
            if (!usable(field, extensible)) continue;
            String where = name + "." + field.getName();
            if (field.getName().equals("Companion")) leaks.add(where + ": a Companion field");
            else if (hidden.contains(field.getName())) leaks.add(where + ": internal in Kotlin, usable by javac");
            if (field.getName().contains("$")) leaks.add(where + ": a name Kotlin made for itself");
            types(where, field.getGenericType());
        }
    }

    private void executable(Class<?> type, Executable member, Set<String> hidden) {
        String label = member instanceof Constructor ? "<init>" : member.getName();
        String where = type.getName() + "." + label + "(" + Stream.of(member.getParameterTypes()).map(Class::getSimpleName).collect(Collectors.joining(", ")) + ")";
        if (label.contains("-")) leaks.add(where + ": a name Kotlin mangled");
        else if (label.contains("$")) leaks.add(where + ": a name Kotlin made for itself");
        else if (hidden.contains(ApiDump.signature(member))) leaks.add(where + ": internal in Kotlin, usable by javac");
        for (Type parameter : member.getGenericParameterTypes()) types(where, parameter);
        for (Type thrown : member.getGenericExceptionTypes()) types(where, thrown);
        for (TypeVariable<?> variable : member.getTypeParameters()) for (Type bound : variable.getBounds()) types(where, bound);
        if (member instanceof Method) types(where, ((Method) member).getGenericReturnType());
    }

    /** Checks every class [type] names, and follows the rtcoord ones. */
    private void types(String where, Type type) {
        if (type == null) return;
        if (type instanceof ParameterizedType) {
            types(where, ((ParameterizedType) type).getRawType());
            for (Type argument : ((ParameterizedType) type).getActualTypeArguments()) types(where, argument);
        } else if (type instanceof WildcardType) {
            for (Type bound : ((WildcardType) type).getUpperBounds()) types(where, bound);
            for (Type bound : ((WildcardType) type).getLowerBounds()) types(where, bound);
        } else if (type instanceof GenericArrayType) {
            types(where, ((GenericArrayType) type).getGenericComponentType());
        } else if (type instanceof Class) {
            Class<?> named = (Class<?>) type;
            while (named.isArray()) named = named.getComponentType();
            if (named.isPrimitive()) return;
            String kind = kind(named);
            if (kind != null) leaks.add(where + ": " + kind + " " + named.getName());
            else add(named);
        }
    }

    /** What is wrong with Java seeing [type]; null when nothing is. */
    private String kind(Class<?> type) {
        String name = type.getName();
        if (name.startsWith("kotlin.") || name.startsWith("kotlinx.")) return "names Kotlin's";
        if (name.startsWith("org.omg.") || name.startsWith("org.jacorb.") || isIdl(type)) return "names CORBA's";
        if (name.startsWith("org.rtcoord.")) return isInternal(name) ? "names rtcoord's internal" : null;
        if (name.startsWith("java.") || name.startsWith("javax.") || name.startsWith("org.jspecify.")) return null;
        return "names a type outside the API:";
    }

    private boolean isIdl(Class<?> type) {
        try {
            return type.getProtectionDomain().getCodeSource() != null && location(type).equals(idl);
        } catch (Exception e) {
            return false;
        }
    }

    private static boolean isInternal(String name) {
        return name.contains(".internal.") || name.endsWith(".internal");
    }

    /** Public, or protected in a class Java can extend; not synthetic (javac ignores synthetic members). */
    private static boolean usable(Member member, boolean extensible) {
        int modifiers = member.getModifiers();
        boolean visible = Modifier.isPublic(modifiers) || (extensible && Modifier.isProtected(modifiers));
        return visible && !member.isSynthetic();
    }

    /** Whether javac can name [type]: public, as is every class it is nested in. */
    private static boolean javacCanUse(Class<?> type) {
        for (Class<?> t = type; t != null; t = t.getDeclaringClass()) {
            if (!Modifier.isPublic(t.getModifiers())) return false;
        }
        Class<?> enclosing = type.getEnclosingClass();
        return enclosing == null || javacCanUse(enclosing);
    }

    private static Path location(Class<?> type) throws Exception {
        return Paths.get(type.getProtectionDomain().getCodeSource().getLocation().toURI());
    }
}
