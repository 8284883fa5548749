package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.sun.source.doctree.DocCommentTree;
import com.sun.source.doctree.DocTree;
import com.sun.source.doctree.ReturnTree;
import com.sun.source.doctree.ThrowsTree;
import com.sun.source.tree.ClassTree;
import com.sun.source.tree.CompilationUnitTree;
import com.sun.source.tree.MethodTree;
import com.sun.source.tree.Tree;
import com.sun.source.tree.VariableTree;
import com.sun.source.util.DocTrees;
import com.sun.source.util.JavacTask;
import com.sun.source.util.TreePath;
import com.sun.source.util.TreePathScanner;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.reflect.Field;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.lang.model.element.Modifier;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;

/**
 * Issue 10's last two "done when" items, read from the sources themselves: every public
 * method and constructor of {@code hitbox} and {@code hitbox.processing} states, in its own
 * javadoc, what a NaN does, what a missing object does, and what it answers when there is
 * nothing to answer; and no class is over {@value #MAX_LINES} lines without saying why in
 * its class doc.
 *
 * <p>The sources are parsed (not compiled) with the JDK's compiler tree API, so the rules
 * see exactly what a reader of the javadoc sees. A method is held to a rule by its
 * signature:
 * <ul>
 *   <li>a {@code float}, {@code double} or {@code float[]} parameter: the doc says
 *       "NaN" (what a NaN argument does, or that it throws); for a method on plain floats,
 *       a sentence about NaN gives the answer the catalog pins for it (its
 *       {@code NAN_ANSWER}, or false, 0 / NONE, -1, empty, null, +Infinity by return
 *       type);</li>
 *   <li>a parameter of a class type ({@code hitbox} only, where the bad-input catalog pins
 *       that every such method refuses null): an {@code @throws IllegalArgumentException}
 *       that mentions null;</li>
 *   <li>a constructor, or a method in {@link BadInputCatalogTest}'s {@code CHECKED} table:
 *       an {@code @throws IllegalArgumentException} (the catalog pins that it throws);</li>
 *   <li>an object answer: its {@code @return} says "null" (null when there is none, or never
 *       null) or, for a {@link Side}, "NONE"; a {@code float} time or distance: "Infinity";
 *       an {@code int} index: "-1".</li>
 * </ul>
 * A record whose canonical constructor is implicit is held to these rules in its class doc.
 * A class over {@value #MAX_LINES} lines must give its reason in its class doc, in the fixed
 * words "longer than most" (or "over the usual size", the words the first such notes used).
 * A class doc that states the class's size ("about 1,200 lines") states it within
 * {@value #SIZE_SLACK_PERCENT}% of the file's line count, so the reason cannot outlive the size.
 * Methods marked {@code @Override} are left to the method they override (the
 * {@link Shape} and {@link BroadPhase} methods are checked where they are declared). The
 * fixture tests show that a method without the sentences is reported, so the rules cannot
 * pass by finding nothing to check.
 */
class JavadocContractTest {

    /** The length above which a class must say why it is long. */
    static final int MAX_LINES = 450;

    /** How far a size stated in a class doc may be from the file's line count, in percent. */
    static final int SIZE_SLACK_PERCENT = 10;

    /** A size stated in a class doc: "about 1,200 lines", "(590 lines)". */
    private static final Pattern STATED_SIZE = Pattern.compile("\\b(\\d{1,3}(?:,\\d{3})*|\\d+) lines\\b");

    /** The phrase a long class's doc uses to give its reason. */
    private static final Pattern LONG_REASON = Pattern.compile("longer than most|over the usual size");

    /** The API: its public members are the promise whose contract this test reads. */
    private static final List<Path> API_ROOTS = List.of(Path.of("src/main/java/hitbox"),
            Path.of("src/processing/java/hitbox/processing"));

    /** Everything in the library, kernels included: a long class says why wherever it is. */
    private static final List<Path> ALL_ROOTS = List.of(Path.of("src/main/java/hitbox"),
            Path.of("src/main/java/hitbox/internal"), Path.of("src/processing/java/hitbox/processing"));

    /** Plain carriers of raw-float answers: their constructors take any float (the catalog's CARRIERS). */
    private static final Set<String> CARRIERS = Set.of("Vec", "Motion.Step", "Snap.Push");

