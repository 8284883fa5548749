package hitbox;

import hitbox.internal.RawTests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Geometry;

/**
 * {@link Shape#contains(Shape)}, and the plain-float bodies the browser's
 * {@code Collide.*Contains*} exports call ({@code RawTests}): the closure of b in the closure of
 * a (touching from inside counts, every shape holds itself).
 *
 * <ul>
 *   <li>Facts: libGDX's {@code Rectangle.contains(Rectangle)} and {@code Circle.contains(Circle)}
 *       cases translated to the touching rule, touching from inside for every pair of kinds,
 *       zero-size shapes, huge coordinates, concave containers whose notch an edge jumps.</li>
 *   <li>JTS ({@code Geometry.covers}, exact on float coordinates) for every ordered pair of
 *       the polygonal kinds (rectangles, segments, convex and concave polygons, and the
 *       zero-size circles and capsules, which are points and segments), both orders, on
 *       whole and half numbers, where touching is common.</li>
 *   <li>Dense sampling for the curved kinds (circles, ellipses aligned and turned, capsules):
 *       the largest signed distance outside a over thousands of points of b's outline; cases
 *       within a band of the tie are counted, not judged.</li>
 * </ul>
 */
class ContainmentTest {


    // ------------------------------------------------------------------ facts

    @Test
    void rectangles_libGdxFacts_translatedToTheTouchingRule() {
        Rect outer = new Rect(0, 0, 10, 10);
        assertTrue(outer.contains(new Rect(1, 1, 5, 5)), "wholly inside (libGDX: true)");
        assertFalse(outer.contains(new Rect(5, 5, 10, 10)), "reaching out (libGDX: false)");
        assertFalse(outer.contains(new Rect(-1, 2, 3, 3)), "reaching out to the left");
        // libGDX's strict comparisons say false here; touching from inside counts for us.
        assertTrue(outer.contains(new Rect(0, 0, 5, 5)), "two edges shared");
        assertTrue(outer.contains(outer), "itself");
        assertTrue(outer.contains(new Rect(10, 0, 0, 10)), "its right edge as a flat rectangle");
        assertFalse(new Rect(1, 1, 5, 5).contains(outer), "the other way round");
        assertTrue(outer.contains(new Rect(0, 0, 10, 10)));
        assertTrue(outer.contains(new Rect(2, 3, 8, 7)));
        assertFalse(outer.contains(new Rect(2, 3, 8.000001f, 7)));
        assertTrue(new Rect(0, 0, 10, 10).contains(new Circle(5, 5, 5)), "inscribed");
        assertFalse(new Rect(0, 0, 10, 10).contains(new Circle(5, 5, 5.000001f)));
        assertTrue(new Rect(0, 0, 10, 10).contains(new Circle(0, 5, 0)), "a point on the edge");
        assertFalse(Collide.rectPoint(0, 0, 10, 10, 0, 5), "which the open inside does not hold");
    }

    @Test
    void circles_libGdxFacts_translatedToTheTouchingRule() {
        Circle outer = new Circle(0, 0, 10);
        assertTrue(outer.contains(new Circle(2, 2, 3)), "libGDX: true");
        assertFalse(outer.contains(new Circle(8, 0, 3)), "libGDX: false");
        assertTrue(outer.contains(new Circle(5, 0, 5)), "touching inside (libGDX: true, dst <= (r1 - r2)^2)");
        assertTrue(outer.contains(new Circle(6, 8, 0)), "a point on the outline (3-4-5)");
        assertFalse(outer.contains(new Circle(6, 8.000001f, 0)));
        assertTrue(outer.contains(outer));
        assertFalse(new Circle(0, 0, 3).contains(outer), "smaller never holds larger");
        assertTrue(new Circle(3, 4, 0).contains(new Circle(3, 4, 0)), "a point holds itself (libGDX: false)");
        assertFalse(new Circle(3, 4, 0).contains(new Circle(3, 5, 0)));
        assertTrue(outer.contains(new Circle(3, 4, 5)), "touching inside at (6, 8)");
        assertFalse(outer.contains(new Circle(3, 4, 5.0000005f)));
        assertTrue(new Circle(0, 0, 5).contains(new Rect(-3, -4, 6, 8)), "corners on the outline");
        assertFalse(new Circle(0, 0, 5).contains(new Rect(-3, -4, 6, 8.000001f)));
        // The shapes refuse such values; the plain-float body the browser's export calls says false.
        assertFalse(RawTests.circleContainsCircle(0, 0, 10, 0, 0, -1), "negative radius");
        assertFalse(RawTests.circleContainsCircle(0, 0, Float.POSITIVE_INFINITY, 0, 0, 1), "infinite");
        assertFalse(RawTests.circleContainsCircle(Float.NaN, 0, 10, 0, 0, 1), "NaN");
    }

