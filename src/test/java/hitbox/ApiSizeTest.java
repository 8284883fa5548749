package hitbox;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The size of the API, counted by reflection over the compiled {@code hitbox} package (issue
 * 30): every public method of every public type (nested ones too, when every type around them
 * is public), a method declared in a type counted in that type (so a record's override of
 * {@link Shape#overlaps} counts once in the record and once in {@code Shape}), and left out:
 * record accessors, {@code equals}, {@code hashCode} and {@code toString}, an enum's
 * {@code values} and {@code valueOf}, and synthetic and bridge methods. Constructors and
 * fields are not methods and are not counted. {@code hitbox.internal} is not API.
 *
 * <p>Run it with {@code gradle test -Ptests.select='hitbox\.ApiSizeTest'}; it writes the count
 * per type to {@code build/api-size.txt} and fails if the API grows past {@link #LIMIT}, the
 * count when it was last trimmed (docs/architecture.md states both).
 */
class ApiSizeTest {

    /**
     * The count after issue 30's second trim (299, under the 300; 424 after the first, 433
     * with issue 29's nine world calls), and issue 29's pose teleport {@code Body.moveTo(x, y,
     * angle)} (300, the limit; docs/architecture.md gives the reason); lower it when
     * the API shrinks, never raise it without a reason in the docs.
     */
    static final int LIMIT = 300;

    @Test
    void publicMethods_countedByReflection_stayWithinTheLimit() throws IOException, URISyntaxException, ClassNotFoundException {
        Map<String, Integer> perType = count();
        int total = perType.values().stream().mapToInt(Integer::intValue).sum();
        StringBuilder report = new StringBuilder();
        report.append("public methods in hitbox (record accessors, Object's methods, enum values/valueOf left out): ")
                .append(total).append(" in ").append(perType.size()).append(" public types\n");
        perType.entrySet().stream().sorted((a, b) -> b.getValue() - a.getValue())
                .forEach(e -> report.append(String.format("%4d %s%n", e.getValue(), e.getKey())));
        Path out = Paths.get("build", "api-size.txt");
        Files.createDirectories(out.getParent());
        Files.writeString(out, report, StandardCharsets.UTF_8);
        System.out.print(report);
        assertTrue(total <= LIMIT, "the API has " + total + " public methods, more than the " + LIMIT
                + " it was trimmed to (build/api-size.txt lists them by type)");
    }

    /** Public methods per public type of the package hitbox, by the rule in the class comment. */
    static Map<String, Integer> count() throws IOException, URISyntaxException, ClassNotFoundException {
        Path root = Paths.get(Shape.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        List<String> names = new ArrayList<>();
        try (Stream<Path> files = Files.list(root.resolve("hitbox"))) {
            files.map(p -> p.getFileName().toString()).filter(f -> f.endsWith(".class"))
                    .forEach(f -> names.add("hitbox." + f.substring(0, f.length() - ".class".length())));
        }
        Map<String, Integer> perType = new TreeMap<>();
        for (String name : names) {
            Class<?> c = Class.forName(name, false, Shape.class.getClassLoader());
            if (!isApi(c)) {
                continue;
            }
            Set<String> accessors = new HashSet<>();
            if (c.isRecord()) {
                for (var component : c.getRecordComponents()) {
                    accessors.add(component.getName());
                }
            }
            int n = 0;
            for (Method m : c.getDeclaredMethods()) {
                if (!Modifier.isPublic(m.getModifiers()) || m.isSynthetic() || m.isBridge()) {
                    continue;
                }
                String mn = m.getName();
                int args = m.getParameterCount();
                boolean accessor = args == 0 && accessors.contains(mn);
                boolean objects = (mn.equals("equals") && args == 1) || ((mn.equals("hashCode") || mn.equals("toString")) && args == 0);
                boolean enums = c.isEnum() && Modifier.isStatic(m.getModifiers()) && (mn.equals("values") || mn.equals("valueOf"));
                if (!accessor && !objects && !enums) {
                    n++;
                }
            }
            perType.put(c.getName().substring("hitbox.".length()), n);
        }
        return perType;
    }

    private static boolean isApi(Class<?> c) {
        for (Class<?> e = c; e != null; e = e.getEnclosingClass()) {
            if (!Modifier.isPublic(e.getModifiers())) {
                return false;
            }
        }
        return !c.isAnonymousClass() && !c.isLocalClass();
    }
}
