package hitbox;

import hitbox.internal.*;

import java.util.List;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Assume;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import static hitbox.ContactFixtures.assertNoShorterMove;
import static hitbox.ContactFixtures.assertPushOutTouches;
import static hitbox.ContactFixtures.assertReversed;
import static hitbox.ContactFixtures.assertUnit;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class SeparatingAxisTest {

    static Polygon square(float x, float y, float size) {
        return Polygon.of(x, y, x + size, y, x + size, y + size, x, y + size);
    }

    static Polygon diamond(float cx, float cy, float r) {
        return Polygon.of(cx, cy - r, cx + r, cy, cx, cy + r, cx - r, cy);
    }

    static Polygon poly(Rect r) {
        return Polygon.of(r.x(), r.y(), r.right(), r.y(), r.right(), r.bottom(), r.x(), r.bottom());
    }

    // ------------------------------------------------------------------------ axes

    @Test
    void axes_twoSquares_aEdgesThenB_outwardNormals_shadows() {
        List<SeparatingAxis.Axis> axes = SeparatingAxis.axes(square(0, 0, 10), square(5, 5, 10));
        assertEquals(List.of(
                // a's edges: top (0,0)-(10,0) faces up, then right, bottom, left
                new SeparatingAxis.Axis(0, -1, -10, 0, -15, -5),
                new SeparatingAxis.Axis(1, 0, 0, 10, 5, 15),
                new SeparatingAxis.Axis(0, 1, 0, 10, 5, 15),
                new SeparatingAxis.Axis(-1, 0, -10, 0, -15, -5),
                // b's edges, in its own vertex order
                new SeparatingAxis.Axis(0, -1, -10, 0, -15, -5),
                new SeparatingAxis.Axis(1, 0, 0, 10, 5, 15),
                new SeparatingAxis.Axis(0, 1, 0, 10, 5, 15),
                new SeparatingAxis.Axis(-1, 0, -10, 0, -15, -5)), axes);
        for (SeparatingAxis.Axis axis : axes) {
            assertEquals(5, axis.overlap());
            assertFalse(axis.separates());
        }
    }

    @Test
    void axes_otherWinding_stillOutward() {
        // The same square listed the other way round: edge 0 is the left edge, facing left.
        Polygon a = Polygon.of(0, 0, 0, 10, 10, 10, 10, 0);
        SeparatingAxis.Axis first = SeparatingAxis.axes(a, a).get(0);
        assertEquals(-1, first.nx());
        assertEquals(0, first.ny());
    }

    @Test
    void axes_touchingDiamonds_sharedEdgeAxesSeparateWithZeroOverlap() {
        // Diamonds sharing the edge (5, 0)-(0, 5); projections on a diagonal are exact.
        List<SeparatingAxis.Axis> axes = SeparatingAxis.axes(diamond(0, 0, 5), diamond(5, 5, 5));
        // Edges 1 and 3 of each diamond are parallel (normals along +-(1, 1)): four axes on
        // that one line, and each shows the shared edge as a zero overlap.
        long separating = axes.stream().filter(SeparatingAxis.Axis::separates).count();
        assertEquals(4, separating);
        assertTrue(axes.stream().filter(SeparatingAxis.Axis::separates).allMatch(a -> a.overlap() == 0));
    }

    @Test
    void axes_listIsUnmodifiable() {
        List<SeparatingAxis.Axis> axes = SeparatingAxis.axes(square(0, 0, 1), square(0, 0, 1));
        assertThrows(UnsupportedOperationException.class, () -> axes.remove(0));
    }

    @ParameterizedTest
    @CsvSource({
        // minA, maxA, minB, maxB, overlap
        "0, 5, 4, 9, 1",       // shadows overlap by 1
        "0, 2, 2, 5, 0",       // they touch: overlap 0, separating
        "0, 1, 4, 6, -3",      // a gap of 3
        "0, 10, 2, 3, 1",      // b's shadow inside a's: the overlap is b's length
        "4, 6, 0, 1, -3",      // b before a
    })
    void axis_overlapAndSeparates(float minA, float maxA, float minB, float maxB, float overlap) {
        SeparatingAxis.Axis axis = new SeparatingAxis.Axis(1, 0, minA, maxA, minB, maxB);
        assertEquals(overlap, axis.overlap());
        assertEquals(overlap <= 0, axis.separates());
    }

    @ParameterizedTest
    @CsvSource({
        "1, 1, 0, 1, 0, 1, 'the axis (nx, ny) must have length 1, but (1.0, 1.0) has length 1.4142135'",
        "1, 0, 2, 1, 0, 1, 'a shadow must not end before it starts (minA <= maxA, minB <= maxB), but a is [2.0, 1.0] and b is [0.0, 1.0]'",
        "1, 0, 0, 1, 0, NaN, 'maxB must be a finite number, was NaN'",
    })
    void axis_badValues_throw(float nx, float ny, float minA, float maxA, float minB, float maxB, String message) {
        assertEquals(message, assertThrows(IllegalArgumentException.class,
                () -> new SeparatingAxis.Axis(nx, ny, minA, maxA, minB, maxB)).getMessage());
    }

    // ------------------------------------------------------------------------ overlaps

    @ParameterizedTest
    @CsvSource({
        // ax, ay, as, bx, by, bs, overlaps
        "0, 0, 10, 5, 5, 10, true",
        "0, 0, 10, 10, 0, 10, false",    // side by side
        "0, 0, 10, 10, 10, 10, false",   // corner to corner
        "0, 0, 10, 11, 0, 10, false",    // apart
        "0, 0, 10, 2, 2, 3, true",       // containment
        "0, 0, 10, 0, 0, 10, true",      // the same square
    })
    void overlaps_squares(float ax, float ay, float as, float bx, float by, float bs, boolean expected) {
        assertEquals(expected, square(ax, ay, as).overlaps(square(bx, by, bs)));
        assertEquals(expected, square(bx, by, bs).overlaps(square(ax, ay, as)));
    }

    @ParameterizedTest
    @CsvSource({
        "5, 5, 5, false",     // sharing an edge
        "10, 0, 5, false",    // sharing a corner
        "4, 4, 5, true",      // overlapping by a sliver
        "0, 0, 2, true",      // inside
    })
    void overlaps_diamonds(float bx, float by, float br, boolean expected) {
        assertEquals(expected, diamond(0, 0, 5).overlaps(diamond(bx, by, br)));
        assertEquals(expected, diamond(bx, by, br).overlaps(diamond(0, 0, 5)));
    }

    @ParameterizedTest
    @CsvSource({"1000000, 0", "0, -1000000", "999999, 1000000"})
    void overlaps_hugeCoordinates_touchingStillTouching(float dx, float dy) {
        assertFalse(diamond(dx, dy, 5).overlaps(diamond(5 + dx, 5 + dy, 5)));
        assertTrue(diamond(dx, dy, 5).overlaps(diamond(4 + dx, 4 + dy, 5)));
    }

    @Test
    void concavePolygon_throwsNamingTheVertex() {
        Polygon l = Polygon.of(0, 0, 6, 0, 6, 2, 2, 2, 2, 6, 0, 6);
        Polygon sq = square(0, 0, 1);
        assertEquals("SAT needs convex polygons; polygon a is concave at vertex 3 (2.0, 2.0)",
                assertThrows(IllegalArgumentException.class, () -> SeparatingAxis.axes(l, sq)).getMessage());
        assertEquals("SAT needs convex polygons; polygon b is concave at vertex 3 (2.0, 2.0)",
                assertThrows(IllegalArgumentException.class, () -> SeparatingAxis.axes(sq, l)).getMessage());
        assertEquals("a must not be null",
                assertThrows(IllegalArgumentException.class, () -> SeparatingAxis.axes(null, sq)).getMessage());
        assertEquals("b must not be null",
                assertThrows(IllegalArgumentException.class, () -> SeparatingAxis.axes(sq, null)).getMessage());
    }

    @Test
    void concaveVertex_straightVerticesAreConvex_otherWindingToo() {
        assertEquals(-1, Polygons.concaveVertex(new float[] {0, 0, 5, 0, 10, 0, 10, 10, 0, 10}));
        assertEquals(-1, Polygons.concaveVertex(new float[] {0, 10, 10, 10, 10, 0, 0, 0}));
        // The L listed the other way round: the inward corner (2, 2) is vertex 2.
        assertEquals(2, Polygons.concaveVertex(new float[] {0, 6, 2, 6, 2, 2, 6, 2, 6, 0, 0, 0}));
    }

    // ------------------------------------------------------------------------ contact

    @ParameterizedTest
    @CsvSource({
        // b's square x, y, size; expected nx, ny, depth (a is the square 0, 0, 10)
        "8, 2, 4, 1, 0, 2",
        "2, 7, 4, 0, 1, 3",
        "0, 0, 10, 0, 1, 10",    // the same square: tie, a goes up
        "1, 3, 2, -1, 0, 3",     // containment: b leaves through a's left edge
    })
    void contact_squares(float bx, float by, float bs, float nx, float ny, float depth) {
        Contact c = square(0, 0, 10).contact(square(bx, by, bs));
        assertEquals(new Contact(nx, ny, depth), c);
        assertEquals(Raw.contactRectRect(0, 0, 10, 10, bx, by, bs, bs), c);
    }

    @Test
    void contact_diamonds_diagonalNormal_bothOrders() {
        Contact c = diamond(0, 0, 5).contact(diamond(4, 4, 5));
        assertNotNull(c);
        assertEquals(Math.sqrt(0.5), c.nx(), 1e-6);
        assertEquals(Math.sqrt(0.5), c.ny(), 1e-6);
        assertEquals(Math.sqrt(2), c.depth(), 1e-6);
        assertReversed(c, diamond(4, 4, 5).contact(diamond(0, 0, 5)));
        assertNull(diamond(0, 0, 5).contact(diamond(5, 5, 5)));
    }

    @ParameterizedTest
    @CsvSource({"1000000, 0", "0, 1000000", "-999999, 999999"})
    void contact_hugeCoordinates_sameContact(float dx, float dy) {
        assertEquals(diamond(0, 0, 5).contact(diamond(4, 4, 5)),
                diamond(dx, dy, 5).contact(diamond(4 + dx, 4 + dy, 5)));
        assertEquals(square(0, 0, 10).contact(square(1, 3, 2)),
                square(dx, dy, 10).contact(square(1 + dx, 3 + dy, 2)));
    }

    // ------------------------------------------------------------------------ properties

    @Provide
    Arbitrary<Rect> solidRect() {
        return ContactFixtures.solidRects();
    }

    @Provide
    Arbitrary<Polygon> rotatedRect() {
        return ContactFixtures.rotatedRects();
    }

    @Provide
    Arbitrary<Polygon> convex() {
        return ContactFixtures.convexPolygons();
    }

    @Property
    void overlaps_agreesWithCollide_forRects(@ForAll("solidRect") Rect a, @ForAll("solidRect") Rect b) {
        assertEquals(Collide.rectRect(a.x(), a.y(), a.w(), a.h(), b.x(), b.y(), b.w(), b.h()),
                poly(a).overlaps(poly(b)));
    }

    @Property
    void contact_agreesWithRectRect(@ForAll("solidRect") Rect a, @ForAll("solidRect") Rect b) {
        assertEquals(Raw.contactRectRect(a.x(), a.y(), a.w(), a.h(), b.x(), b.y(), b.w(), b.h()),
                poly(a).contact(poly(b)));
    }

    @Property
    void overlaps_rotatedRects_agreeWithSampledPoints(@ForAll("rotatedRect") Polygon a, @ForAll("rotatedRect") Polygon b) {
        boolean sat = a.overlaps(b);
        // Sampled: a grid point inside both proves an overlap, so SAT must see it.
        if (sampledCommonPoint(a, b, 0.5)) {
            assertTrue(sat, "a grid point lies inside both");
        }
        // And every overlap SAT reports has a point inside both: the middle of the
        // intersection's corners (corners of each inside the other, and edge crossings).
        double[] mid = intersectionMiddle(a, b);
        assertEquals(sat, mid != null && strictlyInside(a, mid[0], mid[1]) && strictlyInside(b, mid[0], mid[1]),
                () -> "SAT says " + sat);
    }

    @Property
    void overlaps_agreesWithContact_andAxes(@ForAll("convex") Polygon a, @ForAll("convex") Polygon b) {
        boolean sat = a.overlaps(b);
        assertEquals(sat, a.contact(b) != null);
        assertEquals(sat, SeparatingAxis.axes(a, b).stream().noneMatch(SeparatingAxis.Axis::separates));
        assertEquals(sat, ContactFixtures.overlapsRef(a, b));
    }

    @Property(maxDiscardRatio = 20)
    void contact_reversedOrder_translationInvariant_unitNormal(@ForAll("rotatedRect") Polygon a, @ForAll("rotatedRect") Polygon b,
                                                                @ForAll @IntRange(min = -1000, max = 1000) int dx,
                                                                @ForAll @IntRange(min = -1000, max = 1000) int dy) {
        Contact c = a.contact(b);
        Assume.that(c != null);
        assertUnit(c);
        ContactFixtures.assertReversedOrSymmetricTie(a, b, c, b.contact(a));
        Contact moved = a.translated(dx, dy).contact(b.translated(dx, dy));
        // Rotated corners are not whole numbers, so moving them rounds: the depth is close,
        // and where two directions (nearly) tie, rounding may pick the other one; then that
        // one must push the unmoved shapes apart just as well.
        assertEquals(c.depth(), moved.depth(), 1e-3);
        if (Math.abs(c.nx() - moved.nx()) > 1e-3 || Math.abs(c.ny() - moved.ny()) > 1e-3) {
            assertPushOutTouches(a, b, moved);
        }
    }

    @Property
    void contact_wholeNumbers_translationInvariantExactly(@ForAll("convex") Polygon a, @ForAll("convex") Polygon b,
                                                          @ForAll @IntRange(min = -1000000, max = 1000000) int dx,
                                                          @ForAll @IntRange(min = -1000000, max = 1000000) int dy) {
        assertEquals(a.contact(b), a.translated(dx, dy).contact(b.translated(dx, dy)));
    }

    @Property(maxDiscardRatio = 20)
    void contact_pushingOut_leavesThemTouching(@ForAll("rotatedRect") Polygon a, @ForAll("rotatedRect") Polygon b) {
        Contact c = a.contact(b);
        Assume.that(c != null);
        assertPushOutTouches(a, b, c);
    }

    @Property(tries = 60, maxDiscardRatio = 20)
    void contact_isTheMinimumTranslation(@ForAll("convex") Polygon a, @ForAll("convex") Polygon b) {
        Contact c = a.contact(b);
        Assume.that(c != null);
        assertPushOutTouches(a, b, c);
        assertNoShorterMove(a, b, c);
        assertEquals(minkowskiDepth(a, b), c.depth(), 1e-4 + 1e-5 * c.depth());
    }

    /**
     * The penetration depth of two convex polygons by another road than the separating axes:
     * the distance from the origin to the outline of their Minkowski difference, the convex
     * hull (JTS's) of every corner of a less every corner of b. Exact up to double rounding,
     * however sharp a corner is (the sampled {@code ContactFixtures.slowDepth} resolves a
     * thin corner's depth only to the square root of its area threshold).
     */
    static double minkowskiDepth(Polygon a, Polygon b) {
        org.locationtech.jts.geom.GeometryFactory jts = new org.locationtech.jts.geom.GeometryFactory();
        org.locationtech.jts.geom.Coordinate[] d = new org.locationtech.jts.geom.Coordinate[a.size() * b.size()];
        for (int i = 0; i < a.size(); i++) {
            for (int j = 0; j < b.size(); j++) {
                d[i * b.size() + j] = new org.locationtech.jts.geom.Coordinate(
                        (double) a.x(i) - b.x(j), (double) a.y(i) - b.y(j));
            }
        }
        org.locationtech.jts.geom.Geometry hull = new org.locationtech.jts.algorithm.ConvexHull(d, jts).getConvexHull();
        return hull.getBoundary().distance(jts.createPoint(new org.locationtech.jts.geom.Coordinate(0, 0)));
    }

    // ------------------------------------------------------------------------ slow references

    static boolean strictlyInside(Polygon p, double x, double y) {
        int n = p.size();
        double sign = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double o = ((double) p.x(j) - p.x(i)) * (y - p.y(i)) - ((double) p.y(j) - p.y(i)) * (x - p.x(i));
            if (o == 0 || (sign != 0 && Math.signum(o) != sign)) {
                return false;
            }
            sign = Math.signum(o);
        }
        return true;
    }

    static boolean sampledCommonPoint(Polygon a, Polygon b, double step) {
        Rect ra = a.bounds(), rb = b.bounds();
        double x0 = Math.max(ra.x(), rb.x()), x1 = Math.min(ra.right(), rb.right());
        double y0 = Math.max(ra.y(), rb.y()), y1 = Math.min(ra.bottom(), rb.bottom());
        for (double x = Math.floor(x0) + step / 2; x < x1; x += step) {
            for (double y = Math.floor(y0) + step / 2; y < y1; y += step) {
                if (strictlyInside(a, x, y) && strictlyInside(b, x, y)) {
                    return true;
                }
            }
        }
        return false;
    }

    /** Where segments p0-p1 and q0-q1 meet (ends included), or null; parallel ones are skipped. */
    static double[] crossing(double p0x, double p0y, double p1x, double p1y, double q0x, double q0y, double q1x, double q1y) {
        double ex = p1x - p0x, ey = p1y - p0y, fx = q1x - q0x, fy = q1y - q0y;
        double den = ex * fy - ey * fx;
        if (den == 0) {
            return null;
        }
        double t = ((q0x - p0x) * fy - (q0y - p0y) * fx) / den;
        double u = ((q0x - p0x) * ey - (q0y - p0y) * ex) / den;
        return t < 0 || t > 1 || u < 0 || u > 1 ? null : new double[] {p0x + t * ex, p0y + t * ey};
    }

    /** The average of the intersection's corner candidates, or null if there are none. */
    static double[] intersectionMiddle(Polygon a, Polygon b) {
        double sx = 0, sy = 0;
        int count = 0;
        for (Polygon[] pq : new Polygon[][] {{a, b}, {b, a}}) {
            Polygon p = pq[0], q = pq[1];
            for (int i = 0; i < p.size(); i++) {
                if (strictlyInside(q, p.x(i), p.y(i))) {
                    sx += p.x(i);
                    sy += p.y(i);
                    count++;
                }
            }
        }
        for (int i = 0; i < a.size(); i++) {
            for (int j = 0; j < b.size(); j++) {
                double[] c = crossing(a.x(i), a.y(i), a.x((i + 1) % a.size()), a.y((i + 1) % a.size()),
                        b.x(j), b.y(j), b.x((j + 1) % b.size()), b.y((j + 1) % b.size()));
                if (c != null) {
                    sx += c[0];
                    sy += c[1];
                    count++;
                }
            }
        }
        return count == 0 ? null : new double[] {sx / count, sy / count};
    }
}