    @Test
    void everySample_containsItself_andACopyMovedOut_isNotContained() {
        for (Shape s : samples()) {
            assertTrue(s.contains(s), "itself: " + s);
            Shape moved = s.translated(0.5f, 0.25f);
            boolean point = s.bounds().w() == 0 && s.bounds().h() == 0;
            if (!point) {
                assertFalse(s.contains(moved), "moved: " + s);
            }
        }
    }

    @Test
    void touchingFromInside_everyCurvedPairing() {
        // inscribed and concentric cases where the outlines meet
        assertTrue(new Rect(-5, -3, 10, 6).contains(new Ellipse(0, 0, 5, 3)));
        assertFalse(new Rect(-5, -3, 10, 6).contains(new Ellipse(0, 0, 5.0001f, 3)));
        assertTrue(new Ellipse(0, 0, 5, 3).contains(new Circle(0, 0, 3)));
        assertFalse(new Ellipse(0, 0, 5, 3).contains(new Circle(0, 0, 3.001f)));
        assertTrue(new Circle(0, 0, 5).contains(new Ellipse(0, 0, 5, 3)));
        assertFalse(new Circle(0, 0, 4.999f).contains(new Ellipse(0, 0, 5, 3)));
        assertTrue(new Circle(0, 0, 5).contains(new Ellipse(0, 0, 5, 3, 1.1f)), "turned");
        assertTrue(new Capsule(-2, 0, 2, 0, 3).contains(new Ellipse(0, 0, 5, 3)));
        assertFalse(new Capsule(-2, 0, 2, 0, 2.999f).contains(new Ellipse(0, 0, 5, 3)));
        assertTrue(new Ellipse(0, 0, 5, 3).contains(new Ellipse(0, 0, 5, 3)));
        assertTrue(new Ellipse(0, 0, 5, 3, 0.3f).contains(new Ellipse(0, 0, 5, 3, 0.3f)));
        assertTrue(new Ellipse(0, 0, 5, 5, 0.7f).contains(new Circle(0, 0, 5)), "a round ellipse is a circle");
        assertTrue(new Ellipse(0, 0, 5, 3).contains(new Segment(-5, 0, 5, 0)), "its long axis");
        assertFalse(new Ellipse(0, 0, 5, 3).contains(new Segment(-5, 0.001f, 5, 0.001f)));
        assertTrue(new Ellipse(0, 0, 10, 5).contains(new Rect(-8, -3, 16, 6)), "corners on the outline (4/5, 3/5)");
        assertFalse(new Ellipse(0, 0, 10, 5).contains(new Rect(-8, -3, 16, 6.000001f)));
        assertFalse(new Ellipse(0, 0, 10, 5, 0.5f).contains(new Rect(-8, -3, 16, 6).translated(0, 0)));
        assertTrue(new Ellipse(0, 0, 5, 3).contains(new Capsule(-2, 0, 2, 0, 1)));
        assertTrue(new Capsule(0, 0, 10, 0, 5).contains(new Circle(10, 0, 5)), "its end disc");
        assertTrue(new Capsule(0, 0, 10, 0, 5).contains(new Capsule(2, 0, 8, 0, 5)));
        assertFalse(new Capsule(0, 0, 10, 0, 5).contains(new Capsule(2, 0, 8, 0.5f, 5)));
        assertTrue(new Capsule(0, 0, 10, 0, 5).contains(new Rect(0, -5, 10, 10)), "its middle box");
        assertTrue(new Circle(0, 0, 5).contains(new Capsule(-1, 0, 1, 0, 4)));
        assertFalse(new Circle(0, 0, 5).contains(new Capsule(-1, 0, 1.5f, 0, 4)));
        Polygon square = Polygon.of(0, 0, 10, 0, 10, 10, 0, 10);
        assertTrue(square.contains(new Circle(5, 5, 5)), "inscribed circle");
        assertFalse(square.contains(new Circle(5, 5, 5.0001f)));
        assertTrue(square.contains(new Ellipse(5, 5, 5, 2)));
        assertFalse(square.contains(new Capsule(5, 3, 5, 7, 5)));
        assertTrue(square.contains(new Capsule(3, 5, 7, 5, 3)));
        assertTrue(square.contains(new Capsule(5, 5, 5, 5, 5)), "a capsule that is a circle");
        assertTrue(Polygon.of(0, 0, 8, 0, 0, 6).contains(new Circle(2, 2, 2)), "3-4-5 triangle's incircle");
        assertFalse(Polygon.of(0, 0, 8, 0, 0, 6).contains(new Circle(2, 2, 2.0001f)));
    }

