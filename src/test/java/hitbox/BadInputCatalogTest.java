package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.lang.reflect.Array;
import java.lang.reflect.Constructor;
import java.lang.reflect.Executable;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.Parameter;
import java.net.URISyntaxException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.IntConsumer;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * The bad-input catalog: every public constructor and method of package {@code hitbox},
 * found by reflection, called with one argument at a time replaced by a bad value (NaN,
 * infinities, the float extremes, -0, a negative size, huge and negative counts, null, empty,
 * odd and degenerate arrays, lists with a null), each call under its own time limit, so a
 * hang fails instead of sticking the build.
 *
 * <p>What the package documentation promises, checked for every call:
 * <ul>
 *   <li>Nothing throws but {@link IllegalArgumentException} (and
 *       {@link IndexOutOfBoundsException} for a grid cell outside the grid), and an
 *       exception about a parameter names that parameter (a word of its message).</li>
 *   <li>Checked methods (constructors, factories, methods on shapes and contacts) throw for
 *       NaN and infinite floats and for negative sizes.</li>
 *   <li>Methods on plain floats never throw, and a NaN gives the no-result of their kind of
 *       answer: false, 0 sides, -1, null, +Infinity, or the value back unchanged.</li>
 * </ul>
 * Reflection cannot infer which methods check and what each one answers for NaN; the tables
 * {@link #CHECKED}, {@link #NAN_ANSWER} and {@link #SIZES} say so, and a test fails if they
 * name a method that no longer exists.
 */
class BadInputCatalogTest {

    /** How long one call may take: a hang is a failure. */
    private static final Duration LIMIT = Duration.ofSeconds(5);

    // ------------------------------------------------------------------ the expectation tables

    /**
     * Methods that check their arguments as constructors do: NaN and infinite floats, and
     * negative sizes, throw an IllegalArgumentException naming the parameter. Keys are
     * "Class.method" ("Class.new" for constructors); every constructor is checked, except
     * Vec's (a plain value).
     */
    private static final Set<String> CHECKED = Set.of(
            "Rect.centered", "Rect.at", "Rect.translated", "Circle.translated", "Segment.translated",
            "Polygon.translated", "Ellipse.translated", "Capsule.translated", "Shape.translated",
            "Circle.rotated", "Segment.rotated", "Polygon.rotated", "Ellipse.rotated", "Capsule.rotated", "Shape.rotated",
            "Transform.of", "Transform.translation", "Transform.rotation", "Transform.scaling", "Polygon.regular", "Polygon.of",
            "Ray.between", "Sweep.timeOfImpact", "Sweep.move", "Response.pushOut",
            "Grid.parse", "Grid.fillRandom", "Grid.move", "Grid.fromPixels",
            // A broad phase refuses a bad box outright (issue 11), so a stored box always holds.
            "BroadPhase.put", "BroadPhase.query", "BroadPhase.raycast",
            // The world (issue 20): its numbers are positions, angles and moves, all refused when NaN or infinite.
            "World.add", "World.move", "World.queryPoint",
            "Body.moveTo", "Body.turnTo", "Body.turnBy",
            // The character (issue 28): moves, positions and settings; settings are sizes (px, degrees).
            "World.addCharacter", "CharacterBody.move", "CharacterBody.maxSlope", "CharacterBody.stepHeight",
            "CharacterBody.snap", "CharacterBody.up");

    /** The world the catalog calls World's and Body's methods on; every Body argument is a new body of it. */
    private static final World WORLD = new World();

    /** Plain carriers of raw-float answers, documented to take any float. */
    private static final Set<Class<?>> CARRIERS = Set.of(Vec.class, Motion.Step.class, Snap.Push.class);

    /** Classes whose methods that take an object (a shape, a contact) check their floats too. */
    private static final Set<Class<?>> CHECKS_OBJECT_CALLS = Set.of(Response.class, Sweep.class);

    private static boolean takesObjectsOnly(Executable e) {
        return false;
    }

    private static boolean takesObjects(Executable e) {
        for (Class<?> t : e.getParameterTypes()) {
            if (!t.isPrimitive()) {
                return true;
            }
        }
        return false;
    }

    /** Methods whose NaN answer is not the default for their return type: "any" means only "does not throw". */
    private static final Map<String, String> NAN_ANSWER = Map.ofEntries(
            Map.entry("Collide.lineSide", "0"),
            Map.entry("Grid.colAt", "-1"),
            Map.entry("Grid.rowAt", "-1"),
            Map.entry("Grid.cellCenterX", "any"), Map.entry("Grid.cellCenterY", "any"),
            Map.entry("Edges.bounceX", "any"), Map.entry("Edges.bounceY", "any"),
            Map.entry("Edges.circleWrapX", "any"), Map.entry("Edges.circleWrapY", "any"),
            Map.entry("Edges.rectWrapX", "any"), Map.entry("Edges.rectWrapY", "any"),
            Map.entry("Edges.circleClampX", "any"), Map.entry("Edges.circleClampY", "any"),
            Map.entry("Edges.rectClampX", "any"), Map.entry("Edges.rectClampY", "any"),
            Map.entry("Snap.standY", "any"), Map.entry("Snap.landY", "any"),
            Map.entry("Motion.reverseX", "any"), Map.entry("Motion.reverseY", "any"),
            Map.entry("Motion.bounce", "any"),
            Map.entry("Response.bounce", "velocity"), Map.entry("Response.slide", "velocity"),
            Map.entry("Side.ofNormal", "NONE"),
            Map.entry("Vec.dot", "any"),
            Map.entry("Hybrid.Counter.add", "any"),
            Map.entry("Segment.side", "0"),
            // a position handed back: NaN in, NaN out
            Map.entry("Transform.applyX", "any"), Map.entry("Transform.applyY", "any"),
            // Shape declares the point test once for every kind (each kind is asked in containment_isInTheCatalog)
            Map.entry("Shape.contains", "false"));

    /** Parameter names that are sizes: a negative value is refused by checked methods. */
    private static final Set<String> SIZES = Set.of("w", "h", "r", "radius", "width", "height", "cellSize",
            "cellWidth", "cellHeight", "maxDistance", "depth", "distance", "r1", "r2", "w1", "h1", "w2", "h2",
            "radiusX", "radiusY", "radiusX1", "radiusY1", "radiusX2", "radiusY2", "px", "degrees");

    /**
     * Parameters a method on plain numbers still refuses when bad: the numbers a sketch chooses
     * rather than computes (issue 30's one rule for a restitution, wherever one is taken).
     */
    private static final Set<String> CHECKED_PARAMETERS = Set.of("Response.bounce.restitution");

    /** Parameters that may be +Infinity in a checked method (documented). */
    private static final Set<String> MAY_BE_INFINITE = Set.of("Ray.new.maxDistance", "BroadPhase.raycast.maxDistance");

    // ------------------------------------------------------------------ the catalog

    private final Map<String, Integer> perMethod = new LinkedHashMap<>();

    @TestFactory
    Stream<DynamicTest> everyPublicMethodAndConstructor_withEveryBadValue() {
        List<DynamicTest> tests = new ArrayList<>();
        for (Executable e : executables()) {
            Object[] baseline = baseline(e);
            if (baseline == null) {
                tests.add(DynamicTest.dynamicTest(key(e) + ": a baseline call", () ->
                        fail("no good arguments found for " + e + "; add them to goodValues")));
                continue;
            }
            Parameter[] params = e.getParameters();
            for (int i = 0; i < params.length; i++) {
                for (Bad bad : badValues(params[i].getType())) {
                    Object[] args = baseline.clone();
                    args[i] = bad.value();
                    int index = i;
                    tests.add(DynamicTest.dynamicTest(key(e) + "(" + params[i].getName() + " = " + bad.name() + ")",
                            () -> assertTimeoutPreemptively(LIMIT, () -> check(e, args, index, bad))));
                }
            }
        }
        return tests.stream();
    }

    @Test
    void catalog_coversThePackage() {
        List<Executable> all = executables();
        long values = 0;
        for (Executable e : all) {
            for (Parameter p : e.getParameters()) {
                values += badValues(p.getType()).size();
            }
        }
        // The size reported in the closing note of issue 10: methods and constructors, and calls.
        System.out.println("bad-input catalog: " + all.size() + " public methods and constructors, "
                + values + " calls with a bad argument");
        assertTrue(all.size() > 200, "found " + all.size());
        Set<String> keys = new TreeSet<>();
        all.forEach(e -> keys.add(key(e)));
        for (String k : CHECKED) {
            assertTrue(keys.contains(k), "CHECKED names a method that is gone: " + k);
        }
        for (String k : NAN_ANSWER.keySet()) {
            assertTrue(keys.contains(k), "NAN_ANSWER names a method that is gone: " + k);
        }
    }

    @Test
    void containment_isInTheCatalog() {
        // Issue 23's containment: Shape.contains(Shape) refuses null naming "other" (the raw
        // forms Collide.rectContainsRect and circleContainsCircle went in issue 30); the catalog
        // above finds it by reflection. Shape declares contains once for every kind (the catalog
        // calls it on one receiver), so each kind's refusal is asked here.
        Set<String> keys = new TreeSet<>();
        executables().forEach(e -> keys.add(key(e) + "/" + e.getParameterCount()));
        for (String k : List.of("Shape.contains/1")) {
            assertTrue(keys.contains(k), "not in the catalog: " + k);
        }
        for (Shape s : List.of(new Circle(1, 2, 3), new Rect(0, 0, 4, 5), new Segment(0, 0, 3, 4), Polygon.of(0, 0, 10, 0, 0, 10),
                new Ellipse(1, 2, 4, 3), new Ellipse(1, 2, 4, 3, 0.5f), new Capsule(0, 0, 3, 4, 2))) {
            for (org.junit.jupiter.api.function.Executable call : List.<org.junit.jupiter.api.function.Executable>of(
                    () -> s.contains(null), () -> s.overlaps(null))) {
                IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, call, s.toString());
                assertTrue(e.getMessage().contains("other"), s + ": " + e.getMessage());
            }
            // and its point test answers false for a NaN (NAN_ANSWER's "Shape.contains"), whichever coordinate
            assertTrue(!s.contains(Float.NaN, 1) && !s.contains(1, Float.NaN) && !s.contains(Float.NaN, Float.NaN), s.toString());
        }
    }

    @Test
    void polygonOf_namesTheRightCorner() {
        // the second corner is vertex 1, as x(1) reads it
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> Polygon.of(0, 0, Float.NaN, 0, 0, 1));
        assertTrue(e.getMessage().startsWith("x1 "), e.getMessage());
        e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> Polygon.regular(0, 0, 10, Integer.MAX_VALUE, 0));
        assertTrue(e.getMessage().startsWith("sides "), e.getMessage());
    }

    // ------------------------------------------------------------------ one call

    private record Bad(String name, Object value, Kind kind) {
    }

    private enum Kind { NAN, INFINITE, EXTREME, NEGATIVE, HUGE_COUNT, NULL, CONTENT }

    private static void check(Executable e, Object[] args, int index, Bad bad) {
        Parameter param = e.getParameters()[index];
        String key = key(e);
        boolean checked = e instanceof Constructor<?> ? !CARRIERS.contains(e.getDeclaringClass())
                : CHECKED.contains(key) || takesObjects(e) && CHECKS_OBJECT_CALLS.contains(e.getDeclaringClass())
                || CHECKED_PARAMETERS.contains(key + "." + param.getName());
        Object result;
        try {
            result = invoke(e, args);
        } catch (IllegalArgumentException ex) {
            String message = ex.getMessage();
            assertTrue(message != null && !message.isBlank(), key + ": an exception without a message");
            if (bad.kind() != Kind.CONTENT) {
                assertTrue(names(message, param.getName()), key + "(" + param.getName() + " = " + bad.name()
                        + "): the message does not name the parameter: " + message);
            }
            if (!checked && bad.kind() != Kind.NULL && bad.kind() != Kind.CONTENT && bad.kind() != Kind.HUGE_COUNT
                    && param.getType().isPrimitive()) {
                fail(key + "(" + param.getName() + " = " + bad.name() + ") works on plain numbers and must not throw: " + message);
            }
            return;
        } catch (IndexOutOfBoundsException ex) {
            // A grid cell, or a manifold's point, that must name an existing one.
            assertTrue(e.getDeclaringClass() == Grid.class || e.getDeclaringClass() == Manifold.class
                    || e.getDeclaringClass() == Collisions.class, key + ": " + ex);
            return;
        } catch (Throwable ex) {
            throw new AssertionError(key + "(" + param.getName() + " = " + bad.name() + ") threw " + ex, ex);
        }
        if (bad.kind() == Kind.NULL) {
            fail(key + "(" + param.getName() + " = null) accepted null");
        }
        if (checked && param.getType() == float.class) {
            boolean infiniteAllowed = MAY_BE_INFINITE.contains(key + "." + param.getName());
            if (bad.kind() == Kind.NAN || (bad.kind() == Kind.INFINITE && !infiniteAllowed)) {
                fail(key + "(" + param.getName() + " = " + bad.name() + ") must throw, gave " + result);
            }
            if (bad.kind() == Kind.NEGATIVE && SIZES.contains(param.getName())) {
                fail(key + "(" + param.getName() + " = -1) is a size and must throw, gave " + result);
            }
        }
        if (!checked && bad.kind() == Kind.NAN && !takesObjectsOnly(e)) {
            checkNoResult(e, args, index, result);
        }
    }

    /** A NaN answers "no result" for the method's kind of answer. */
    private static void checkNoResult(Executable e, Object[] args, int index, Object result) {
        String key = key(e);
        String want = NAN_ANSWER.get(key);
        if ("any".equals(want)) {
            return;
        }
        Class<?> type = e instanceof Method m ? m.getReturnType() : void.class;
        String what = key + " with a NaN " + e.getParameters()[index].getName() + " gave " + result;
        if (want != null) {
            switch (want) {
                case "0" -> assertEquals(0, ((Number) result).intValue(), what);
                case "-1" -> assertEquals(-1, ((Number) result).intValue(), what);
                case "false" -> assertEquals(false, result, what);
                case "NONE" -> assertEquals(Side.NONE, result, what);
                case "velocity" -> assertEquals(new Vec((Float) args[0], (Float) args[1]), result,
                        what + ": the velocity must come back unchanged");
                default -> fail("unknown expectation " + want);
            }
            return;
        }
        if (type == boolean.class) {
            assertEquals(false, result, what);
        } else if (type == float.class) {
            // Times and distances: +Infinity; other floats (positions) may be NaN.
            if (e.getName().startsWith("distanceTo") || e.getDeclaringClass() == Sweep.class
                    || e.getDeclaringClass() == Separation.class) {
                assertEquals(Float.POSITIVE_INFINITY, result, what);
            }
        } else if (type == int.class) {
            int expected = e.getName().equals("first") ? -1 : 0;
            assertEquals(expected, result, what);
        } else if (type == int[].class) {
            assertEquals(0, ((int[]) result).length, what);
        } else if (type == Snap.Push.class) {
            assertEquals(Side.NONE, ((Snap.Push) result).side(), what);
        } else if (type == Hit.class || type == Contact.class || type == RayHit.class || type == Separation.class
                || type == Manifold.class) {
            assertEquals(null, result, what);
        }
    }

    /** Does the message name the parameter, as a word? */
    private static boolean names(String message, String name) {
        return Pattern.compile("(?<![\\w])" + Pattern.quote(name) + "(?![\\w])").matcher(message).find();
    }

    private static Object invoke(Executable e, Object[] args) throws Throwable {
        try {
            if (e instanceof Constructor<?> c) {
                return c.newInstance(args);
            }
            Method m = (Method) e;
            Object receiver = Modifier.isStatic(m.getModifiers()) ? null : receiver(m.getDeclaringClass());
            return m.invoke(receiver, args);
        } catch (InvocationTargetException ex) {
            throw ex.getCause();
        }
    }

    // ------------------------------------------------------------------ what to call, with what

    private static String key(Executable e) {
        String owner = e.getDeclaringClass().getName().substring("hitbox.".length()).replace('$', '.');
        return owner + "." + (e instanceof Constructor<?> ? "new" : e.getName());
    }

    /** Every public constructor and method declared by a public class of the package (nested ones too). */
    private static List<Executable> executables() {
        List<Executable> out = new ArrayList<>();
        for (Class<?> c : publicClasses()) {
            if (c.isAnnotationPresent(FunctionalInterface.class)) {
                continue;  // a callback the user writes (PairConsumer, BoxConsumer, RayVisitor)
            }
            if (c.isEnum() || c.isInterface() && c != Shape.class && c != BroadPhase.class) {
                // Enums: their own static helpers only.
                for (Method m : c.getDeclaredMethods()) {
                    if (Modifier.isPublic(m.getModifiers()) && !m.isSynthetic() && m.getParameterCount() > 0
                            && !m.getName().equals("valueOf")) {
                        out.add(m);
                    }
                }
                continue;
            }
            if (!Modifier.isAbstract(c.getModifiers()) || c == Shape.class) {
                for (Constructor<?> k : c.getConstructors()) {
                    if (k.getParameterCount() > 0) {
                        out.add(k);
                    }
                }
            }
            for (Method m : c.getDeclaredMethods()) {
                if (Modifier.isPublic(m.getModifiers()) && !m.isSynthetic() && m.getParameterCount() > 0
                        && !m.getName().equals("equals")) {
                    out.add(m);
                }
            }
        }
        out.sort((a, b) -> (key(a) + Arrays.toString(a.getParameterTypes())).compareTo(key(b) + Arrays.toString(b.getParameterTypes())));
        return out;
    }

    private static List<Class<?>> publicClasses() {
        File dir;
        try {
            dir = new File(Circle.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException ex) {
            throw new IllegalStateException(ex);
        }
        File pkg = new File(dir, "hitbox");
        String[] names = pkg.list((d, n) -> n.endsWith(".class"));
        assertTrue(names != null && names.length > 0, "no classes in " + pkg);
        List<Class<?>> out = new ArrayList<>();
        for (String n : names) {
            try {
                Class<?> c = Class.forName("hitbox." + n.substring(0, n.length() - ".class".length()));
                boolean visible = Modifier.isPublic(c.getModifiers())
                        && (c.getEnclosingClass() == null || Modifier.isPublic(c.getEnclosingClass().getModifiers()));
                if (visible && !c.isAnonymousClass()) {
                    out.add(c);
                }
            } catch (ClassNotFoundException ex) {
                throw new IllegalStateException(ex);
            }
        }
        return out;
    }

    /** An object to call an instance method on, for each class that has them. */
    private static Object receiver(Class<?> c) {
        if (c == Circle.class) {
            return new Circle(1, 2, 3);
        }
        if (c == Rect.class) {
            return new Rect(0, 0, 4, 5);
        }
        if (c == Segment.class) {
            return new Segment(0, 0, 3, 4);
        }
        if (c == Ellipse.class) {
            return new Ellipse(1, 2, 4, 3);
        }
        if (c == Capsule.class) {
            return new Capsule(0, 0, 3, 4, 2);
        }
        if (c == Polygon.class || c == Shape.class) {
            return Polygon.of(0, 0, 10, 0, 0, 10);
        }
        if (c == Transform.class) {
            return Transform.rotation(0.3f, 1, 2);
        }
        if (c == Grid.class) {
            Grid g = new Grid(4, 3, 10);
            g.set(1, 1, Grid.SOLID);
            return g;
        }
        if (c == PixelMask.class) {
            return PixelMask.parse("#.\n##");
        }
        if (c == Ray.class) {
            return new Ray(0, 0, 1, 0);
        }
        if (c == Vec.class) {
            return new Vec(1, 2);
        }
        if (c == Sweep.Move.class) {
            return new Sweep.Move(0, 0, 0, 0, java.util.Set.of());
        }
        if (c == Snap.Push.class) {
            return new Snap.Push(0, 0, Side.TOP);
        }
        if (c == Hybrid.Counter.class) {
            return new Hybrid.Counter();
        }
        if (c == Contact.class) {
            return new Contact(0, 1, 1);
        }
        if (c == Manifold.class) {
            return new Manifold(new Contact(0, 1, 2), 2, 0, 0, 1, 4, 0, 2);
        }
        if (c == PathCosts.class) {
            return PathCosts.steps();
        }
        if (c == TerrainColors.class) {
            return new TerrainColors().put(0x000000, Grid.EMPTY).put(0xFFFFFF, Grid.SOLID);
        }
        if (c == World.class) {
            return WORLD;
        }
        if (c == Body.class) {
            return WORLD.add(new Rect(30, 30, 10, 10));
        }
        if (c == CharacterBody.class) {
            return WORLD.addCharacter(new Rect(60, 30, 10, 10));
        }
        if (c == Collisions.class) {
            // one collision: a box dropped onto another
            World w = new World();
            w.add(new Rect(0, 10, 10, 10));
            return w.move(w.add(new Rect(0, 0, 10, 5)), 0, 10);
        }
        if (c == BodyEvent.class) {
            return new BodyEvent(BodyEvent.Kind.ENTER, WORLD.add(new Circle(0, 0, 1)), WORLD.add(new Circle(1, 0, 1)));
        }
        if (c == BroadPhase.class) {
            BroadPhase b = BroadPhase.grid();
            for (int id = 0; id < 8; id++) {
                b.put(id, 10 * id, 5, 12, 12);
            }
            return b;
        }
        throw new IllegalStateException("no receiver for " + c);
    }

    /**
     * Good arguments for a call: the first of a few candidate sets (distinct small numbers,
     * fitting objects) that the call accepts. Null if none works.
     */
    private static Object[] baseline(Executable e) {
        Class<?>[] types = e.getParameterTypes();
        for (int attempt = 0; attempt < 7; attempt++) {
            Object[] args = new Object[types.length];
            for (int i = 0; i < types.length; i++) {
                args[i] = good(types[i], i, attempt, e);
            }
            try {
                Object[] copy = args.clone();
                assertTimeoutPreemptively(LIMIT, () -> invoke(e, copy));
                return args;
            } catch (Throwable ignored) {
                // try the next candidate set
            }
        }
        return null;
    }

    private static Object good(Class<?> type, int i, int attempt, Executable e) {
        if (type == float.class) {
            // Distinct small numbers, not on one line; later attempts use 0.5 or 1 for all (shares, restitution, t).
            return switch (attempt) {
                case 0 -> (float) (1 + (i * 7) % 11);
                case 1 -> (float) ((i * 5) % 9);
                case 2 -> 0.5f;
                case 3 -> 1f;
                case 4 -> (float) (2 + i);
                case 5 -> i == 0 ? 0f : 1f;
                default -> 0f;
            };
        }
        if (type == double.class) {
            return 1.0 + i;
        }
        if (type == int.class) {
            return switch (attempt) {
                case 0 -> 3 + i;
                case 1 -> 1;
                case 2 -> 0;
                default -> 2;
            };
        }
        if (type == long.class) {
            return 7L;
        }
        if (type == boolean.class) {
            return attempt % 2 == 0;
        }
        if (type == float[].class) {
            return new float[] {0, 0, 10, 0, 0, 10};
        }
        if (type == int[].class) {
            // A route of one cell (PathCosts.costOf), or one opaque black pixel for the
            // fromPixels methods, whose sizes are all 1 on the odd attempts.
            return attempt % 2 == 0 ? new int[] {0} : new int[] {0xff000000};
        }
        if (type == TerrainColors.class) {
            return new TerrainColors().put(0x000000, Grid.EMPTY).put(0xFFFFFF, Grid.SOLID);
        }
        if (type == PathCosts.class) {
            return PathCosts.steps();
        }
        if (type == Grid.class) {
            return new Grid(4, 3, 10);
        }
        if (type == boolean[][].class) {
            return new boolean[][] {{true, false}, {false, true}};
        }
        if (type == String.class) {
            return "#.\n.#";
        }
        if (type == Side.class) {
            return Side.TOP;
        }
        if (type == Transform.class) {
            // a turn and a uniform scale, which every kind of shape takes
            return Transform.rotation(0.5f).then(Transform.scaling(2, 2));
        }
        if (type == Set.class) {
            return EnumSet.of(Side.LEFT);
        }
        if (type == Side[].class) {
            return new Side[] {Side.LEFT};
        }
        if (type == IntConsumer.class) {
            return (IntConsumer) k -> { };
        }
        if (type == PairConsumer.class) {
            return (PairConsumer) (a, b) -> { };
        }
        if (type == BoxConsumer.class) {
            return (BoxConsumer) (key, x, y, w, h) -> { };
        }
        if (type == RayVisitor.class) {
            return (RayVisitor) (id, distance) -> true;
        }
        if (type == Ray.class) {
            return new Ray(0, 0, 1, 0);
        }
        if (type == BroadPhase.class) {
            return e.getDeclaringClass() == World.class ? BroadPhase.grid() : receiver(BroadPhase.class);
        }
        if (type == Body.class) {
            return WORLD.add(attempt % 2 == 0 ? new Rect(30, 30, 10, 10) : new Circle(0, 0, 3));
        }
        if (type == java.util.function.BiConsumer.class) {
            return (java.util.function.BiConsumer<?, ?>) (a, b) -> { };
        }
        if (type == CollisionFilter.class) {
            return (CollisionFilter) (m, o) -> Reaction.SLIDE;
        }
        if (type == java.util.function.Predicate.class) {
            return (java.util.function.Predicate<?>) b -> true;
        }
        if (type == Reaction.class) {
            return Reaction.SLIDE;
        }
        if (type == BodyEvent.Kind.class) {
            return BodyEvent.Kind.ENTER;
        }
        if (type == Hit.class) {
            return new Hit(0.5f, 0, 1, Side.TOP);
        }
        if (type == RayHit.class) {
            return new RayHit(1, 2, 3, 1, 0);
        }
        if (type == Hybrid.Stage.class) {
            return Hybrid.Stage.PRECISE;
        }
        if (type == Hybrid.Result.class) {
            return new Hybrid.Result(false, Hybrid.Stage.PRECISE);
        }
        if (type == PixelMask.class) {
            return PixelMask.parse("#");
        }
        if (type == Contact.class) {
            return new Contact(0, 1, 1);
        }
        if (type == Manifold.class) {
            return receiver(Manifold.class);
        }
        if (type == Vec.class) {
            return new Vec(1, 2);
        }
        if (type == Circle.class) {
            return new Circle(40, 40, 5);
        }
        if (type == Rect.class) {
            return attempt % 2 == 0 ? new Rect(30, 30, 10, 10) : new Rect(0, 0, 2, 2);
        }
        if (type == Segment.class) {
            return new Segment(50, 0, 50, 20);
        }
        if (type == Ellipse.class) {
            return new Ellipse(40, 40, 6, 4);
        }
        if (type == Capsule.class) {
            return new Capsule(30, 40, 50, 40, 3);
        }
        if (type == Polygon.class) {
            return Polygon.of(20, 20, 30, 20, 20, 30);
        }
        if (type == Shape.class) {
            return attempt % 2 == 0 ? new Circle(40, 40, 5) : new Rect(30, 30, 10, 10);
        }
        if (type == Rect[].class) {
            return new Rect[] {new Rect(30, 30, 10, 10)};
        }
        if (type == Shape[].class) {
            return new Shape[] {new Rect(30, 30, 10, 10)};
        }
        if (type == List.class && e.getParameters()[i].getName().matches("out|changes")) {
            return new ArrayList<>();  // a list the method fills (issue 29's forms): the caller's, which takes adds
        }
        if (type == List.class || type == Iterable.class || type == Collection.class) {
            return List.of(new Rect(30, 30, 10, 10));
        }
        if (type == Object.class) {
            return new Object();
        }
        throw new IllegalStateException("no good value for " + type + " in " + e);
    }

    /** The bad values for a parameter of this type. */
    private static List<Bad> badValues(Class<?> type) {
        List<Bad> out = new ArrayList<>();
        if (type == float.class) {
            out.add(new Bad("NaN", Float.NaN, Kind.NAN));
            out.add(new Bad("+Infinity", Float.POSITIVE_INFINITY, Kind.INFINITE));
            out.add(new Bad("-Infinity", Float.NEGATIVE_INFINITY, Kind.INFINITE));
            out.add(new Bad("MAX_VALUE", Float.MAX_VALUE, Kind.EXTREME));
            out.add(new Bad("-MAX_VALUE", -Float.MAX_VALUE, Kind.EXTREME));
            out.add(new Bad("MIN_VALUE", Float.MIN_VALUE, Kind.EXTREME));
            out.add(new Bad("-0", -0f, Kind.EXTREME));
            out.add(new Bad("-1", -1f, Kind.NEGATIVE));
        } else if (type == double.class) {
            out.add(new Bad("NaN", Double.NaN, Kind.NAN));
            out.add(new Bad("+Infinity", Double.POSITIVE_INFINITY, Kind.INFINITE));
            out.add(new Bad("-MAX_VALUE", -Double.MAX_VALUE, Kind.EXTREME));
        } else if (type == int.class) {
            out.add(new Bad("Integer.MAX_VALUE", Integer.MAX_VALUE, Kind.HUGE_COUNT));
            out.add(new Bad("Integer.MIN_VALUE", Integer.MIN_VALUE, Kind.HUGE_COUNT));
            out.add(new Bad("-1", -1, Kind.HUGE_COUNT));
        } else if (type == long.class) {
            out.add(new Bad("Long.MIN_VALUE", Long.MIN_VALUE, Kind.EXTREME));
        } else if (type == boolean.class) {
            return out;
        } else {
            out.add(new Bad("null", null, Kind.NULL));
            if (type == float[].class) {
                out.add(new Bad("{}", new float[0], Kind.CONTENT));
                out.add(new Bad("{NaN...}", new float[] {Float.NaN, 0, 10, 0, 0, 10}, Kind.CONTENT));
                out.add(new Bad("{odd}", new float[] {0, 0, 10, 0, 0}, Kind.CONTENT));
                out.add(new Bad("{collinear}", new float[] {0, 0, 1, 1, 2, 2}, Kind.CONTENT));
                out.add(new Bad("{+-MAX_VALUE}", new float[] {-Float.MAX_VALUE, -Float.MAX_VALUE, Float.MAX_VALUE,
                        -Float.MAX_VALUE, 0, Float.MAX_VALUE}, Kind.CONTENT));
                out.add(new Bad("{Infinity...}", new float[] {0, 0, Float.POSITIVE_INFINITY, 0, 0, 10}, Kind.CONTENT));
            } else if (type == Transform.class) {
                // singular, huge, stretched one way (a capsule has no exact image), a shear
                out.add(new Bad("scaling(0, 0)", Transform.scaling(0, 0), Kind.CONTENT));
                out.add(new Bad("scaling(0, 1)", Transform.scaling(0, 1), Kind.CONTENT));
                out.add(new Bad("scaling(MAX_VALUE)", Transform.scaling(Float.MAX_VALUE, Float.MAX_VALUE), Kind.CONTENT));
                out.add(new Bad("scaling(2, 1)", Transform.scaling(2, 1), Kind.CONTENT));
                out.add(new Bad("shear", Transform.of(1, 3, 0, 0, 1, 0), Kind.CONTENT));
            } else if (type == int[].class) {
                out.add(new Bad("{}", new int[0], Kind.CONTENT));
            } else if (type == boolean[][].class) {
                out.add(new Bad("{}", new boolean[0][], Kind.CONTENT));
                out.add(new Bad("{null}", new boolean[][] {null}, Kind.CONTENT));
                out.add(new Bad("{ragged}", new boolean[][] {{true}, {true, false}}, Kind.CONTENT));
                out.add(new Bad("{{}}", new boolean[][] {{}}, Kind.CONTENT));
            } else if (type == String.class) {
                out.add(new Bad("\"\"", "", Kind.CONTENT));
                out.add(new Bad("\"\\t\"", "\t", Kind.CONTENT));
                out.add(new Bad("\"#\\n##\"", "#\n##", Kind.CONTENT));
            } else if (type == List.class || type == Iterable.class || type == Collection.class) {
                out.add(new Bad("[null]", Arrays.asList(new Rect(30, 30, 10, 10), null), Kind.CONTENT));
                out.add(new Bad("[]", List.of(), Kind.CONTENT));
            } else if (type.isArray()) {
                out.add(new Bad("{null}", Array.newInstance(type.getComponentType(), 1), Kind.CONTENT));
                out.add(new Bad("{}", Array.newInstance(type.getComponentType(), 0), Kind.CONTENT));
            } else if (type == Set.class) {
                out.add(new Bad("{null}", new java.util.HashSet<>(Arrays.asList((Side) null)), Kind.CONTENT));
            }
        }
        return out;
    }
}
