package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;

/**
 * The fast paths of issue 12: the convex polygon test by orientation signs
 * ({@link Polygons#convexOverlap}), the convexity check on raw arrays
 * ({@link Polygons#convexWinding}), {@link Collide#rectRect} where float sums round, the exact
 * near-zero shortcut of {@link Lines#orient}, and that the boolean, distance and convex
 * contact answers allocate nothing but their result.
 */
class ConvexFastPathTest {

    /** Convex hulls of 3 to 8 points on a 7 x 7 grid: small, so touching comes up often. */
    @Provide
    Arbitrary<float[]> hulls() {
        return Arbitraries.integers().between(0, 6).list().ofMinSize(6).ofMaxSize(16)
                .map(ConvexFastPathTest::hull)
                .filter(h -> h.length >= 6);
    }

    /** Andrew's monotone chain, strictly convex, on whole numbers (exact in long). */
    static float[] hull(List<Integer> coords) {
        List<long[]> p = new ArrayList<>();
        for (int i = 0; i + 1 < coords.size(); i += 2) {
            p.add(new long[] {coords.get(i), coords.get(i + 1)});
        }
        p.sort((u, v) -> u[0] != v[0] ? Long.compare(u[0], v[0]) : Long.compare(u[1], v[1]));
        long[][] h = new long[2 * p.size() + 1][];
        int k = 0;
        for (long[] q : p) {
            while (k >= 2 && cross(h[k - 2], h[k - 1], q) <= 0) {
                k--;
            }
            h[k++] = q;
        }
        for (int i = p.size() - 2, floor = k + 1; i >= 0; i--) {
            long[] q = p.get(i);
            while (k >= floor && cross(h[k - 2], h[k - 1], q) <= 0) {
                k--;
            }
            h[k++] = q;
        }
        k--; // the last point is the first again
        float[] xy = new float[2 * Math.max(k, 0)];
        for (int i = 0; i < k; i++) {
            xy[2 * i] = h[i][0];
            xy[2 * i + 1] = h[i][1];
        }
        return k >= 3 ? xy : new float[0];
    }

    private static long cross(long[] o, long[] a, long[] b) {
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    }

    @Property(tries = 3000)
    void convexPairs_agreeWithExactReference(@ForAll("hulls") float[] a, @ForAll("hulls") float[] b,
                                             @ForAll @IntRange(min = -3, max = 3) int dx,
                                             @ForAll @IntRange(min = -3, max = 3) int dy,
                                             @ForAll boolean reverse) {
        float[] moved = ExactReference.translated(reverse ? ExactReference.reversed(b) : b, dx, dy);
        boolean expected = ExactReference.polygonsMeet(a, moved);
        int wa = Polygons.convexWinding(a), wb = Polygons.convexWinding(moved);
        assertNotEquals(0, wa);
        assertNotEquals(0, wb);
        assertEquals(Polygons.winding(a), wa, "the convex winding is the winding");
        assertEquals(expected, Polygons.convexOverlap(a, wa, moved, wb));
        assertEquals(expected, Collide.polygonPolygon(a, moved));
        Polygon p = Polygon.of(a), q = Polygon.of(moved);
        assertEquals(expected, p.overlaps(q));
        assertEquals(expected, q.overlaps(p));
        assertEquals(expected, p.contact(q) != null);
    }

    @Test
    void convexWinding_readsRawArraysAsTheGeneralPathDoes() {
        float[] square = {0, 0, 10, 0, 10, 10, 0, 10};
        assertEquals(Polygons.winding(square), Polygons.convexWinding(square));
        float[] repeated = {0, 0, 10, 0, 10, 0, 10, 10, 0, 10, 0, 0};
        assertEquals(Polygons.winding(square), Polygons.convexWinding(repeated), "repeated vertices are skipped");
        float[] straight = {0, 0, 5, 0, 10, 0, 10, 10, 0, 10};
        assertEquals(Polygons.winding(square), Polygons.convexWinding(straight), "a vertex in the middle of a side");
        assertEquals(0, Polygons.convexWinding(new float[] {0, 0, 10, 0, 5, 2, 10, 10, 0, 10}), "concave");
        assertEquals(0, Polygons.convexWinding(new float[] {0, 0, 10, 0, 20, 0, 10, 0, 10, 10}), "folds back");
        assertEquals(0, Polygons.convexWinding(new float[] {0, 0, 10, 0, 20, 0}), "no area");
        assertEquals(0, Polygons.convexWinding(new float[] {0, 0, 10, 0}), "too few vertices");
        // A pentagram turns the same way at every corner but winds round twice.
        float[] star = new float[10];
        for (int i = 0; i < 5; i++) {
            double t = 2 * Math.PI * (2 * i) / 5;
            star[2 * i] = (float) Math.round(100 * Math.cos(t));
            star[2 * i + 1] = (float) Math.round(100 * Math.sin(t));
        }
        assertEquals(0, Polygons.convexWinding(star), "a pentagram is not convex");
        float[] negativeZero = {-0f, 0, 10, 0, 10, 10, 0f, 10};
        assertEquals(Polygons.winding(negativeZero), Polygons.convexWinding(negativeZero), "-0 and 0 are one x");
    }

    @Test
    void convexFastPath_decidesTouchingExactlyBeyondWholeNumbers() {
        // Triangles sharing an edge whose ends are not whole numbers: touching, not overlapping.
        float x = 0.1f, y = 1e7f + 1, u = 3.3f;
        float[] a = {x, 0, y, u, x, 10};
        float[] b = {x, 0, x, 10, -y, u};
        assertFalse(Collide.polygonPolygon(a, b));
        assertEquals(ExactReference.polygonsMeet(a, b), Collide.polygonPolygon(a, b));
        float[] c = {Math.nextUp(x), 0, y, u, x, 10};
        assertEquals(ExactReference.polygonsMeet(c, b), Collide.polygonPolygon(c, b));
    }