    @Test
    void concaveContainer_cornersInside_butAnEdgeLeaves() {
        Polygon cup = Polygon.of(TestShapes.CUP); // notch x in (4, 6), y in (0, 8)
        assertTrue(cup.contains(1, 1) && cup.contains(9, 1));
        assertFalse(cup.contains(new Segment(1, 1, 9, 1)), "a segment across the notch");
        assertTrue(cup.contains(new Segment(1, 9, 9, 9)), "below the notch");
        assertTrue(cup.contains(new Segment(1, 8, 9, 8)), "along the notch's bottom");
        assertFalse(cup.contains(new Rect(1, 1, 8, 2)), "all four corners inside, the box bridges the notch");
        assertFalse(cup.contains(Polygon.of(1, 1, 9, 1, 5, 11)), "a triangle over the notch");
        assertTrue(cup.contains(Polygon.of(0, 0, 4, 0, 4, 8, 0, 8)), "the left arm, edges shared");
        assertTrue(cup.contains(new Segment(4, 0, 4, 8)), "along the notch's side");
        assertFalse(cup.contains(new Segment(0, 0, 10, 12)));
        assertFalse(cup.contains(new Circle(5, 10, 2.5f)), "a disc reaching up into the notch");
        assertTrue(cup.contains(new Circle(5, 10, 2)), "touching the notch's bottom");
        assertFalse(cup.contains(new Capsule(1, 10, 9, 10, 2.5f)));
        assertTrue(cup.contains(new Capsule(2, 10, 8, 10, 2)));
        assertFalse(cup.contains(new Ellipse(5, 10, 5, 2.5f)));
        assertTrue(cup.contains(new Ellipse(5, 10, 5, 2)));
        Polygon crown = Polygon.of(TestShapes.CROWN); // reflex corner (5, 5)
        assertTrue(crown.contains(new Segment(0, 10, 5, 5)), "to the reflex corner");
        assertTrue(crown.contains(new Segment(0, 5, 10, 5)), "through the reflex corner, touching it");
        assertFalse(crown.contains(new Segment(1, 2, 9, 2)), "across the V");
        assertTrue(crown.contains(new Segment(0, 0, 5, 5)), "along an edge");
        assertFalse(crown.contains(new Segment(0, 0, 10, 0)), "the V's open top");
    }

    @Test
    void segmentContainer_holdsOnlyWhatLiesOnIt() {
        Segment s = new Segment(0, 0, 10, 5);
        assertTrue(s.contains(s));
        assertTrue(s.contains(new Segment(2, 1, 8, 4)));
        assertTrue(s.contains(new Segment(8, 4, 2, 1)));
        assertFalse(s.contains(new Segment(2, 1, 12, 6)), "runs past the end");
        assertTrue(s.contains(new Circle(4, 2, 0)));
        assertFalse(s.contains(new Circle(4, 2, 0.001f)));
        assertTrue(s.contains(new Capsule(2, 1, 10, 5, 0)));
        assertFalse(s.contains(new Capsule(2, 1, 10, 5, 1)));
        assertTrue(new Segment(0, 0, 10, 0).contains(new Rect(2, 0, 5, 0)), "a flat rectangle along it");
        assertTrue(new Segment(0, 0, 10, 0).contains(new Ellipse(5, 0, 5, 0)), "a flat ellipse, its ends");
        assertFalse(new Segment(0, 0, 10, 0).contains(new Ellipse(5, 0, 5.5f, 0)));
        assertFalse(s.contains(Polygon.of(0, 0, 10, 5, 0, 5)));
        assertFalse(s.contains(new Rect(0, 0, 10, 5)));
        Segment point = new Segment(3, 3, 3, 3);
        assertTrue(point.contains(new Circle(3, 3, 0)) && point.contains(point) && !point.contains(new Segment(3, 3, 3, 4)));
    }

    @Test
    void zeroSize_containersAndContents() {
        Circle dot = new Circle(2, 3, 0);
        assertTrue(dot.contains(new Rect(2, 3, 0, 0)));
        assertTrue(dot.contains(new Segment(2, 3, 2, 3)));
        assertTrue(dot.contains(new Ellipse(2, 3, 0, 0)));
        assertTrue(dot.contains(new Capsule(2, 3, 2, 3, 0)));
        assertFalse(dot.contains(new Segment(2, 3, 2, 4)));
        assertFalse(dot.contains(new Ellipse(2, 3, 1, 1)));
        Rect flat = new Rect(0, 0, 10, 0);
        assertTrue(flat.contains(new Segment(1, 0, 9, 0)));
        assertTrue(flat.contains(new Rect(0, 0, 10, 0)));
        assertFalse(flat.contains(new Circle(5, 0, 1)));
        assertTrue(new Ellipse(5, 0, 5, 0).contains(new Segment(0, 0, 10, 0)), "a flat ellipse is its closed box");
        assertTrue(new Ellipse(0, 0, 5, 0, 0.6f).contains(new Circle(0, 0, 0)));
        assertTrue(new Capsule(0, 0, 10, 0, 0).contains(new Segment(0, 0, 10, 0)));
        assertFalse(new Capsule(0, 0, 10, 0, 0).contains(new Circle(5, 0, 1)));
        assertTrue(new Rect(0, 0, 10, 10).contains(new Capsule(0, 0, 10, 10, 0)), "the diagonal");
        assertTrue(Polygon.of(TestShapes.SQUARE).contains(new Circle(10, 10, 0)), "a corner");
        assertTrue(Polygon.of(TestShapes.SQUARE).contains(new Rect(0, 10, 10, 0)), "an edge as a flat rectangle");
    }

