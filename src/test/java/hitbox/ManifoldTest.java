package hitbox;

import hitbox.internal.Extents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.PropertyDefaults;
import net.jqwik.api.Provide;
import net.jqwik.api.ShrinkingMode;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;

/**
 * {@link Contact#manifold}: exact cases (box on box, a box on its corner, a capsule lying flat
 * and tilted, round pairs, a deep cross), and for thousands of random pairs of every kind with
 * area, both orders: the contact is exactly {@link Contact#between}'s, every point lies in
 * both shapes' closures (checked against JTS and against each shape's own formula, not the
 * kernel's), swapping the shapes keeps the points and flips the normal, the points of two
 * convex polygons lie on the outline of their JTS intersection, and a pair placed
 * symmetrically about a vertical line has symmetric points.
 */
@PropertyDefaults(shrinking = ShrinkingMode.OFF, tries = 300)
class ManifoldTest {

    private static final GeometryFactory GF = new GeometryFactory();

    // ---------------------------------------------------------------- exact cases

    @Test
    void boxOnBox_twoPointsAtTheClippedFaceEnds() {
        // b overlaps a's bottom by 1, from x = 4 to a's right edge at 10.
        Manifold m = Contact.manifold(new Rect(0, 0, 10, 10), new Rect(4, 9, 10, 10));
        assertEquals(new Manifold(new Contact(0, 1, 1), 2, 4, 9, 1, 10, 9, 1), m);
        // The reference is the upper box either way round: the points are on the lower one's top.
        assertEquals(m.flipped(), Contact.manifold(new Rect(4, 9, 10, 10), new Rect(0, 0, 10, 10)));
    }

    @Test
    void boxOnAWiderFloor_pointsAtTheBoxCorners() {
        Rect floor = new Rect(-100, 50, 200, 20);
        Rect box = new Rect(10, 30, 16, 22);   // 2 into the floor
        Manifold m = Contact.manifold(box, floor);
        assertEquals(new Manifold(new Contact(0, 1, 2), 2, 10, 50, 2, 26, 50, 2), m);
    }

    @Test
    void rotatedBoxOnItsCorner_onePointAtTheCorner() {
        float h = 5 * (float) Math.sqrt(2);
        Polygon diamond = Polygon.of(Rect.centered(10, 1 - h, 10, 10)).rotated((float) Math.PI / 4, 10, 1 - h);
        Rect floor = new Rect(0, 0, 20, 10);
        // The corner is the vertex with the largest y.
        int low = 0;
        for (int i = 1; i < diamond.size(); i++) {
            low = diamond.y(i) > diamond.y(low) ? i : low;
        }
        float cx = diamond.x(low), cy = diamond.y(low);
        Manifold m = Contact.manifold(diamond, floor);
        assertNotNull(m);
        assertEquals(1, m.pointCount());
        assertEquals(cx, m.x(0));
        assertEquals(cy, m.y(0));
        assertEquals(m.contact().depth(), m.depth(0));
        assertEquals(cy, m.contact().depth(), 1e-6);
        assertEquals(m.flipped(), Contact.manifold(floor, diamond));
    }

    @Test
    void capsuleLyingFlat_twoPoints_tilted_oneAtItsCap() {
        Rect floor = new Rect(0, 0, 20, 10);
        Manifold flat = Contact.manifold(new Capsule(2, -1, 8, -1, 2), floor);
        assertEquals(new Manifold(new Contact(0, 1, 1), 2, 2, 0, 1, 8, 0, 1), flat);
        Manifold tilted = Contact.manifold(new Capsule(2, -1, 8, -4, 2), floor);
        assertEquals(new Manifold(new Contact(0, 1, 1), 1, 2, 1, 1, 2, 1, 1), tilted);
    }

    @Test
    void twoCapsulesSideBySide_twoPointsOnTheLowerOnesSide() {
        Manifold m = Contact.manifold(new Capsule(0, 0, 10, 0, 3), new Capsule(2, 5, 12, 5, 3));
        assertEquals(new Manifold(new Contact(0, 1, 1), 2, 2, 2, 1, 10, 2, 1), m);
    }