    /** Classes whose methods that take an object check their floats too (the catalog's CHECKS_OBJECT_CALLS). */
    private static final Set<String> CHECKS_OBJECT_CALLS = Set.of("Response", "Sweep");

    private static final Pattern NAN = Pattern.compile("\\bNaN\\b");
    private static final Pattern NULL = Pattern.compile("\\bnull\\b");
    private static final Pattern NONE = Pattern.compile("\\bNONE\\b");
    private static final Pattern INFINITY = Pattern.compile("Infinity|POSITIVE_INFINITY");
    private static final Pattern MINUS_ONE = Pattern.compile("(?<![\\w.])-1\\b");
    /** Float answers that are a time or a distance, whose "nothing" is +Infinity. */
    private static final Pattern TIME_OR_DISTANCE = Pattern.compile("(?i).*(time|distance|impact|toi).*");
    /** Int answers that are an index, whose "nothing" is -1. */
    private static final Pattern INDEX = Pattern.compile("(?i)(first|indexOf.*|.*Index|colAt|rowAt|index)");

    // ------------------------------------------------------------------ the library

    @Test
    void everyPublicMethodAndConstructor_statesItsNanRangeAndNoResultBehaviour() {
        List<String> problems = problems(parse(sources(API_ROOTS)), Catalog.read());
        assertTrue(problems.isEmpty(), problems.size() + " public members do not state their contract:\n"
                + String.join("\n", problems));
    }

    @Test
    void everyLongClass_saysWhyInItsClassDoc() {
        List<String> problems = longClasses(parse(sources(ALL_ROOTS)));
        assertTrue(problems.isEmpty(), String.join("\n", problems));
    }

    @Test
    void everySizeAClassDocStates_isWithinTenPercentOfTheFile() {
        List<String> problems = staleSizes(parse(sources(ALL_ROOTS)));
        assertTrue(problems.isEmpty(), String.join("\n", problems));
    }

    @Test
    void theSourcesAndTheCatalogAreFound() {
        // Guards against a rule that passes by reading nothing.
        List<CompilationUnitTree> api = parse(sources(API_ROOTS)).units;
        assertTrue(api.size() > 30, "found " + api.size() + " API source files");
        List<CompilationUnitTree> all = parse(sources(ALL_ROOTS)).units;
        assertTrue(all.size() > api.size() + 30, "found " + all.size() + " source files in all");
        Catalog catalog = Catalog.read();
        assertTrue(catalog.checked.contains("Polygon.of") && catalog.checked.size() > 20, "CHECKED: " + catalog.checked);
        assertEquals("false", catalog.nanAnswers.get("Shape.contains"), "NAN_ANSWER: " + catalog.nanAnswers);
    }

    // ------------------------------------------------------------------ the rules catch what they should

    @Test
    void aMethodWithoutTheSentences_isReported() {
        String source = """
                package hitbox;
                /** A fixture. */
                public final class Fixture {
                    /**
                     * Makes one.
                     * @param r the radius
                     */
                    public Fixture(float r) { }
                    /**
                     * Does the shape hit? Compare it with null.
                     * @param x a position
                     * @param s a shape
                     * @return the hit
                     */
                    public Hit hit(float x, Shape s) { return null; }
                    /**
                     * When.
                     * @param vx a speed
                     * @return the time
                     */
                    public static float timeOfImpact(float vx) { return 0; }
                    /**
                     * Which one.
                     * @return its index
                     */
                    public int firstIndex() { return 0; }
                    /**
                     * Checked in the catalog.
                     * @param k a count
                     * @return a number
                     */
                    public int tiles(int k) { return k; }
                    /**
                     * A NaN answers null; never null otherwise.
                     * @param x a position
                     * @param s a shape
                     * @return the hit, or null
                     * @throws IllegalArgumentException if s is null
                     */
                    public Hit good(float x, Shape s) { return null; }
                    /**
                     * A NaN throws.
                     * @param x a position
                     * @return whether it touches
                     */
                    public static boolean touches(float x) { return false; }
                    /**
                     * A NaN answers 0 (the catalog's NAN_ANSWER).
                     * @param x a position
                     * @return the side
                     */
                    public static int side(float x) { return 0; }
                    /** Not public: not checked. @return x */
                    Hit hidden(float x) { return null; }
                    /** {@inheritDoc} */
                    @Override
                    public String toString() { return ""; }
                }
                """;
        List<String> problems = problems(parse(List.of(new Source("Fixture.java", source))),
                new Catalog(Set.of("Fixture.tiles"), Map.of("Fixture.side", "0")));
        assertEquals(List.of(
                "Fixture#Fixture(float r): no NaN statement (it takes a float/double/float[])",
                "Fixture#Fixture(float r): no @throws IllegalArgumentException (it checks its arguments)",
                "Fixture#hit(float x, Shape s): no NaN statement (it takes a float/double/float[])",
                "Fixture#hit(float x, Shape s): no @throws IllegalArgumentException naming null (it takes an object)",
                "Fixture#hit(float x, Shape s): no no-result statement in @return (null / never null / NONE)",
                "Fixture#timeOfImpact(float vx): no NaN statement (it takes a float/double/float[])",
                "Fixture#timeOfImpact(float vx): no no-result statement in @return (Infinity, for a time or distance)",
                "Fixture#firstIndex(): no no-result statement in @return (-1, for an index)",
                "Fixture#tiles(int k): no @throws IllegalArgumentException (it checks its arguments)",
                "Fixture#touches(float x): its NaN statement does not give the catalog's answer (false)"),
                problems);
    }