    @Test
    void rectRect_floatSumsThatRoundAreDecidedByTheDoubleSum() {
        float big = 0x1p24f; // floats step by 2 here: big + 1 rounds to big
        assertTrue(Collide.rectRect(big, 0, 1, 1, big, 0, 2, 1), "the exact right edge big + 1 is past big");
        assertFalse(Collide.rectRect(big + 2, 0, 1, 1, big + 4, 0, 2, 1), "big + 3 rounds up to big + 4 but is short of it");
        assertFalse(Collide.rectRect(big + 4, 0, 2, 1, big + 2, 0, 1, 1), "the same, swapped");
        assertTrue(Collide.rectRect(0, big, 1, 1, 0, big, 1, 2), "and in y");
        assertFalse(Collide.rectRect(0, Float.MAX_VALUE, 1, Float.MAX_VALUE, 0, Float.POSITIVE_INFINITY, 1, 1),
                "a float sum that overflows is still compared exactly");
    }

    @Property(tries = 3000)
    void orient_hasTheExactSign(@ForAll @IntRange(min = -40, max = 40) int e, @ForAll("coordinates") float ax,
                                @ForAll("coordinates") float ay, @ForAll("coordinates") float bx,
                                @ForAll("coordinates") float by, @ForAll @IntRange(min = -2, max = 2) int t) {
        // c on the line through a and b (t = 0) or a step off it, at scale 2^e.
        float s = (float) Math.scalb(1.0, e);
        float cx = ax * s + (bx - ax) * s, cy = ay * s + (by - ay) * s + t * Math.ulp(ay * s);
        double got = Lines.orient(ax * s, ay * s, bx * s, by * s, cx, cy);
        int exact = Lines.exactOrient(ax * s, ay * s, bx * s, by * s, cx, cy).signum();
        assertEquals(exact, (int) Math.signum(got));
    }

    @Provide
    Arbitrary<Float> coordinates() {
        return Arbitraries.oneOf(Arbitraries.integers().between(-1000, 1000).map(Integer::floatValue),
                Arbitraries.floats().between(-1e6f, 1e6f));
    }

    // ---------------------------------------------------------------- allocation

    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();

    /** Bytes allocated per call of {@code body} over many calls, after a warm-up. */
    private static double bytesPerCall(Runnable body) {
        for (int i = 0; i < 20_000; i++) {
            body.run();
        }
        long id = Thread.currentThread().getId();
        long before = THREADS.getThreadAllocatedBytes(id);
        int calls = 20_000;
        for (int i = 0; i < calls; i++) {
            body.run();
        }
        return (THREADS.getThreadAllocatedBytes(id) - before) / (double) calls;
    }

    static volatile Object sink;
    static volatile boolean flag;
    static volatile float number;

    @Test
    void booleanDistanceAndContactAnswers_allocateOnlyTheirResult() {
        float[] a = Polygon.regular(100, 100, 40, 8, 0.1f).coordinates();
        float[] b = Polygon.regular(150, 110, 40, 8, 0.3f).coordinates();
        float[] far = Polygon.regular(300, 110, 40, 8, 0.3f).coordinates();
        Polygon p = Polygon.of(a), q = Polygon.of(b), r = Polygon.of(far);
        assertTrue(p.overlaps(q));
        assertTrue(bytesPerCall(() -> flag = Collide.polygonPolygon(a, b)) < 1, "polygonPolygon");
        assertTrue(bytesPerCall(() -> flag = Collide.polygonPolygon(a, far)) < 1, "polygonPolygon, apart");
        assertTrue(bytesPerCall(() -> flag = p.overlaps(q)) < 1, "Polygon.overlaps");
        assertTrue(bytesPerCall(() -> flag = Collide.lineLine(0, 0, 10, 10, 5, 5, 20, 20)) < 1, "lineLine, collinear");
        assertTrue(bytesPerCall(() -> number = Ray.distanceToCircle(0, 0, 1, 1, 500, 50, 50, 10)) < 1, "distanceToCircle");
        assertTrue(bytesPerCall(() -> flag = Collide.rectRect(0, 0, 10, 10, 10, 0, 10, 10)) < 1, "rectRect, touching");
        assertTrue(bytesPerCall(() -> sink = p.contact(r)) < 1, "Contact.between, apart");
        // One Contact (a header and three floats) per call, nothing else.
        double contact = bytesPerCall(() -> sink = p.contact(q));
        assertTrue(contact <= 32, "Contact.between allocates " + contact + " bytes per call");
        assertEquals(Arrays.toString(a), Arrays.toString(p.coordinates()));
    }

    @Test
    void rectPolygonContact_allocatesOnlyItsResult() {
        Polygon p = Polygon.regular(100, 100, 40, 8, 0.1f);
        Rect box = new Rect(120, 90, 50, 30);
        Rect far = new Rect(300, 90, 50, 30);
        Contact expected = Polygon.of(box).contact(p);
        assertEquals(expected, box.contact(p));
        assertEquals(p.contact(Polygon.of(box)), p.contact(box));
        double there = bytesPerCall(() -> sink = box.contact(p));
        assertTrue(there <= 32, "rect.contact(polygon) allocates " + there + " bytes per call");
        double back = bytesPerCall(() -> sink = p.contact(box));
        assertTrue(back <= 32, "polygon.contact(rect) allocates " + back + " bytes per call");
        assertTrue(bytesPerCall(() -> sink = far.contact(p)) < 1, "rect.contact(polygon), apart");
    }
}