    @Test
    void ballOnABox_onePointAtTheBallsBottom() {
        Manifold m = Contact.manifold(new Circle(5, -1, 3), new Rect(0, 0, 20, 10));
        assertEquals(new Manifold(new Contact(0, 1, 2), 1, 5, 2, 2, 5, 2, 2), m);
    }

    @Test
    void twoBalls_theMiddleOfTheOverlap() {
        Manifold m = Contact.manifold(new Circle(0, 0, 10), new Circle(15, 0, 10));
        assertEquals(new Manifold(new Contact(1, 0, 5), 1, 7.5f, 0, 5, 7.5f, 0, 5), m);
    }

    @Test
    void smallBoxDeepInABigBall_thePointIsTheBoxs() {
        // The ball's deepest point along the normal is far outside the box: the box's corner instead.
        Manifold m = Contact.manifold(new Circle(5, 5, 30), new Rect(0, 0, 2, 2));
        assertNotNull(m);
        assertEquals(1, m.pointCount());
        assertEquals(2, m.x(0), 1e-5);
        assertEquals(2, m.y(0), 1e-5);
    }

    @Test
    void aDeepCross_theOverlapsDeepestCorners() {
        // A plus sign: no edge of either bar lies inside the other.
        Manifold m = Contact.manifold(new Rect(-10, -1, 20, 2), new Rect(-1, -10, 2, 20));
        assertNotNull(m);
        assertEquals(new Rect(-10, -1, 20, 2).contact(new Rect(-1, -10, 2, 20)), m.contact());
        assertEquals(2, m.pointCount());
        for (int i = 0; i < 2; i++) {
            assertEquals(1, Math.abs(m.x(i)), 0);
            assertEquals(1, Math.abs(m.y(i)), 0);
        }
    }

    @Test
    void concaveCupOnABar_pointsInBoth() {
        Polygon cup = Polygon.of(TestShapes.CUP);   // a U, its two prongs pointing up
        Rect lid = new Rect(-2, -3, 14, 4);   // across both prongs' tops, 1 deep
        Manifold m = Contact.manifold(lid, cup);
        assertNotNull(m);
        assertEquals(lid.contact(cup), m.contact());
        assertEquals(2, m.pointCount());
        assertValid(lid, cup, m);
        // The two prongs' outer corners, the farthest apart along the surface.
        assertEquals(0, m.x(0), 1e-6);
        assertEquals(10, m.x(1), 1e-6);
    }

    @Test
    void apartAndTouching_giveNull() {
        assertNull(Contact.manifold(new Rect(0, 0, 10, 10), new Rect(10, 0, 10, 10)));
        assertNull(Contact.manifold(new Circle(0, 0, 5), new Circle(10, 0, 5)));
        assertNull(Contact.manifold(new Capsule(0, 0, 10, 0, 2), new Rect(0, 2, 5, 5)));
    }