    @Test
    void hugeCoordinates_exact() {
        float p100 = 0x1p100f;
        Rect r100 = new Rect(p100, p100, p100, p100);
        assertTrue(r100.contains(new Circle(1.5f * p100, 1.5f * p100, 0.5f * p100)), "inscribed, 2^100");
        assertFalse(r100.contains(new Circle(1.5f * p100, 1.5f * p100, Math.nextUp(0.5f * p100))));
        float big = 1e30f, up = Math.nextUp(big);
        Rect r = new Rect(big, big, big, big);
        assertTrue(r.contains(new Rect(big, big, 1, 1)), "a unit square in the corner: 1e30 + 1 needs exact sums");
        assertFalse(r.contains(new Rect(Math.nextDown(big), big, 1, 1)));
        assertFalse(new Rect(0, 0, big, 1).contains(new Circle(big, 0.5f, 0.5f)), "1e30 + 0.5 > 1e30, exactly");
        assertTrue(new Rect(0, 0, big, 1).contains(new Circle(Math.nextDown(big), 0.5f, 0.5f)), "a float step (7e22) to spare");
        assertTrue(new Circle(0, 0, big).contains(new Circle(big, 0, 0)), "a point on the outline");
        assertFalse(new Circle(0, 0, big).contains(new Circle(up, 0, 0)));
        assertFalse(new Circle(0, 0, big).contains(new Circle(1, 0, big)), "1 + 1e30 > 1e30, exactly");
        assertTrue(new Circle(1, 0, big).contains(new Circle(0, 0, 0)));
        assertTrue(new Circle(1, 0, big).contains(new Circle(0, 0, 2)), "1 <= 1e30 - 2");
        assertFalse(new Circle(1, 0, big).contains(new Circle(0, 0, big)), "1 > 0");
        assertTrue(new Circle(1e6f, 1e6f, 1e6f).contains(new Circle(1e6f + 300000, 1e6f + 400000, 500000)),
                "touching inside, 3-4-5 at a million");
        assertFalse(new Circle(1e6f, 1e6f, 1e6f).contains(new Circle(1e6f + 300000, 1e6f + 400001, 500000)));
        Polygon far = Polygon.of(1e7f, 1e7f, 1e7f + 30, 1e7f, 1e7f + 30, 1e7f + 30, 1e7f, 1e7f + 30);
        assertTrue(far.contains(new Circle(1e7f + 15, 1e7f + 15, 15)));
        assertFalse(far.contains(new Circle(1e7f + 15, 1e7f + 15, 15.000001f)));
        assertTrue(far.contains(new Segment(1e7f, 1e7f, 1e7f + 30, 1e7f + 30)));
    }

    @Test
    void rawBodies_agreeWithTheShapes() {
        SplittableRandom rnd = new SplittableRandom(23);
        for (int i = 0; i < 20000; i++) {
            Rect a = new Rect(rnd.nextInt(-10, 10), rnd.nextInt(-10, 10), rnd.nextInt(0, 20), rnd.nextInt(0, 20));
            Rect b = new Rect(rnd.nextInt(-10, 10), rnd.nextInt(-10, 10), rnd.nextInt(0, 10), rnd.nextInt(0, 10));
            Circle c = new Circle(rnd.nextInt(-10, 10), rnd.nextInt(-10, 10), rnd.nextInt(0, 15));
            Circle d = new Circle(rnd.nextInt(-10, 10), rnd.nextInt(-10, 10), rnd.nextInt(0, 8));
            assertEquals(a.contains(b), RawTests.rectContainsRect(a.x(), a.y(), a.w(), a.h(), b.x(), b.y(), b.w(), b.h()));
            assertEquals(c.contains(d), RawTests.circleContainsCircle(c.x(), c.y(), c.r(), d.x(), d.y(), d.r()));
            // the formulas themselves, in exact integer arithmetic
            assertEquals(b.x() >= a.x() && b.x() + b.w() <= a.x() + a.w() && b.y() >= a.y() && b.y() + b.h() <= a.y() + a.h(),
                    a.contains(b), a + " " + b);
            long dx = (long) d.x() - (long) c.x(), dy = (long) d.y() - (long) c.y(), m = (long) c.r() - (long) d.r();
            assertEquals(m >= 0 && dx * dx + dy * dy <= m * m, c.contains(d), c + " " + d);
            // a circle in a rect: its box within the edges; a rect in a circle: every corner within r
            long cx = (long) c.x(), cy = (long) c.y(), r = (long) c.r();
            assertEquals(cx - r >= (long) a.x() && cx + r <= (long) a.x() + (long) a.w()
                    && cy - r >= (long) a.y() && cy + r <= (long) a.y() + (long) a.h(), a.contains(c), a + " " + c);
            boolean corners = true;
            for (long qx : new long[] {(long) b.x(), (long) b.x() + (long) b.w()}) {
                for (long qy : new long[] {(long) b.y(), (long) b.y() + (long) b.h()}) {
                    corners &= (qx - cx) * (qx - cx) + (qy - cy) * (qy - cy) <= r * r;
                }
            }
            assertEquals(corners, c.contains(b), c + " " + b);
        }
    }