    @Test
    void aRecordWithAnImplicitConstructor_isHeldToItsClassDoc() {
        String source = """
                package hitbox;
                /**
                 * A fixture.
                 * @param x a value
                 */
                public record Pair(float x) { }
                """;
        assertEquals(List.of("Pair#Pair(float x): no NaN statement (it takes a float/double/float[])",
                        "Pair#Pair(float x): no @throws IllegalArgumentException (it checks its arguments)"),
                problems(parse(List.of(new Source("Pair.java", source))), new Catalog(Set.of(), Map.of())));
    }

    @Test
    void aLongClassWithoutItsReason_isReported() {
        String body = "    // filler\n".repeat(MAX_LINES);
        String quiet = "package hitbox;\n/** Long. */\nfinal class Quiet {\n" + body + "}\n";
        String said = "package hitbox;\n/** Long. This class is longer than most: a reason. */\nfinal class Said {\n"
                + body + "}\n";
        List<String> problems = longClasses(parse(List.of(new Source("Quiet.java", quiet), new Source("Said.java", said))));
        assertEquals(1, problems.size(), problems.toString());
        assertTrue(problems.get(0).startsWith("Quiet.java: " + (MAX_LINES + 4) + " lines"), problems.get(0));
    }

    @Test
    void aStaleStatedSize_isReported() {
        String body = "    // filler\n".repeat(100);
        String stale = "package hitbox;\n/** Long (about 1,200 lines): a reason. */\nfinal class Stale {\n" + body + "}\n";
        String near = "package hitbox;\n/** Long (about 100 lines): a reason. */\nfinal class Near {\n" + body + "}\n";
        List<String> problems = staleSizes(parse(List.of(new Source("Stale.java", stale), new Source("Near.java", near))));
        assertEquals(List.of("Stale.java: its class doc says 1,200 lines, the file has 104"), problems);
    }

    // ------------------------------------------------------------------ the checks

    /** Class docs whose stated size is more than {@link #SIZE_SLACK_PERCENT}% off the file's. */
    private static List<String> staleSizes(Parsed parsed) {
        List<String> out = new ArrayList<>();
        for (CompilationUnitTree unit : parsed.units) {
            long lines = parsed.lines(unit);
            for (Tree t : unit.getTypeDecls()) {
                String doc = parsed.docs.getDocComment(new TreePath(new TreePath(unit), t));
                if (doc == null) {
                    continue;
                }
                Matcher m = STATED_SIZE.matcher(doc);
                while (m.find()) {
                    long said = Long.parseLong(m.group(1).replace(",", ""));
                    if (Math.abs(said - lines) * 100 > SIZE_SLACK_PERCENT * lines) {
                        out.add(Path.of(unit.getSourceFile().getName()).getFileName() + ": its class doc says "
                                + m.group(1) + " lines, the file has " + lines);
                    }
                }
            }
        }
        return out;
    }

