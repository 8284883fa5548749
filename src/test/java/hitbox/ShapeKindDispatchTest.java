package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Set;
import java.util.Map;
import java.util.function.Consumer;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * Every operation reaches every kind of shape: the kinds are read from
 * {@code Shape.class.getPermittedSubclasses()}, not from a list kept here, so a seventh kind
 * fails this test (named) until it has a sample below, a {@link ShapeKind} constant, and an
 * answer from every operation, one kind at a time and for every ordered pair of kinds.
 *
 * <p>The samples of all kinds cover the square [-2, 2] x [-2, 2] about the origin (a segment
 * crosses it), so every pair overlaps: each pair must then give an answer that says so
 * (overlaps, a contact, an immediate hit), never an exception or a miss. The answers' values
 * are the pair tests' business; here a missing route shows as a {@link ClassCastException},
 * an {@link IllegalStateException} from {@link ShapeKind#of}, or a wrong kind of answer.
 */
class ShapeKindDispatchTest {

    /** Samples per kind: plain and awkward ones (turned, concave, flat-sided). */
    private static final Map<Class<?>, List<Shape>> SAMPLES = new LinkedHashMap<>();

    static {
        SAMPLES.put(Circle.class, List.of(new Circle(0, 0, 10)));
        SAMPLES.put(Rect.class, List.of(new Rect(-8, -6, 16, 12)));
        SAMPLES.put(Segment.class, List.of(new Segment(-9, -3, 9, 4)));
        SAMPLES.put(Polygon.class, List.of(
                Polygon.of(-10, -8, 10, -8, 11, 8, -9, 9),
                // concave: a notch cut into the top, the origin still inside
                Polygon.of(-10, -10, -3, -10, 0, -4, 3, -10, 10, -10, 10, 10, -10, 10)));
        SAMPLES.put(Ellipse.class, List.of(new Ellipse(0, 0, 12, 6), new Ellipse(0, 0, 12, 6, 0.7f)));
        SAMPLES.put(Capsule.class, List.of(new Capsule(-6, -2, 6, 3, 4)));
    }

    /** The kinds, as the sealed interface lists them. */
    private static List<Class<?>> kinds() {
        return Arrays.asList(Shape.class.getPermittedSubclasses());
    }

    /** The samples of a kind; fails, naming the kind, when there are none. */
    private static List<Shape> samples(Class<?> kind) {
        List<Shape> samples = SAMPLES.get(kind);
        if (samples == null || samples.isEmpty()) {
            fail("no sample shape for kind " + kind.getSimpleName() + ": add one to ShapeKindDispatchTest.SAMPLES");
        }
        return samples;
    }

    @Test
    void everyPermittedKind_hasASampleAndItsOwnConstant() {
        List<String> missing = new ArrayList<>();
        for (Class<?> kind : kinds()) {
            if (!SAMPLES.containsKey(kind)) {
                missing.add(kind.getSimpleName() + " has no sample");
                continue;
            }
            for (Shape s : samples(kind)) {
                ShapeKind k = ShapeKind.of(s);
                if (!k.name().equals(kind.getSimpleName().toUpperCase())) {
                    missing.add(kind.getSimpleName() + " is told apart as " + k);
                }
            }
        }
        assertEquals(List.of(), missing);
        assertEquals(kinds().size(), ShapeKind.values().length, "one ShapeKind constant per permitted kind");
        assertEquals(SAMPLES.size(), kinds().size(), "a sample for a kind that Shape does not permit");
    }

    @Test
    void of_null_isRefusedNamingTheShape() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ShapeKind.of(null));
        assertTrue(e.getMessage().contains("shape"), e.getMessage());
    }

    // ---------------------------------------------------------------- one kind at a time

    @TestFactory
    Stream<DynamicTest> everyKind_everyUnaryOperation() {
        List<DynamicTest> tests = new ArrayList<>();
        for (Class<?> kind : kinds()) {
            String name = kind.getSimpleName();
            tests.add(each(name, "contains", s -> assertTrue(s.contains(0.5f, 0.25f) || !ShapeKind.of(s).hasArea())));
            tests.add(each(name, "bounds and Bounds' extents", s -> {
                Rect b = s.bounds();
                assertTrue(b.x() <= -2 && b.y() <= -2 && b.right() >= 2 && b.bottom() >= 2 || !ShapeKind.of(s).hasArea(), b.toString());
                assertTrue(b.x() <= Extents.minX(s) && Extents.minX(s) <= Extents.maxX(s) && Extents.maxX(s) <= (double) b.x() + b.w());
                assertTrue(b.y() <= Extents.minY(s) && Extents.minY(s) <= Extents.maxY(s) && Extents.maxY(s) <= (double) b.y() + b.h());
            }));
            tests.add(each(name, "translated", s -> {
                Shape moved = s.translated(100, -50);
                assertSame(s.getClass(), moved.getClass());
                assertEquals(s.bounds().x() + 100, moved.bounds().x(), 1e-3);
                assertEquals(s.bounds().y() - 50, moved.bounds().y(), 1e-3);
            }));
            tests.add(each(name, "transformed", s -> {
                // a turn, a mirror and a uniform scale (a similarity every kind takes), with a move
                Transform t = Transform.rotation(0.7f).then(Transform.scaling(-2, 2)).then(Transform.translation(300, 100));
                Shape image = s.transformed(t);
                assertSame(s.getClass() == Rect.class ? Polygon.class : s.getClass(), image.getClass());
                assertEquals(image, Transforms.apply(s, t), "the kernel's own route");
                // the image of an inside point is inside the image (the sample holds (0.5, 0.25))
                assertTrue(image.contains(t.applyX(0.5f, 0.25f), t.applyY(0.5f, 0.25f)) || !ShapeKind.of(s).hasArea());
                assertTrue(image.bounds().x() > 250 && image.bounds().y() > 50, image.bounds().toString());
            }));
            tests.add(each(name, "rotated", s -> {
                Shape turned = s.rotated(0.4f, 1000, 0);
                assertSame(s.getClass() == Rect.class ? Polygon.class : s.getClass(), turned.getClass());
                Shape quarter = s.rotated((float) Math.PI / 2, 0, 0);
                assertSame(s.getClass(), quarter.getClass(), "a quarter turn keeps every kind");
                // turning (0.5, 0.25) by a quarter turn clockwise on screen gives (-0.25, 0.5)
                assertTrue(quarter.contains(-0.25f, 0.5f) || !ShapeKind.of(s).hasArea());
                assertTrue(turned.bounds().y() < -350 && turned.bounds().x() > 50, "turned clockwise about (1000, 0), it rises: " + turned.bounds());
            }));
            tests.add(each(name, "Ray.cast", s -> {
                RayHit hit = new Ray(-100, 0.5f, 1, 0).cast(s);
                assertNotNull(hit, "a ray along y = 0.5 from the left must hit");
                assertTrue(hit.distance() > 80 && hit.distance() <= 100, "distance " + hit.distance());
                assertNull(new Ray(-100, 0.5f, -1, 0).cast(s), "a ray away from it must miss");
            }));
            tests.add(each(name, "Supports.support", s -> {
                Rect b = s.bounds();
                assertEquals(Extents.maxX(s), Supports.support(s, 1, 0), 1e-3 * Math.max(1, b.w()));
                assertEquals(-Extents.minY(s), Supports.support(s, 0, -1), 1e-3 * Math.max(1, b.h()));
            }));
            tests.add(each(name, "ConvexSweep.pieces", s -> assertTrue(!ConvexSweep.pieces(s).isEmpty())));
            tests.add(each(name, "Edges.crossed", s -> {
                assertEquals(Set.of(Side.LEFT, Side.TOP), Edges.crossed(s, 200, 200), "it reaches past x = 0 and y = 0");
                assertEquals(Set.of(), Edges.crossed(s.translated(100, 100), 200, 200));
            }));
            tests.add(each(name, "Grid.overlapsSolid", s -> {
                Grid grid = Grid.parse("""
                        ........
                        ........
                        ..#.....
                        ........
                        ........
                        ........
                        ........
                        ........
                        """, 10);
                assertTrue(grid.overlapsSolid(s.translated(25, 25)), "over the solid cell");
                assertTrue(!grid.overlapsSolid(s.translated(55, 55)), "clear of it, inside the grid");
                assertTrue(grid.overlapsSolid(s.translated(75, 55)), "reaching past the grid's right edge");
            }));
            tests.add(each(name, "Sweep.turningTimeOfImpact against it", s -> {
                Polygon blade = Polygon.of(-40, -1, -30, -1, -30, 1, -40, 1);
                Hit hit = Sweep.turningTimeOfImpact(blade, -35, 0, 40, 0, 0.5f, s);
                assertNotNull(hit, "a blade moving into it must hit");
                assertTrue(hit.t() > 0 && hit.t() < 1, "t " + hit.t());
            }));
        }
        return tests.stream();
    }

    /** A test of one operation on every sample of a kind, named by both, that fails naming the sample. */
    private static DynamicTest each(String kind, String operation, Consumer<Shape> check) {
        return DynamicTest.dynamicTest(kind + ": " + operation, () -> {
            Class<?> c = kinds().stream().filter(k -> k.getSimpleName().equals(kind)).findFirst().orElseThrow();
            for (Shape s : samples(c)) {
                try {
                    check.accept(s);
                } catch (AssertionError | RuntimeException e) {
                    throw new AssertionError(kind + " " + operation + " on " + s + ": " + e, e);
                }
            }
        });
    }

    // ---------------------------------------------------------------- every ordered pair

    @TestFactory
    Stream<DynamicTest> everyOrderedPair_everyPairOperation() {
        List<DynamicTest> tests = new ArrayList<>();
        for (Class<?> first : kinds()) {
            for (Class<?> second : kinds()) {
                String name = first.getSimpleName() + " x " + second.getSimpleName();
                tests.add(pair(first, second, name, "overlaps", (a, b) -> {
                    assertTrue(a.overlaps(b), "the samples overlap");
                    assertEquals(a.overlaps(b), b.overlaps(a), "both ways round");
                    assertEquals(a.overlaps(b), Overlaps.test(a, b), "the library's own route");
                    Shape far = b.translated(500, 0);
                    assertTrue(!a.overlaps(far) && !far.overlaps(a), "far apart");
                }));
                tests.add(pair(first, second, name, "contains(Shape)", (a, b) -> {
                    assertEquals(a.contains(b), Containment.test(a, b), "the library's own route");
                    assertTrue(!a.contains(b.translated(500, 0)), "far apart");
                    assertTrue(!ShapeKind.of(a).hasArea() || a.contains(tiny(b)), "a small one of its kind about (0.5, 0.25)");
                    if (!ShapeKind.of(a).hasArea()) {
                        assertTrue(a.contains(new Segment(0, 0.5f, 9, 4)) && !a.contains(tiny(new Circle(0, 0, 1))),
                                "a segment holds a piece of itself, nothing with area");
                    }
                    if (a.getClass() == b.getClass()) {
                        assertTrue(a.contains(a) && b.contains(b), "itself");
                    }
                }));
                tests.add(pair(first, second, name, "Hybrid.check", (a, b) -> {
                    assertTrue(Hybrid.check(a, b).overlaps());
                    Hybrid.Result apart = Hybrid.check(a, b.translated(0, 40));
                    assertTrue(!apart.overlaps() && apart.decidedBy() != Hybrid.Stage.PRECISE, apart.toString());
                }));
                tests.add(pair(first, second, name, "contact", (a, b) -> {
                    if (!ShapeKind.of(a).hasArea() || !ShapeKind.of(b).hasArea()) {
                        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> a.contact(b));
                        assertTrue(e.getMessage().contains("Segment"), e.getMessage());
                        return;
                    }
                    Contact c = a.contact(b);
                    assertNotNull(c, "overlapping shapes have a contact");
                    assertEquals(1, Math.hypot(c.nx(), c.ny()), 1e-4);
                    assertTrue(c.depth() > 0);
                    Contact back = b.contact(a);
                    assertNotNull(back);
                    assertEquals(c.depth(), back.depth(), 1e-3 * c.depth());
                    assertNull(a.contact(b.translated(500, 0)), "far apart");
                }));
                tests.add(pair(first, second, name, "separation", (a, b) -> {
                    assertNull(Separation.between(a, b), "overlapping shapes have no separation");
                    assertNull(Separation.between(b, a));
                    Shape far = b.translated(500, 0);
                    Separation s = Separation.between(a, far), back = Separation.between(far, a);
                    assertNotNull(s, "far apart");
                    assertNotNull(back, "far apart, the other way round");
                    double gap = Extents.minX(far) - Extents.maxX(a);
                    assertTrue(s.distance() >= gap - 1e-3 && s.distance() < 500, "distance " + s.distance() + ", boxes " + gap + " apart");
                    assertEquals(s.distance(), back.distance(), 1e-4 * s.distance());
                    assertEquals(s.distance(), Math.hypot(s.bx() - s.ax(), s.by() - s.ay()), 1e-3);
                    assertTrue(SeparationOracleTest.toOutline(a, s.ax(), s.ay()) < 1e-3, "a's point on a: " + s);
                    assertTrue(SeparationOracleTest.toOutline(far, s.bx(), s.by()) < 1e-3, "b's point on b: " + s);
                }));
                tests.add(pair(first, second, name, "Contact.manifold", (a, b) -> {
                    if (!ShapeKind.of(a).hasArea() || !ShapeKind.of(b).hasArea()) {
                        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Contact.manifold(a, b));
                        assertTrue(e.getMessage().contains("Segment"), e.getMessage());
                        return;
                    }
                    Manifold m = Contact.manifold(a, b);
                    assertNotNull(m, "overlapping shapes have a manifold");
                    assertEquals(a.contact(b), m.contact(), "the contact of Contact.between");
                    assertTrue(m.pointCount() == 1 || m.pointCount() == 2, m.toString());
                    for (int i = 0; i < m.pointCount(); i++) {
                        // Every sample covers [-2, 2] x [-2, 2] and lies in [-13, 13] x [-11, 11].
                        assertTrue(Math.abs(m.x(i)) <= 13 && Math.abs(m.y(i)) <= 11, m.toString());
                        assertTrue(m.depth(i) > 0 && m.depth(i) <= m.contact().depth(), m.toString());
                    }
                    Manifold back = Contact.manifold(b, a);
                    assertNotNull(back);
                    if (back.contact().equals(m.contact().flipped())) {
                        assertEquals(m.flipped(), back, "both orders: the same points");
                    }
                    assertNull(Contact.manifold(a, b.translated(500, 0)), "far apart");
                }));
                tests.add(pair(first, second, name, "Sweep.timeOfImpact", (a, b) -> {
                    assertTrue(Sweep.timeOfImpact(a, 10, 0, b).alreadyOverlapping(), "overlapping at the start");
                    // Two copies of one segment, one moved along the other, would meet only at
                    // an instant (parallel): the mover is then the segment turned upright.
                    Shape mover = (a.equals(b) && !ShapeKind.of(a).hasArea() ? new Segment(-3, -9, 4, 9) : a).translated(-100, 0);
                    Hit hit = Sweep.timeOfImpact(mover, 200, 0, b);
                    assertNotNull(hit, "a mover passing through it must hit");
                    assertTrue(hit.t() > 0 && hit.t() < 1, "t " + hit.t());
                    assertNull(Sweep.timeOfImpact(mover, -200, 0, b), "a mover going away must miss");
                }));
                tests.add(pair(first, second, name, "Response.separate", (a, b) -> {
                    if (!ShapeKind.of(a).hasArea() || !ShapeKind.of(b).hasArea()) {
                        return;
                    }
                    Shape out = Response.separate(a, b);
                    assertSame(a.getClass(), out.getClass());
                    assertTrue(!out.overlaps(b), "separated: " + out);
                }));
            }
        }
        return tests.stream();
    }

    /** A small shape of b's kind about (0.5, 0.25), inside every sample with area. */
    private static Shape tiny(Shape b) {
        return switch (ShapeKind.of(b)) {
            case ELLIPSE -> new Ellipse(0.5f, 0.25f, 0.2f, 0.1f, ((Ellipse) b).angle());
            case CAPSULE -> new Capsule(0.4f, 0.25f, 0.6f, 0.25f, 0.05f);
            case CIRCLE -> new Circle(0.5f, 0.25f, 0.1f);
            case RECT -> new Rect(0.4f, 0.2f, 0.2f, 0.1f);
            case SEGMENT -> new Segment(0.4f, 0.2f, 0.6f, 0.3f);
            case POLYGON -> Polygon.of(0.4f, 0.2f, 0.6f, 0.2f, 0.5f, 0.3f);
        };
    }

    private interface PairCheck {
        void check(Shape a, Shape b);
    }

    private static DynamicTest pair(Class<?> first, Class<?> second, String name, String operation, PairCheck check) {
        return DynamicTest.dynamicTest(name + ": " + operation, () -> {
            for (Shape a : samples(first)) {
                for (Shape b : samples(second)) {
                    try {
                        check.check(a, b);
                    } catch (AssertionError | RuntimeException e) {
                        throw new AssertionError(name + " " + operation + " on " + a + " and " + b + ": " + e, e);
                    }
                }
            }
        });
    }
}