    // ------------------------------------------------------------------ JTS, the polygonal kinds

    @Test
    void polygonalKinds_agreeWithJtsCovers_bothOrders() {
        SplittableRandom rnd = new SplittableRandom(2023);
        int cases = 0, held = 0, concaveCases = 0;
        List<String> wrong = new ArrayList<>();
        for (int i = 0; i < 2000; i++) {
            Shape a = polygonal(rnd, true);
            List<Shape> bs = new ArrayList<>();
            for (int k = 0; k < 4; k++) {
                bs.add(polygonal(rnd, false));
            }
            bs.addAll(partsOf(a, rnd));
            for (Shape b : bs) {
                for (Shape[] pair : new Shape[][] {{a, b}, {b, a}}) {
                    boolean want = jts(pair[0]).covers(jts(pair[1]));
                    boolean got = pair[0].contains(pair[1]);
                    cases++;
                    held += want ? 1 : 0;
                    if (pair[0] instanceof Polygon p && !p.isConvex()) {
                        concaveCases++;
                    }
                    if (want != got && wrong.size() < 20) {
                        wrong.add(pair[0] + " contains " + pair[1] + ": JTS " + want + ", Hitbox " + got);
                    }
                }
            }
        }
        System.out.println("containment vs JTS covers: " + cases + " ordered pairs, " + held + " held, "
                + concaveCases + " with a concave container, " + wrong.size() + " disagreements");
        assertEquals(List.of(), wrong);
        assertTrue(held > cases / 10, "too few held cases to mean anything: " + held);
    }

    /** A random rectangle, segment, polygon, point-circle or zero-radius capsule on half pixels. */
    private static Shape polygonal(SplittableRandom rnd, boolean big) {
        int size = big ? 40 : 12;
        switch (rnd.nextInt(big ? 6 : 8)) {
            case 0, 1: {
                return new Rect(half(rnd, -20, 20), half(rnd, -20, 20), rnd.nextInt(4) == 0 ? 0 : half(rnd, 0, size),
                        rnd.nextInt(6) == 0 ? 0 : half(rnd, 0, size));
            }
            case 2:
                return TestShapes.convexRing(rnd, 3 + rnd.nextInt(6), rnd.nextInt(-10, 10), rnd.nextInt(-10, 10), true);
            case 3, 4:
                return TestShapes.starRing(rnd, 5 + rnd.nextInt(8), rnd.nextInt(-10, 10), rnd.nextInt(-10, 10), true);
            case 5:
                return new Segment(half(rnd, -20, 20), half(rnd, -20, 20), half(rnd, -20, 20), half(rnd, -20, 20));
            case 6:
                return new Circle(half(rnd, -20, 20), half(rnd, -20, 20), 0);
            default:
                return new Capsule(half(rnd, -20, 20), half(rnd, -20, 20), half(rnd, -20, 20), half(rnd, -20, 20), 0);
        }
    }

    private static float half(SplittableRandom rnd, int lo, int hi) {
        return rnd.nextInt(2 * lo, 2 * hi + 1) / 2f;
    }

    /**
     * Shapes made from a container's own corners: diagonals and triangles of a polygon's
     * vertices (inside, outside, or jumping a notch), its edges, corners, and boxes inside
     * its bounds; the cases where containment is decided on the outline.
     */
    private static List<Shape> partsOf(Shape a, SplittableRandom rnd) {
        List<Shape> out = new ArrayList<>();
        float[] v;
        if (a instanceof Polygon p) {
            v = p.coordinates();
        } else if (a instanceof Rect r) {
            v = new float[] {r.x(), r.y(), r.right(), r.y(), r.right(), r.bottom(), r.x(), r.bottom()};
        } else {
            return out;
        }
        int n = v.length / 2;
        for (int k = 0; k < 6; k++) {
            int i = rnd.nextInt(n), j = rnd.nextInt(n), m = rnd.nextInt(n);
            out.add(new Segment(v[2 * i], v[2 * i + 1], v[2 * j], v[2 * j + 1]));
            out.add(new Circle(v[2 * i], v[2 * i + 1], 0));
            try {
                out.add(Polygon.of(v[2 * i], v[2 * i + 1], v[2 * j], v[2 * j + 1], v[2 * m], v[2 * m + 1]));
            } catch (IllegalArgumentException e) {
                // three corners on a line
            }
            // a box with one corner at a vertex, the other at the midpoint of a diagonal
            float mx = (v[2 * i] + v[2 * j]) / 2, my = (v[2 * i + 1] + v[2 * j + 1]) / 2;
            out.add(new Rect(Math.min(mx, v[2 * m]), Math.min(my, v[2 * m + 1]), Math.abs(mx - v[2 * m]), Math.abs(my - v[2 * m + 1])));
        }
        return out;
    }

