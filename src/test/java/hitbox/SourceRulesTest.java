package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Rules of the code's layout that the architecture page and {@code Tolerance} claim, read off
 * the sources so that the claims cannot drift from the code:
 * <ul>
 *   <li><b>One question of kind.</b> {@code ShapeKind.of} is the library's only
 *       {@code instanceof} chain over the six shape kinds; any other {@code instanceof} of a
 *       kind (or a {@code case Circle c} pattern) is in {@link #KIND_TESTS_ALLOWED}, each with
 *       its reason, and there as many times as it says.</li>
 *   <li><b>Every tolerance named and indexed.</b> No bare tolerance literal (a number between 0
 *       and 0.1) in the library outside a {@code static final} declaration; every such named
 *       constant is declared in {@code Tolerance} or named in its class doc's index.</li>
 *   <li><b>Imports run one way.</b> A kernel ({@code hitbox.internal}) uses from the API only
 *       the values it takes and gives ({@link #KERNEL_MAY_USE}: the shapes, the answers, the
 *       structures it implements or reads), and calls no API method but a value's factory: it
 *       never asks a question of the API's classes ({@code Collide}, {@code Sweep}, ...), which
 *       answer by calling the kernels.</li>
 * </ul>
 * Each rule has a fixture test that plants a violation and sees it reported, so no rule passes
 * by finding nothing.
 */
class SourceRulesTest {

    private static final Path LIBRARY = Path.of("src/main/java/hitbox");
    private static final Path KERNELS = Path.of("src/main/java/hitbox/internal");
    private static final Path ADAPTER = Path.of("src/processing/java/hitbox/processing");
    private static final Path TOLERANCE = KERNELS.resolve("Tolerance.java");

    private static final String KINDS = "Circle|Rect|Segment|Polygon|Ellipse|Capsule";
    private static final Pattern KIND_TEST = Pattern.compile(
            "\\binstanceof\\s+(" + KINDS + ")\\b|\\bcase\\s+(" + KINDS + ")\\s+\\w+\\s*(->|:)");

    /**
     * The {@code instanceof}s of a kind outside {@code ShapeKind}, by file, with how many and
     * why. Documented in {@code docs/architecture.md} ("One home per shape kind").
     */
    static final Map<String, Integer> KIND_TESTS_ALLOWED = Map.of(
            // ShapeKind.of: the one chain the dispatch is built on.
            "ShapeKind.java", 6,
            // Overlaps.circleWith's measured fast path for a circle against a circle or a rectangle.
            "Overlaps.java", 2,
            // Polygon.equals(Object): equality, not a question of kind.
            "Polygon.java", 1,
            // Poses: inside the dispatch's SEGMENT, CAPSULE case, which of the two it is.
            "Poses.java", 1);

    /** The API types a kernel may use: the values it takes and gives and the structures it serves. */
    static final Set<String> KERNEL_MAY_USE = Set.of(
            "Shape", "Circle", "Rect", "Segment", "Polygon", "Ellipse", "Capsule", "Transform",
            "Contact", "Manifold", "Separation", "Hit", "RayHit", "Side", "Vec", "Ray",
            "BroadPhase", "BoxConsumer", "PairConsumer", "RayVisitor", "Grid", "PathCosts", "TerrainColors");

    /** Members of other API types a kernel may name: an answer type nested in a question's class, and a constant. */
    static final Set<String> KERNEL_MAY_NAME = Set.of("Sweep.Move", "Sweep.MAX_SLIDES");

    /** The static methods of API types a kernel may call: the values' factories. */
    static final Set<String> KERNEL_MAY_CALL = Set.of("Polygon.of", "Side.ofNormal");

    /**
     * Calls back up into the API that are still to be moved down, each by the trim of the raw
     * forms they belong to (issue 30): the test fails once one of them is gone, so that this
     * list only shrinks.
     */
    static final Set<String> KERNEL_CALLS_PENDING = Set.of();

    private static final Pattern NUMBER = Pattern.compile(
            "(?<![\\w.])((?:\\d+\\.\\d*|\\.\\d+|\\d+)(?:[eE][-+]?\\d+)?[fFdD]?|0[xX][0-9a-fA-F.]+[pP][-+]?\\d+[fFdD]?)(?![\\w.])");
    private static final Pattern CONSTANT = Pattern.compile(
            "static\\s+final\\s+(?:float|double)\\s+([^;]*);", Pattern.DOTALL);

    // ------------------------------------------------------------------ the rules on the library

    @Test
    void onlyShapeKindAndTheAllowList_askWhichKindAShapeIs() {
        List<String> problems = kindTests(sources(LIBRARY, KERNELS, ADAPTER), KIND_TESTS_ALLOWED);
        assertTrue(problems.isEmpty(), String.join("\n", problems));
    }

    @Test
    void noBareToleranceLiteral_inTheLibrary() {
        List<String> problems = bareTolerances(sources(LIBRARY, KERNELS, ADAPTER));
        assertTrue(problems.isEmpty(), problems.size() + " bare tolerance literals; name them and list them in"
                + " Tolerance's index:\n" + String.join("\n", problems));
    }

    @Test
    void everyNamedTolerance_isInTolerancesIndex() {
        List<String> problems = unindexedTolerances(sources(LIBRARY, KERNELS, ADAPTER), toleranceDoc(read(TOLERANCE)));
        assertTrue(problems.isEmpty(), String.join("\n", problems));
    }

    @Test
    void kernelsUseFromTheApiOnlyTheValuesTheyTakeAndGive() {
        List<String> problems = kernelUses(sources(KERNELS), apiTypes());
        assertTrue(problems.isEmpty(), String.join("\n", problems));
    }

    @Test
    void theReadmesModuleSentence_isTheModuleInfos() {
        String info = strip(read(Path.of("src/main/java/module-info.java")));
        String readme = read(Path.of("README.md"));
        assertTrue(info.contains("module hitbox") && info.contains("exports hitbox;") && !info.contains("exports hitbox.internal"),
                "module-info.java no longer exports the API alone: " + info);
        assertTrue(readme.contains("the jar is the module `hitbox` (`requires hitbox;`), which exports\nthe API alone"),
                "the README's sentence on the module path no longer says what module-info.java makes the jar");
        assertTrue(!readme.toLowerCase().contains("automatic module"), "the README calls the jar an automatic module");
    }

    @Test
    void theSourcesAreFound() {
        assertTrue(sources(LIBRARY).size() > 40, "API sources: " + sources(LIBRARY).size());
        assertTrue(sources(KERNELS).size() > 40, "kernel sources: " + sources(KERNELS).size());
        assertTrue(apiTypes().containsAll(Set.of("Collide", "Sweep", "World", "Circle")), "API types: " + apiTypes());
        assertTrue(toleranceDoc(read(TOLERANCE)).contains("Mover.SKIN"), "Tolerance's index was not read");
    }

    // ------------------------------------------------------------------ the rules catch what they should

    @Test
    void aPlantedKindTest_isReported() {
        Map<String, String> files = Map.of(
                "Planted.java", "class Planted { boolean f(Shape s) { return s instanceof Ellipse; } }",
                "Switch.java", "class Switch { int f(Shape s) { return switch (s) { case Circle c -> 1; default -> 0; }; } }",
                "Quiet.java", "class Quiet { /* s instanceof Circle */ String t = \"instanceof Rect\"; }");
        assertEquals(List.of("Planted.java: 1 test(s) of a shape's kind (line 1); allowed: 0",
                        "Switch.java: 1 test(s) of a shape's kind (line 1); allowed: 0"),
                kindTests(files, Map.of()));
    }

    @Test
    void aPlantedBareTolerance_isReported() {
        Map<String, String> files = Map.of(
                "Planted.java", "class Planted {\n static final double OK = 1e-9;\n boolean f(double d) { return d < 1e-7; }\n}",
                "Quiet.java", "class Quiet { double half = 0.5, one = 1.0; // 1e-9 in a comment\n }");
        assertEquals(List.of("Planted.java:3: 1e-7"), bareTolerances(files));
    }

    @Test
    void aPlantedUnindexedTolerance_isReported() {
        Map<String, String> files = Map.of("Planted.java",
                "class Planted {\n static final double LISTED = 1e-9, HIDDEN = 2e-9;\n static final int COUNT = 3;\n}");
        assertEquals(List.of("Planted.HIDDEN (2e-9) is not in Tolerance's index"),
                unindexedTolerances(files, "{@code Planted.LISTED} (1e-9)"));
    }

    @Test
    void aPlantedCallBackUp_isReported() {
        Map<String, String> files = Map.of(
                "Planted.java", "class Planted { boolean f(Rect r) { return Collide.rectRect(0, 0, 1, 1, r.x(), r.y(), r.w(), r.h()); } }",
                "Asks.java", "class Asks { Object f(Shape s) { return Sweep.timeOfImpact(s, 1, 0, s); } }",
                "Fine.java", "class Fine { Object f(float[] xy) { Sweep.Move m = null; return Polygon.of(xy); } }");
        assertEquals(List.of("Asks.java:1: uses Sweep.timeOfImpact", "Planted.java:1: uses Collide.rectRect"),
                kernelUses(files, Set.of("Collide", "Sweep", "Polygon", "Rect", "Shape")));
    }

    // ------------------------------------------------------------------ the checks

    /** Files with more tests of a shape's kind than the allow-list gives them. */
    static List<String> kindTests(Map<String, String> files, Map<String, Integer> allowed) {
        List<String> out = new ArrayList<>();
        for (Map.Entry<String, String> f : new TreeMap<>(files).entrySet()) {
            String code = strip(f.getValue());
            List<Integer> lines = new ArrayList<>();
            Matcher m = KIND_TEST.matcher(code);
            while (m.find()) {
                lines.add(lineOf(code, m.start()));
            }
            int may = allowed.getOrDefault(f.getKey(), 0);
            if (lines.size() != may) {
                out.add(f.getKey() + ": " + lines.size() + " test(s) of a shape's kind (line "
                        + lines.stream().map(String::valueOf).collect(Collectors.joining(", ")) + "); allowed: " + may);
            }
        }
        return out;
    }

    /** Number literals between 0 and 0.1 outside {@code static final} declarations. */
    static List<String> bareTolerances(Map<String, String> files) {
        List<String> out = new ArrayList<>();
        for (Map.Entry<String, String> f : new TreeMap<>(files).entrySet()) {
            String code = blankConstants(strip(f.getValue()));
            Matcher m = NUMBER.matcher(code);
            while (m.find()) {
                if (small(m.group(1))) {
                    out.add(f.getKey() + ":" + lineOf(code, m.start()) + ": " + m.group(1));
                }
            }
        }
        return out;
    }

    /** Named constants whose value holds a number between 0 and 0.1 and that Tolerance's index does not name. */
    static List<String> unindexedTolerances(Map<String, String> files, String index) {
        List<String> out = new ArrayList<>();
        for (Map.Entry<String, String> f : new TreeMap<>(files).entrySet()) {
            String owner = f.getKey().replace(".java", "");
            if (owner.equals("Tolerance")) {
                continue;
            }
            Matcher m = CONSTANT.matcher(strip(f.getValue()));
            while (m.find()) {
                for (String part : m.group(1).split(",(?=\\s*[A-Z_][A-Z0-9_]*\\s*=)")) {
                    String name = part.substring(0, part.indexOf('=')).trim();
                    String value = part.substring(part.indexOf('=') + 1).trim();
                    Matcher n = NUMBER.matcher(value);
                    boolean tolerance = false;
                    while (n.find()) {
                        tolerance |= small(n.group(1));
                    }
                    if (tolerance && !Pattern.compile("\\b" + owner + "[.#]" + name + "\\b").matcher(index).find()) {
                        out.add(owner + "." + name + " (" + value + ") is not in Tolerance's index");
                    }
                }
            }
        }
        return out;
    }

    /** A kernel's uses of API types beyond the values it takes and gives, and its calls up. */
    static List<String> kernelUses(Map<String, String> files, Set<String> api) {
        List<String> out = new ArrayList<>();
        Pattern use = Pattern.compile("\\b(" + String.join("|", api) + ")\\b(?:\\s*\\.\\s*([A-Za-z_]\\w*)(\\s*\\()?)?");
        Set<String> pendingSeen = new java.util.HashSet<>();
        for (Map.Entry<String, String> f : new TreeMap<>(files).entrySet()) {
            String code = strip(f.getValue());
            Matcher m = use.matcher(code);
            while (m.find()) {
                if (m.start() > 0 && code.charAt(m.start() - 1) == '.' && !code.startsWith("hitbox.", m.start() - 7)) {
                    continue; // a member of something else; hitbox.Rect is a use of Rect
                }
                String type = m.group(1), member = m.group(2);
                String named = member == null ? type : type + "." + member;
                boolean call = m.group(3) != null && member != null && Character.isLowerCase(member.charAt(0));
                boolean fine = call ? KERNEL_MAY_CALL.contains(named)
                        : KERNEL_MAY_USE.contains(type) || KERNEL_MAY_NAME.contains(named);
                if (KERNEL_CALLS_PENDING.contains(f.getKey() + ":" + named)) {
                    pendingSeen.add(f.getKey() + ":" + named);
                    fine = true;
                }
                if (!fine) {
                    out.add(f.getKey() + ":" + lineOf(code, m.start()) + ": uses " + named);
                }
            }
        }
        if (files.size() > 10) {
            for (String pending : KERNEL_CALLS_PENDING) {
                if (!pendingSeen.contains(pending)) {
                    out.add(pending + " is no longer called: take it off KERNEL_CALLS_PENDING");
                }
            }
        }
        return out;
    }

    // ------------------------------------------------------------------ reading the sources

    /** The top-level public types of the API package. */
    private static Set<String> apiTypes() {
        return sources(LIBRARY).keySet().stream().filter(n -> !n.equals("package-info.java") && !n.equals("module-info.java"))
                .map(n -> n.replace(".java", "")).collect(Collectors.toSet());
    }

    /** The class doc of Tolerance: its index. */
    private static String toleranceDoc(String source) {
        return source.substring(0, source.indexOf("public final class Tolerance"));
    }

    /** The {@code .java} files directly in the folders, by file name. */
    private static Map<String, String> sources(Path... folders) {
        Map<String, String> out = new TreeMap<>();
        for (Path folder : folders) {
            try (Stream<Path> files = Files.list(folder)) {
                files.filter(p -> p.toString().endsWith(".java")).forEach(p -> out.put(p.getFileName().toString(), read(p)));
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return out;
    }

    private static String read(Path p) {
        try {
            return Files.readString(p);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The code without comments, strings and character literals, line breaks kept. */
    static String strip(String source) {
        StringBuilder out = new StringBuilder(source.length());
        int i = 0, n = source.length();
        while (i < n) {
            char c = source.charAt(i);
            if (c == '/' && i + 1 < n && source.charAt(i + 1) == '/') {
                while (i < n && source.charAt(i) != '\n') {
                    i++;
                }
            } else if (c == '/' && i + 1 < n && source.charAt(i + 1) == '*') {
                int end = source.indexOf("*/", i + 2);
                end = end < 0 ? n : end + 2;
                for (; i < end; i++) {
                    if (source.charAt(i) == '\n') {
                        out.append('\n');
                    }
                }
            } else if (c == '"' || c == '\'') {
                boolean block = c == '"' && source.startsWith("\"\"\"", i);
                int j = i + (block ? 3 : 1);
                while (j < n && !(block ? source.startsWith("\"\"\"", j) : source.charAt(j) == c)) {
                    if (source.charAt(j) == '\\') {
                        j++;
                    } else if (source.charAt(j) == '\n') {
                        out.append('\n');
                    }
                    j++;
                }
                out.append(c).append(c);
                i = Math.min(n, j + (block ? 3 : 1));
            } else {
                out.append(c);
                i++;
            }
        }
        return out.toString();
    }

    /** The code with each {@code static final float/double} declaration blanked, line breaks kept. */
    private static String blankConstants(String code) {
        Matcher m = CONSTANT.matcher(code);
        StringBuilder out = new StringBuilder();
        int last = 0;
        while (m.find()) {
            out.append(code, last, m.start()).append(m.group().replaceAll("[^\n]", " "));
            last = m.end();
        }
        return out.append(code.substring(last)).toString();
    }

    /** Is the literal a number strictly between 0 and 0.1 in size: a tolerance's, not a count's or a half's? */
    private static boolean small(String literal) {
        String t = literal.replaceAll("[fFdD]$", "");
        double v = t.toLowerCase().startsWith("0x") ? Double.parseDouble(t + (t.toLowerCase().contains("p") ? "" : "p0"))
                : Double.parseDouble(t);
        return v > 0 && v < 0.1;
    }

    private static int lineOf(String code, int at) {
        int line = 1;
        for (int i = 0; i < at; i++) {
            if (code.charAt(i) == '\n') {
                line++;
            }
        }
        return line;
    }
}