    /** One rule per line: "Class#method(params): what is missing". */
    private static List<String> problems(Parsed parsed, Catalog catalog) {
        List<String> out = new ArrayList<>();
        for (CompilationUnitTree unit : parsed.units) {
            boolean core = unit.getPackageName() != null && unit.getPackageName().toString().equals("hitbox");
            new TreePathScanner<Void, String>() {
                @Override
                public Void visitClass(ClassTree c, String outer) {
                    String name = outer == null ? c.getSimpleName().toString() : outer + "." + c.getSimpleName();
                    boolean visible = c.getModifiers().getFlags().contains(Modifier.PUBLIC)
                            || outer != null && isInterface(getCurrentPath().getParentPath().getLeaf());
                    if (!visible || isFunctional(c)) {
                        return null;  // not API, or a callback the user writes
                    }
                    boolean explicitCanonical = false;
                    for (Tree member : c.getMembers()) {
                        if (member instanceof MethodTree m) {
                            boolean ctor = m.getName().contentEquals("<init>");
                            if (ctor && c.getKind() == Tree.Kind.RECORD && sameTypes(m.getParameters(), recordComponents(c))) {
                                explicitCanonical = true;
                            }
                            boolean isPublic = m.getModifiers().getFlags().contains(Modifier.PUBLIC)
                                    || isInterface(c) && !m.getModifiers().getFlags().contains(Modifier.PRIVATE)
                                    || ctor && c.getKind() == Tree.Kind.RECORD && sameTypes(m.getParameters(), recordComponents(c));
                            if (!isPublic || overrides(m)) {
                                continue;
                            }
                            Doc doc = Doc.of(parsed.docs, new TreePath(getCurrentPath(), m));
                            check(out, name, c, m.getName().toString(), m.getParameters(), m.getReturnType(),
                                    doc, core, catalog);
                        }
                    }
                    if (c.getKind() == Tree.Kind.RECORD && !explicitCanonical && !recordComponents(c).isEmpty()) {
                        // The implicit canonical constructor: its contract is the record's own doc.
                        check(out, name, c, "<init>", recordComponents(c), null, Doc.of(parsed.docs, getCurrentPath()),
                                core, catalog);
                    }
                    return super.visitClass(c, name);
                }
            }.scan(unit, null);
        }
        return out;
    }

    private static void check(List<String> out, String owner, ClassTree c, String method,
            List<? extends VariableTree> params, Tree returns, Doc doc, boolean core, Catalog catalog) {
        boolean ctor = method.equals("<init>");
        String simple = owner.substring(owner.lastIndexOf('.') + 1);
        String where = owner + "#" + (ctor ? simple : method) + "(" + params.stream()
                .map(p -> p.getType() + " " + p.getName()).collect(Collectors.joining(", ")) + ")";
        if (doc == null) {
            out.add(where + ": no javadoc");
            return;
        }
        boolean floats = params.stream().anyMatch(p -> isFloaty(p.getType().toString()));
        boolean objects = params.stream().anyMatch(p -> !isPrimitive(p.getType().toString()));
        if (floats && !NAN.matcher(doc.all).find()) {
            out.add(where + ": no NaN statement (it takes a float/double/float[])");
        }
        boolean throwsIae = doc.throwsIae != null;
        String key = owner + "." + (ctor ? "new" : method);
        // The catalog calls a constructor checked when it is not a carrier's; with only int
        // parameters (a pixel's column and row) there is nothing for it to refuse.
        boolean checked = ctor && (floats || objects) && !CARRIERS.contains(owner) && c.getKind() != Tree.Kind.ENUM
                || !params.isEmpty() && catalog.checked.contains(key)
                || objects && CHECKS_OBJECT_CALLS.contains(owner);
        if (checked && !throwsIae) {
            out.add(where + ": no @throws IllegalArgumentException (it checks its arguments)");
        } else if (core && objects && !(throwsIae && NULL.matcher(doc.throwsIae).find())) {
            out.add(where + ": no @throws IllegalArgumentException naming null (it takes an object)");
        }
        if (returns == null || ctor) {
            return;
        }
        String type = returns.toString();
        if (core && floats && !checked && NAN.matcher(doc.all).find()) {
            // The NaN statement gives the answer the bad-input catalog pins for a NaN.
            Pattern want = nanAnswer(catalog.nanAnswers.get(key), owner, method, type);
            if (want != null && nanSentences(doc.all).stream().noneMatch(t -> want.matcher(t).find())) {
                out.add(where + ": its NaN statement does not give the catalog's answer ("
                        + want.pattern().replace("\\b", "") + ")");
            }
        }
        if (!isPrimitive(type) && !type.equals("void")) {
            boolean said = NULL.matcher(doc.returns).find() || type.equals("Side") && NONE.matcher(doc.returns).find();
            if (!said) {
                out.add(where + ": no no-result statement in @return (null / never null / NONE)");
            }
        } else if ((type.equals("float") || type.equals("double")) && TIME_OR_DISTANCE.matcher(method).matches()
                && !INFINITY.matcher(doc.returns).find()) {
            out.add(where + ": no no-result statement in @return (Infinity, for a time or distance)");
        } else if (type.equals("int") && INDEX.matcher(method).matches() && !MINUS_ONE.matcher(doc.returns).find()) {
            out.add(where + ": no no-result statement in @return (-1, for an index)");
        }
    }