    /** The closure of a polygonal or zero-size shape as JTS geometry. */
    static Geometry jts(Shape s) {
        if (s instanceof Circle c && c.r() == 0 || s instanceof Capsule k && k.r() == 0) {
            return JtsShapes.core(s);
        }
        return JtsShapes.straight(s);
    }

    // ------------------------------------------------------------------ dense sampling, the curved kinds

    @Test
    void curvedKinds_agreeWithDenseSampling_bothOrders() {
        SplittableRandom rnd = new SplittableRandom(77);
        int cases = 0, judged = 0, held = 0, ambiguous = 0;
        List<String> wrong = new ArrayList<>();
        for (int i = 0; i < 1500; i++) {
            Shape a = any(rnd, true);
            Shape b = any(rnd, false);
            if (!(curved(a) || curved(b))) {
                continue;
            }
            // and b moved to a's centre (to half pixels), where holding is common
            Rect ab = a.bounds(), bb = b.bounds();
            Shape centred = b.translated(Math.round(ab.x() + ab.w() / 2 - bb.x() - bb.w() / 2),
                    Math.round(ab.y() + ab.h() / 2 - bb.y() - bb.h() / 2));
            for (Shape[] pair : new Shape[][] {{a, b}, {b, a}, {a, centred}}) {
                cases++;
                double excess = excess(pair[0], pair[1]);
                double band = 1e-3 * (1 + size(pair[0]));
                boolean got = pair[0].contains(pair[1]);
                if (Math.abs(excess) < band) {
                    ambiguous++;
                    continue;
                }
                judged++;
                boolean want = excess < 0;
                held += want ? 1 : 0;
                if (want != got && wrong.size() < 20) {
                    wrong.add(pair[0] + " contains " + pair[1] + ": sampled excess " + excess + ", Hitbox " + got);
                }
            }
        }
        System.out.println("containment vs dense sampling: " + cases + " ordered pairs, " + judged + " judged ("
                + held + " held), " + ambiguous + " within the band of touching, " + wrong.size() + " disagreements");
        assertEquals(List.of(), wrong);
        assertTrue(held > judged / 20, "too few held cases: " + held);
    }

    @Test
    void curvedKinds_touchingFromInside_byConstruction() {
        // Pairs whose outlines meet, made so: held as they are, not when the inner one grows
        // by a relative 1e-5 (far outside the 1e-9 tolerance, far inside a float's reach).
        SplittableRandom rnd = new SplittableRandom(5);
        int n = 0;
        for (int i = 0; i < 400; i++) {
            float x = half(rnd, -50, 50), y = half(rnd, -50, 50);
            float a = 1 + rnd.nextInt(40), b = 1 + rnd.nextInt(40), angle = rnd.nextBoolean() ? 0 : (float) rnd.nextDouble(-4, 4);
            float lo = Math.min(a, b), hi = Math.max(a, b), grow = 1 + 1e-5f;
            Ellipse e = new Ellipse(x, y, a, b, angle);
            // the circle on the minor axis's ends, and the one through the major axis's ends
            n += held(e, new Circle(x, y, lo), new Circle(x, y, lo * grow));
            n += held(new Circle(x, y, hi), e, new Ellipse(x, y, a * grow, b * grow, angle));
            // an ellipse with one radius shorter: they touch at the other axis's ends
            if (a > 1) {
                n += held(e, new Ellipse(x, y, a - 1, b, angle), new Ellipse(x, y, a - 1, b * grow, angle));
            }
            // the ellipse through a horizontal capsule's ends and sides
            float d = 1 + rnd.nextInt(20), r = 1 + rnd.nextInt(20);
            n += held(new Capsule(x - d, y, x + d, y, r), new Ellipse(x, y, d + r, r), new Ellipse(x, y, d + r, r * grow));
            // a capsule inside a circle, its ends' discs touching it
            n += held(new Circle(x, y, d + r), new Capsule(x - d, y, x + d, y, r), new Capsule(x - d, y, x + d, y, r * grow));
            // a circle in a capsule's end
            n += held(new Capsule(x - d, y, x + d, y, r), new Circle(x + d, y, r), new Circle(x + d, y, r * grow));
            // every curved shape holds itself
            n += e.contains(e) ? 1 : 0;
        }
        assertTrue(n > 400 * 6, "pairs checked: " + n);
    }