    @Test
    void segmentsAndNull_areRefusedAsContactRefusesThem() {
        Segment s = new Segment(0, 0, 10, 10);
        Circle c = new Circle(5, 5, 5);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Contact.manifold(s, c));
        assertTrue(e.getMessage().contains("Segment"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> Contact.manifold(c, s));
        assertTrue(e.getMessage().contains("Segment"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> Contact.manifold(null, c));
        assertTrue(e.getMessage().contains("a"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> Contact.manifold(c, null));
        assertTrue(e.getMessage().contains("b"), e.getMessage());
    }

    @Test
    void theRecord_checksItsValues() {
        Contact c = new Contact(0, 1, 2);
        assertThrows(IllegalArgumentException.class, () -> new Manifold(null, 1, 0, 0, 1, 0, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> new Manifold(c, 3, 0, 0, 1, 0, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> new Manifold(c, 2, Float.NaN, 0, 1, 0, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> new Manifold(c, 2, 0, 0, 3, 0, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> new Manifold(c, 2, 0, 0, 0, 0, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> new Manifold(c, 1, 0, 0, 1, 5, 0, 1));
        Manifold one = new Manifold(c, 1, 3, 4, 1, 3, 4, 1);
        assertEquals(3f, one.x(0));
        assertEquals(4f, one.y(0));
        assertThrows(IndexOutOfBoundsException.class, () -> one.x(1));
        assertThrows(IndexOutOfBoundsException.class, () -> one.y(-1));
        Manifold two = new Manifold(c, 2, 3, 4, 1, 5, 6, 2);
        assertEquals(5, two.x(1));
        assertEquals(6, two.y(1));
        assertEquals(2, two.depth(1));
        assertThrows(IndexOutOfBoundsException.class, () -> two.depth(2));
    }

    // ---------------------------------------------------------------- every pair, sampled

    @Test
    void randomPairsOfEveryKind_bothOrders() {
        Random rnd = new Random(20261127L);
        int[] checked = new int[3];   // overlapping pairs, two-point manifolds, swaps that flip
        for (int k = 0; k < 6000; k++) {
            Shape a = randomShape(rnd), b = randomShape(rnd);
            checked[0] += checkPair(a, b, checked) ? 1 : 0;
        }
        // Enough of each, so that the checks cannot pass by seeing nothing.
        assertTrue(checked[0] > 2500, "overlapping pairs " + checked[0]);
        assertTrue(checked[1] > 300, "two-point manifolds " + checked[1]);
        assertTrue(checked[2] > 2000, "swaps that flip " + checked[2]);
    }

    @Property
    void anyPair_pointsInBoth_andTheSameBothWays(@ForAll("shapes") Shape a, @ForAll("shapes") Shape b) {
        checkPair(a, b, new int[3]);
    }

    @Property
    void convexPolygons_pointsOnTheOutlineOfTheirJtsIntersection(@ForAll("convex") Shape a, @ForAll("convex") Shape b) {
        Manifold m = Contact.manifold(a, b);
        if (m == null) {
            return;
        }
        Geometry overlap = jts(a).intersection(jts(b));
        double tol = Manifold.TOLERANCE * scale(a, b);
        for (int i = 0; i < m.pointCount(); i++) {
            double off = overlap.getBoundary().distance(GF.createPoint(new Coordinate(m.x(i), m.y(i))));
            assertTrue(off <= tol, "point (" + m.x(i) + ", " + m.y(i) + ") is " + off + " from the outline of the overlap of "
                    + a + " and " + b + ": " + m);
        }
    }

    @Property
    void symmetricAboutAVerticalLine_symmetricPoints(@ForAll("mirrored") Shape a, @ForAll("mirrored") Shape b) {
        Manifold m = Contact.manifold(a, b);
        if (m == null || m.contact().nx() != 0 || m.contact().depth() < 1e-5 * scale(a, b)) {
            // A tie between two mirrored normals picks one: nothing to mirror. And a hair's
            // overlap is decided by the rounding of a regular polygon's float corners, which
            // are symmetric only to rounding: one corner touches, its mirror image does not.
            return;
        }
        // Every shape here is symmetric about x = 0: the points are too.
        double tol = 10 * Manifold.TOLERANCE * scale(a, b);
        for (int i = 0; i < m.pointCount(); i++) {
            boolean found = false;
            for (int j = 0; j < m.pointCount(); j++) {
                found |= Math.abs(m.x(i) + m.x(j)) <= tol && Math.abs(m.y(i) - m.y(j)) <= tol;
            }
            assertTrue(found, "no mirror image of (" + m.x(i) + ", " + m.y(i) + ") in " + m + " for " + a + " and " + b);
        }
    }

    /** Checks one pair both ways; true if they overlap. Counts two-point answers and flipping swaps. */
    private static boolean checkPair(Shape a, Shape b, int[] counts) {
        Contact c = a.contact(b);
        Manifold m = Contact.manifold(a, b);
        if (c == null) {
            assertNull(m, a + " and " + b + " do not overlap");
            assertNull(Contact.manifold(b, a));
            return false;
        }
        assertNotNull(m, a + " and " + b);
        assertEquals(c, m.contact(), "the contact of Contact.between exactly, for " + a + " and " + b);
        assertValid(a, b, m);
        Manifold back = Contact.manifold(b, a);
        assertNotNull(back);
        assertValid(b, a, back);
        if (b.contact(a).equals(c.flipped())) {
            assertEquals(m.flipped(), back, "swapped: the same points, the normal flipped, for " + a + " and " + b);
            counts[2]++;
        }
        counts[1] += m.pointCount() == 2 ? 1 : 0;
        return true;
    }

    /** The count, the depths, and each point in both shapes' closures. */
    private static void assertValid(Shape a, Shape b, Manifold m) {
        assertTrue(m.pointCount() == 1 || m.pointCount() == 2);
        boolean curved = a instanceof Ellipse || b instanceof Ellipse;
        double tol = (curved ? Manifold.CURVED_TOLERANCE : Manifold.TOLERANCE) * scale(a, b);
        for (int i = 0; i < m.pointCount(); i++) {
            assertTrue(m.depth(i) > 0 && m.depth(i) <= m.contact().depth(), "depth " + m.depth(i) + " in " + m);
            double offA = outside(a, m.x(i), m.y(i)), offB = outside(b, m.x(i), m.y(i));
            assertTrue(offA <= tol && offB <= tol, "point (" + m.x(i) + ", " + m.y(i) + ") is " + offA + " outside " + a + " and "
                    + offB + " outside " + b + ": " + m);
        }
    }

    private static double scale(Shape a, Shape b) {
        double s = 1;
        for (Shape t : new Shape[] {a, b}) {
            s = Math.max(s, Math.max(Math.max(Math.abs(Extents.minX(t)), Math.abs(Extents.maxX(t))), Math.max(Math.abs(Extents.minY(t)), Math.abs(Extents.maxY(t)))));
        }
        return s;
    }

    // ---------------------------------------------------------------- an independent "how far outside"

    /** How far the point lies outside the shape (0 inside), by JTS or the shape's own formula. */
    static double outside(Shape s, double x, double y) {
        if (s instanceof Circle c) {
            return Math.max(0, Math.hypot(x - c.x(), y - c.y()) - c.r());
        }
        if (s instanceof Capsule k) {
            Geometry core = GF.createLineString(new Coordinate[] {new Coordinate(k.x1(), k.y1()), new Coordinate(k.x2(), k.y2())});
            return Math.max(0, core.distance(GF.createPoint(new Coordinate(x, y))) - k.r());
        }
        return jts(s).distance(GF.createPoint(new Coordinate(x, y)));
    }

    /** A rectangle, polygon or ellipse as a JTS polygon; an ellipse's circumscribed 4096-gon. */
    static Geometry jts(Shape s) {
        List<Coordinate> ring = new ArrayList<>();
        if (s instanceof Rect r) {
            double x2 = (double) r.x() + r.w(), y2 = (double) r.y() + r.h();
            if (r.w() == 0 || r.h() == 0) {
                return GF.createLineString(new Coordinate[] {new Coordinate(r.x(), r.y()), new Coordinate(x2, y2)});
            }
            ring.add(new Coordinate(r.x(), r.y()));
            ring.add(new Coordinate(x2, r.y()));
            ring.add(new Coordinate(x2, y2));
            ring.add(new Coordinate(r.x(), y2));
        } else if (s instanceof Polygon p) {
            for (int i = 0; i < p.size(); i++) {
                ring.add(new Coordinate(p.x(i), p.y(i)));
            }
        } else if (s instanceof Ellipse e) {
            int n = 4096;
            double grow = 1 / Math.cos(Math.PI / n), cos = Math.cos(e.angle()), sin = Math.sin(e.angle());
            for (int i = 0; i < n; i++) {
                double t = 2 * Math.PI * i / n;
                double lx = grow * e.rx() * Math.cos(t), ly = grow * e.ry() * Math.sin(t);
                ring.add(new Coordinate(e.x() + lx * cos - ly * sin, e.y() + lx * sin + ly * cos));
            }
        } else {
            throw new IllegalArgumentException("not a polygon: " + s);
        }
        ring.add(ring.get(0));
        return GF.createPolygon(ring.toArray(new Coordinate[0]));
    }

    // ---------------------------------------------------------------- shapes

    /** Concave polygons from the table tests, half size. */
    private static final float[][] CONCAVE = {TestShapes.CROWN, TestShapes.ELL, TestShapes.CUP, TestShapes.DOUBLE_V};

    /** A shape of any kind with area about the origin, 2 to 16 across, sometimes on whole numbers. */
    static Shape randomShape(Random rnd) {
        boolean whole = rnd.nextInt(3) == 0;
        float x = coordinate(rnd, whole), y = coordinate(rnd, whole);
        float s = whole ? 2 + rnd.nextInt(12) : 2 + 12 * rnd.nextFloat();
        float angle = rnd.nextInt(4) == 0 ? 0 : (float) (rnd.nextDouble() * Math.PI);
        return switch (rnd.nextInt(9)) {
            case 0 -> new Circle(x, y, s / 2);
            case 1, 2 -> new Rect(x, y, s, whole ? 2 + rnd.nextInt(12) : 2 + 12 * rnd.nextFloat());
            case 3 -> Polygon.regular(x, y, s / 2, 3 + rnd.nextInt(6), angle);
            case 4 -> Polygon.of(Rect.centered(x, y, s, 1 + rnd.nextInt(10))).rotated(angle, x, y);
            case 5 -> new Ellipse(x, y, s / 2, 1 + 5 * rnd.nextFloat(), rnd.nextBoolean() ? 0 : angle);
            case 6 -> {
                float len = rnd.nextFloat() * s;
                float dx = (float) Math.cos(angle) * len, dy = (float) Math.sin(angle) * len;
                if (whole) {
                    dx = Math.round(dx);
                    dy = Math.round(dy);
                }
                yield new Capsule(x, y, x + dx, y + dy, 1 + rnd.nextInt(4));
            }
            default -> {
                float[] xy = CONCAVE[rnd.nextInt(CONCAVE.length)].clone();
                for (int i = 0; i < xy.length; i += 2) {
                    xy[i] = x + xy[i] * (whole ? 1 : 0.7f);
                    xy[i + 1] = y + xy[i + 1] * (whole ? 1 : 0.7f);
                }
                yield Polygon.of(xy);
            }
        };
    }

    private static float coordinate(Random rnd, boolean whole) {
        return whole ? rnd.nextInt(17) - 8 : (float) (rnd.nextDouble() * 16 - 8);
    }

    @Provide
    Arbitrary<Shape> shapes() {
        return Arbitraries.longs().map(seed -> randomShape(new Random(seed)));
    }

    @Provide
    Arbitrary<Shape> convex() {
        return Arbitraries.longs().map(seed -> {
            Random rnd = new Random(seed);
            Shape s;
            do {
                s = randomShape(rnd);
            } while (!(s instanceof Rect || s instanceof Polygon p && p.isConvex()));
            return s;
        });
    }

    /** Shapes symmetric about x = 0: centred rectangles, regular polygons with a vertex up or down, circles, aligned ellipses, level capsules. */
    @Provide
    Arbitrary<Shape> mirrored() {
        Arbitrary<Integer> kind = Arbitraries.integers().between(0, 4);
        Arbitrary<Integer> y = Arbitraries.integers().between(-8, 8);
        Arbitrary<Integer> w = Arbitraries.integers().between(1, 8);
        Arbitrary<Integer> h = Arbitraries.integers().between(1, 8);
        return Combinators.combine(kind, y, w, h).as((k, cy, hw, hh) -> switch (k) {
            case 0 -> new Rect(-hw, cy, 2 * hw, 2 * hh);
            case 1 -> new Circle(0, cy, hw);
            case 2 -> new Ellipse(0, cy, hw, hh);
            case 3 -> new Capsule(-hw, cy, hw, cy, hh);
            default -> Polygon.regular(0, cy, hw + 1, 3 + hh % 4, (float) (hh % 2 == 0 ? -Math.PI / 2 : Math.PI / 2));
        });
    }
}