    /** Classes over the limit whose class doc does not say why. */
    private static List<String> longClasses(Parsed parsed) {
        List<String> out = new ArrayList<>();
        for (CompilationUnitTree unit : parsed.units) {
            long lines = parsed.lines(unit);
            if (lines <= MAX_LINES) {
                continue;
            }
            for (Tree t : unit.getTypeDecls()) {
                String doc = parsed.docs.getDocComment(new TreePath(new TreePath(unit), t));
                if (doc == null || !LONG_REASON.matcher(doc).find()) {
                    out.add(Path.of(unit.getSourceFile().getName()).getFileName() + ": " + lines
                            + " lines, and its class doc does not say why it is \"longer than most\"");
                }
            }
        }
        return out;
    }

    // ------------------------------------------------------------------ helpers

    private static boolean isFloaty(String type) {
        return type.equals("float") || type.equals("double") || type.startsWith("float[") || type.startsWith("double[")
                || type.equals("float...") || type.equals("double...");
    }

    private static boolean isPrimitive(String type) {
        return Set.of("float", "double", "int", "long", "boolean", "byte", "short", "char").contains(type);
    }

    private static boolean isInterface(Tree t) {
        return t.getKind() == Tree.Kind.INTERFACE;
    }

    private static boolean isFunctional(ClassTree c) {
        return c.getModifiers().getAnnotations().stream()
                .anyMatch(a -> a.getAnnotationType().toString().endsWith("FunctionalInterface"));
    }

    private static boolean overrides(MethodTree m) {
        return m.getModifiers().getAnnotations().stream()
                .anyMatch(a -> a.getAnnotationType().toString().endsWith("Override"));
    }

    private static List<? extends VariableTree> recordComponents(ClassTree c) {
        List<VariableTree> out = new ArrayList<>();
        for (Tree member : c.getMembers()) {
            // A record's components are its non-static fields.
            if (member instanceof VariableTree v && !v.getModifiers().getFlags().contains(Modifier.STATIC)) {
                out.add(v);
            }
        }
        return out;
    }

    private static boolean sameTypes(List<? extends VariableTree> a, List<? extends VariableTree> b) {
        // A compact canonical constructor has its parameters filled in from the components.
        if (a.size() != b.size()) {
            return false;
        }
        for (int i = 0; i < a.size(); i++) {
            if (!a.get(i).getType().toString().equals(b.get(i).getType().toString())) {
                return false;
            }
        }
        return true;
    }

    /**
     * What a NaN statement must say, as a pattern: the catalog's answer for the method
     * ({@code NAN_ANSWER}), or the default it checks for the return type; null where the
     * catalog pins nothing but "does not throw".
     */
    private static Pattern nanAnswer(String listed, String owner, String method, String type) {
        if (listed != null) {
            return switch (listed) {
                case "0" -> Pattern.compile("\\b0\\b|NONE");
                case "-1" -> MINUS_ONE;
                case "false" -> Pattern.compile("\\bfalse\\b");
                case "NONE" -> NONE;
                case "velocity" -> Pattern.compile("unchanged|back");
                default -> null;  // "any"
            };
        }
        return switch (type) {
            case "boolean" -> Pattern.compile("\\bfalse\\b");
            case "int" -> method.equals("first") ? MINUS_ONE : Pattern.compile("\\b0\\b|NONE");
            case "int[]" -> Pattern.compile("\\bempty\\b");
            case "float" -> method.startsWith("distanceTo") || owner.equals("Sweep") || owner.equals("Separation") ? INFINITY : null;
            case "Push", "Snap.Push" -> NONE;
            case "Hit", "Contact", "RayHit", "Separation" -> NULL;
            default -> null;
        };
    }

