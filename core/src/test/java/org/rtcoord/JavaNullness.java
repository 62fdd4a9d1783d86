package org.rtcoord;

import kotlin.metadata.Attributes;
import kotlin.metadata.KmClass;
import kotlin.metadata.KmConstructor;
import kotlin.metadata.KmFunction;
import kotlin.metadata.KmProperty;
import kotlin.metadata.KmType;
import kotlin.metadata.KmValueParameter;
import kotlin.metadata.MemberKind;
import kotlin.metadata.jvm.JvmExtensionsKt;
import kotlin.metadata.jvm.JvmMethodSignature;
import kotlin.metadata.jvm.KotlinClassMetadata;
import org.jspecify.annotations.NullMarked;
import org.jspecify.annotations.Nullable;

import java.lang.reflect.AnnotatedType;
import java.lang.reflect.Executable;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * What Java's null analysis reads of a package's API (JSpecify): the package is {@link NullMarked}, and
 * every type Kotlin declares nullable at the top of a public signature (a parameter, a return, a
 * property) is {@link Nullable} in the class file, so that Eclipse, IntelliJ and NullAway take nothing
 * for non-null that may be null. Core's and the dsl's nullness tests share it.
 */
public final class JavaNullness {
    private JavaNullness() {
    }

    /** What is wrong in [packageName] among [classes]: an unmarked package, and each nullable type not marked, one a line. */
    public static List<String> unmarked(List<Class<?>> classes, String packageName, ClassLoader loader) throws ClassNotFoundException {
        List<String> problems = new ArrayList<>();
        Package marked = Class.forName(packageName + ".package-info", false, loader).getPackage();
        if (!marked.isAnnotationPresent(NullMarked.class)) problems.add(packageName + " is not @NullMarked");
        for (Class<?> type : classes) {
            if (!type.getPackageName().equals(packageName) || !(ApiDump.metadata(type) instanceof KotlinClassMetadata.Class)) continue;
            KmClass kotlin = ((KotlinClassMetadata.Class) ApiDump.metadata(type)).getKmClass();
            for (KmConstructor constructor : kotlin.getConstructors()) {
                if (ApiDump.isPublic(Attributes.getVisibility(constructor))) {
                    check(problems, type, JvmExtensionsKt.getSignature(constructor), null, constructor.getValueParameters());
                }
            }
            for (KmFunction function : kotlin.getFunctions()) {
                // A data class's equals is Kotlin's to write, without annotations: not checked (Java's tools take
                // Object.equals to accept null); a class that writes its own equals marks `other`.
                boolean generatedEquals = Attributes.getKind(function) == MemberKind.SYNTHESIZED && function.getName().equals("equals");
                if (ApiDump.isPublic(Attributes.getVisibility(function)) && function.getReceiverParameterType() == null && !generatedEquals) {
                    check(problems, type, JvmExtensionsKt.getSignature(function), function.getReturnType(), function.getValueParameters());
                }
            }
            for (KmProperty property : kotlin.getProperties()) {
                if (ApiDump.isPublic(Attributes.getVisibility(property)) && property.getReceiverParameterType() == null) {
                    check(problems, type, JvmExtensionsKt.getGetterSignature(property), property.getReturnType(), List.of());
                }
            }
        }
        return problems;
    }

    /** Adds a line to [problems] for each nullable of [returns] and [parameters] that the method with [signature] leaves unmarked. */
    private static void check(List<String> problems, Class<?> type, JvmMethodSignature signature, KmType returns, List<KmValueParameter> parameters) {
        Optional<Executable> member = signature == null ? Optional.empty() : javaMember(type, signature.toString());
        // Hidden from Java (@JvmSynthetic, a suspend function's Continuation), or not where its metadata says: nothing Java reads.
        if (member.isEmpty() || member.get().isSynthetic()) return;
        String name = type.getName() + "." + signature;
        if (returns != null && Attributes.isNullable(returns) && !marked(((java.lang.reflect.Method) member.get()).getAnnotatedReturnType())) {
            problems.add(name + " returns null unmarked");
        }
        AnnotatedType[] javaParameters = member.get().getAnnotatedParameterTypes();
        if (javaParameters.length != parameters.size()) return;
        for (int i = 0; i < parameters.size(); i++) {
            if (Attributes.isNullable(parameters.get(i).getType()) && !marked(javaParameters[i])) {
                problems.add(name + " takes null unmarked as " + parameters.get(i).getName());
            }
        }
    }

    private static boolean marked(AnnotatedType type) {
        return type.isAnnotationPresent(Nullable.class);
    }

    private static Optional<Executable> javaMember(Class<?> type, String signature) {
        return Stream.concat(Arrays.stream(type.getDeclaredMethods()), Arrays.stream(type.getDeclaredConstructors()))
                .filter(m -> ApiDump.signature(m).equals(signature))
                .findFirst();
    }
}