    @Test
    void curvedSearch_nearTies_flipWithinAHundredThousandth() {
        // A curved shape inside a curved container, scaled about its centre until the sampled
        // oracle says it touches (bisection on the scale); then 1e-5 smaller must be held and
        // 1e-5 larger must not: the search is checked at the tie, where sampling alone judges
        // nothing.
        SplittableRandom rnd = new SplittableRandom(11);
        int checked = 0;
        for (int i = 0; i < 120; i++) {
            Shape a = curvedOnly(rnd, 20);
            Rect box = a.bounds();
            float cx = box.x() + box.w() / 2 + (float) rnd.nextDouble(-2, 2), cy = box.y() + box.h() / 2 + (float) rnd.nextDouble(-2, 2);
            Shape unit = curvedOnly(rnd, 6);
            double lo = 0, hi = 1;
            while (excess(a, scaled(unit, cx, cy, hi)) < 0 && hi < 1e4) {
                hi *= 2;
            }
            if (excess(a, scaled(unit, cx, cy, 1e-6)) >= 0) {
                continue; // the centre is not inside
            }
            for (int k = 0; k < 60; k++) {
                double mid = (lo + hi) / 2;
                if (excess(a, scaled(unit, cx, cy, mid)) < 0) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            Shape inner = scaled(unit, cx, cy, lo * (1 - 1e-5)), outer = scaled(unit, cx, cy, lo * (1 + 1e-5));
            assertTrue(a.contains(inner), a + " must hold " + inner);
            assertFalse(a.contains(outer), a + " must not hold " + outer);
            checked++;
        }
        System.out.println("containment near ties (curved, 1e-5 either side): " + checked + " pairs");
        assertTrue(checked > 60, "checked " + checked);
    }

    /** A circle, ellipse (aligned or turned) or capsule with area, about the origin. */
    private static Shape curvedOnly(SplittableRandom rnd, int size) {
        float r1 = 1 + rnd.nextInt(size), r2 = 1 + rnd.nextInt(size);
        return switch (rnd.nextInt(4)) {
            case 0 -> new Circle(0, 0, r1);
            case 1 -> new Ellipse(0, 0, r1, r2);
            case 2 -> new Ellipse(0, 0, r1, r2, (float) rnd.nextDouble(-4, 4));
            default -> {
                double t = rnd.nextDouble(0, 2 * Math.PI);
                yield new Capsule((float) (-r2 * Math.cos(t)), (float) (-r2 * Math.sin(t)), (float) (r2 * Math.cos(t)),
                        (float) (r2 * Math.sin(t)), r1 / 2);
            }
        };
    }

    /** The shape (about the origin) scaled by f and moved to (x, y). */
    private static Shape scaled(Shape s, float x, float y, double f) {
        if (s instanceof Circle c) {
            return new Circle(x, y, (float) (c.r() * f));
        }
        if (s instanceof Ellipse e) {
            return new Ellipse(x, y, (float) (e.rx() * f), (float) (e.ry() * f), e.angle());
        }
        Capsule k = (Capsule) s;
        return new Capsule((float) (x + k.x1() * f), (float) (y + k.y1() * f), (float) (x + k.x2() * f), (float) (y + k.y2() * f),
                (float) (k.r() * f));
    }

    /** a holds b and not the grown b; 1 when so (asserted). */
    private static int held(Shape a, Shape b, Shape grown) {
        assertTrue(a.contains(b), a + " must hold " + b);
        assertFalse(a.contains(grown), a + " must not hold " + grown);
        return 1;
    }

    @Test
    void chains_areTransitive_andNestTheirBoxes() {
        // a big shape, a smaller one moved to its centre, a smaller one moved to that one's
        // centre: chains a > b > c are common, and a must then hold c (every kind, ellipses
        // included: the tolerance is far below these half-pixel gaps)
        SplittableRandom rnd = new SplittableRandom(31);
        int chains = 0;
        for (int i = 0; i < 6000; i++) {
            Shape a = any(rnd, true);
            Shape b = centredOn(a, any(rnd, false));
            Shape c = centredOn(b, scaledDown(any(rnd, false)));
            if (a.contains(b) && b.contains(c)) {
                chains++;
                assertTrue(a.contains(c), a + " > " + b + " > " + c);
            }
        }
        System.out.println("containment chains a > b > c checked for a > c: " + chains);
        assertTrue(chains > 500, "chains: " + chains);
    }

    /** b moved by whole pixels so that its box's centre is near a's. */
    private static Shape centredOn(Shape a, Shape b) {
        Rect ab = a.bounds(), bb = b.bounds();
        return b.translated(Math.round(ab.x() + ab.w() / 2 - bb.x() - bb.w() / 2),
                Math.round(ab.y() + ab.h() / 2 - bb.y() - bb.h() / 2));
    }

    /** A smaller shape of the same kind (sizes a quarter, corners drawn in about the first). */
    private static Shape scaledDown(Shape s) {
        if (s instanceof Circle c) {
            return new Circle(c.x(), c.y(), c.r() / 4);
        }
        if (s instanceof Rect r) {
            return new Rect(r.x(), r.y(), r.w() / 4, r.h() / 4);
        }
        if (s instanceof Ellipse e) {
            return new Ellipse(e.x(), e.y(), e.rx() / 4, e.ry() / 4, e.angle());
        }
        if (s instanceof Capsule k) {
            return new Capsule(k.x1(), k.y1(), k.x1() + (k.x2() - k.x1()) / 4, k.y1() + (k.y2() - k.y1()) / 4, k.r() / 4);
        }
        if (s instanceof Segment g) {
            return new Segment(g.x1(), g.y1(), g.x1() + (g.x2() - g.x1()) / 4, g.y1() + (g.y2() - g.y1()) / 4);
        }
        return s;
    }

    /** The largest signed distance outside a (negative inside) over points of b's outline. */
    static double excess(Shape a, Shape b) {
        double most = Double.NEGATIVE_INFINITY;
        for (double[] p : Sampled.outline(b)) {
            most = Math.max(most, signedDistance(a, p[0], p[1]));
        }
        return most;
    }

    /**
     * A signed distance from the shape's outline, negative inside: exact for circles,
     * rectangles, segments, polygons and capsules; for an ellipse a bound with the right sign
     * that is never larger in size than the true distance ((g - 1) times the smaller radius, g
     * the point's scale from the centre, since g E holds E grown by that much).
     */
    static double signedDistance(Shape s, double x, double y) {
        if (s instanceof Circle c) {
            return Math.hypot(x - c.x(), y - c.y()) - c.r();
        }
        if (s instanceof Rect r) {
            double dx = Math.max(r.x() - x, x - ((double) r.x() + r.w()));
            double dy = Math.max(r.y() - y, y - ((double) r.y() + r.h()));
            return dx <= 0 && dy <= 0 ? Math.max(dx, dy) : Math.hypot(Math.max(dx, 0), Math.max(dy, 0));
        }
        if (s instanceof Segment g) {
            return Sampled.segmentDistance(g.x1(), g.y1(), g.x2(), g.y2(), x, y);
        }
        if (s instanceof Capsule k) {
            return Sampled.segmentDistance(k.x1(), k.y1(), k.x2(), k.y2(), x, y) - k.r();
        }
        if (s instanceof Polygon p) {
            double d = Double.POSITIVE_INFINITY;
            for (int i = 0; i < p.size(); i++) {
                Segment e = p.edge(i);
                d = Math.min(d, Sampled.segmentDistance(e.x1(), e.y1(), e.x2(), e.y2(), x, y));
            }
            return Sampled.inside(p, x, y) ? -d : d;
        }
        Ellipse e = (Ellipse) s;
        double c = Math.cos(e.angle()), sn = Math.sin(e.angle());
        if (e.rx() == 0 || e.ry() == 0) {
            double hx = e.rx() * c - e.ry() * sn, hy = e.rx() * sn + e.ry() * c;
            return Sampled.segmentDistance(e.x() - hx, e.y() - hy, e.x() + hx, e.y() + hy, x, y);
        }
        double dx = x - e.x(), dy = y - e.y();
        double g = Math.hypot((dx * c + dy * sn) / e.rx(), (-dx * sn + dy * c) / e.ry());
        return (g - 1) * Math.min(e.rx(), e.ry());
    }

    private static boolean curved(Shape s) {
        return s instanceof Circle c && c.r() > 0 || s instanceof Ellipse || s instanceof Capsule k && k.r() > 0;
    }

    private static double size(Shape s) {
        Rect b = s.bounds();
        return Math.max(b.w(), b.h());
    }

    /** Any kind, curved ones often, on half pixels; containers larger. */
    static Shape any(SplittableRandom rnd, boolean big) {
        int size = big ? 30 : 10;
        switch (rnd.nextInt(8)) {
            case 0:
                return new Circle(half(rnd, -10, 10), half(rnd, -10, 10), rnd.nextInt(8) == 0 ? 0 : half(rnd, 0, size));
            case 1: {
                float rx = rnd.nextInt(8) == 0 ? 0 : half(rnd, 0, size), ry = half(rnd, 0, size);
                return new Ellipse(half(rnd, -10, 10), half(rnd, -10, 10), rx, ry);
            }
            case 2:
                return new Ellipse(half(rnd, -10, 10), half(rnd, -10, 10), half(rnd, 0, size), half(rnd, 0, size),
                        (float) rnd.nextDouble(-4, 4));
            case 3:
            case 4:
                return new Capsule(half(rnd, -10, 10), half(rnd, -10, 10), half(rnd, -10, 10), half(rnd, -10, 10),
                        rnd.nextInt(8) == 0 ? 0 : half(rnd, 0, size / 2));
            default:
                return polygonal(rnd, big);
        }
    }

    /** Every kind, plain and awkward, for the checks every shape must pass. */
    static List<Shape> samples() {
        return List.of(new Circle(0, 0, 10), new Circle(3, 4, 0), new Rect(-8, -6, 16, 12), new Rect(0, 0, 10, 0),
                new Segment(-9, -3, 9, 4), new Segment(1, 1, 1, 1), Polygon.of(TestShapes.CUP), Polygon.of(TestShapes.CROWN),
                Polygon.of(-10, -8, 10, -8, 11, 8, -9, 9), new Ellipse(0, 0, 12, 6), new Ellipse(0, 0, 12, 6, 0.7f),
                new Ellipse(1, 2, 0, 6), new Ellipse(1, 2, 5, 0, 0.4f), new Capsule(-6, -2, 6, 3, 4), new Capsule(0, 0, 5, 5, 0),
                new Capsule(2, 2, 2, 2, 3));
    }
}