    /** The sentences (and block tags) of a doc comment that mention NaN. */
    private static List<String> nanSentences(String doc) {
        List<String> out = new ArrayList<>();
        for (String part : doc.split("(?<=\\.)\\s+(?=[A-Z<{])|\\s(?=@\\w)")) {
            if (NAN.matcher(part).find()) {
                out.add(part);
            }
        }
        return out;
    }

    /**
     * The bad-input catalog's tables, read rather than copied, so the two cannot drift apart:
     * which methods check their arguments ({@code CHECKED}) and what a NaN answers where it is
     * not the default for the return type ({@code NAN_ANSWER}).
     */
    private record Catalog(Set<String> checked, Map<String, String> nanAnswers) {
        @SuppressWarnings("unchecked")
        static Catalog read() {
            try {
                Field checked = BadInputCatalogTest.class.getDeclaredField("CHECKED");
                Field answers = BadInputCatalogTest.class.getDeclaredField("NAN_ANSWER");
                checked.setAccessible(true);
                answers.setAccessible(true);
                return new Catalog((Set<String>) checked.get(null), (Map<String, String>) answers.get(null));
            } catch (ReflectiveOperationException ex) {
                throw new AssertionError("BadInputCatalogTest's CHECKED or NAN_ANSWER table is gone", ex);
            }
        }
    }

    // ------------------------------------------------------------------ parsing

    private record Source(String name, String text) {
    }

    /**
     * What a rule reads of one doc comment: all of it, its {@code @return} text, and its
     * {@code @throws IllegalArgumentException} text (null when it has none).
     */
    private record Doc(String all, String returns, String throwsIae) {
        static Doc of(DocTrees docs, TreePath path) {
            DocCommentTree tree = docs.getDocCommentTree(path);
            if (tree == null) {
                return null;
            }
            StringBuilder returns = new StringBuilder();
            String throwsIae = null;
            for (DocTree tag : tree.getBlockTags()) {
                if (tag instanceof ReturnTree r) {
                    returns.append(r.getDescription()).append(' ');
                } else if (tag instanceof ThrowsTree t
                        && t.getExceptionName().toString().endsWith("IllegalArgumentException")) {
                    throwsIae = (throwsIae == null ? "" : throwsIae + " ") + t.getDescription();
                }
            }
            return new Doc(docs.getDocComment(path), returns.toString(), throwsIae);
        }
    }

    private record Parsed(List<CompilationUnitTree> units, DocTrees docs) {
        long lines(CompilationUnitTree unit) {
            try {
                return unit.getSourceFile().getCharContent(true).toString().lines().count();
            } catch (IOException ex) {
                throw new UncheckedIOException(ex);
            }
        }
    }

    private static List<Source> sources(List<Path> roots) {
        List<Source> out = new ArrayList<>();
        for (Path root : roots) {
            assertTrue(Files.isDirectory(root), "no " + root.toAbsolutePath() + " (the tests run in the project folder)");
            try (Stream<Path> files = Files.list(root)) {
                for (Path p : files.filter(p -> p.toString().endsWith(".java")).sorted().toList()) {
                    out.add(new Source(p.toString(), Files.readString(p)));
                }
            } catch (IOException ex) {
                throw new UncheckedIOException(ex);
            }
        }
        return out;
    }

    private static Parsed parse(List<Source> sources) {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertTrue(javac != null, "the tests need a JDK (javax.tools finds no compiler)");
        StandardJavaFileManager files = javac.getStandardFileManager(null, null, null);
        List<JavaFileObject> objects = new ArrayList<>();
        for (Source s : sources) {
            objects.add(new SimpleJavaFileObject(URI.create("string:///" + s.name().replace('\\', '/')),
                    JavaFileObject.Kind.SOURCE) {
                @Override
                public CharSequence getCharContent(boolean ignoreEncodingErrors) {
                    return s.text();
                }
            });
        }
        JavacTask task = (JavacTask) javac.getTask(null, files, null, List.of("-proc:none"), null, objects);
        List<CompilationUnitTree> units = new ArrayList<>();
        try {
            task.parse().forEach(units::add);
        } catch (IOException ex) {
            throw new UncheckedIOException(ex);
        }
        return new Parsed(units, DocTrees.instance(task));
    }

}
