package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;

/**
 * {@link Contact#between} on convex polygons and rectangles (flat ones too), as a sketch calls
 * it, against the separating axis theorem written out exactly ({@link
 * ExactReference#convexPushes}: every edge normal of both, every vertex projected, in
 * BigDecimal on the given floats), and against JTS: what the {@link Contact} javadoc promises.
 * <ul>
 *   <li>a contact exactly when the open shapes overlap;</li>
 *   <li>its depth the shortest push (to a float's rounding), its normal that push's direction,
 *       from a to b, and among pushes equally short to within {@link Contact#TIE} the one the
 *       tie rule names (larger |ny|, then larger nx ny, then larger ny, then larger nx);</li>
 *   <li>b moved by the contact, a little less, still overlaps a, and a little more it is
 *       clear, by JTS's relate on the moved outlines.</li>
 * </ul>
 */
class SeparatingAxisExactTest {

    private static final GeometryFactory GF = new GeometryFactory();

    private static Polygon ring(SplittableRandom rnd, boolean half) {
        return TestShapes.convexRing(rnd, 3 + rnd.nextInt(8), rnd.nextInt(200) / 2.0, rnd.nextInt(200) / 2.0, half);
    }

    private static Rect rect(SplittableRandom rnd, boolean half) {
        double scale = half ? 2.0 : 1 / (rnd.nextDouble() + 0.1);
        float x = (float) (rnd.nextInt(200) / scale), y = (float) (rnd.nextInt(200) / scale);
        // Flat ones too: a segment or a point has no inside, but a polygon can still cover it.
        float w = rnd.nextInt(8) == 0 ? 0 : (float) (rnd.nextInt(120) / scale);
        float h = rnd.nextInt(8) == 0 ? 0 : (float) (rnd.nextInt(120) / scale);
        return new Rect(x, y, w, h);
    }

    /** The corners, a rectangle's far sides {@code x + w} and {@code y + h} exact in double. */
    private static double[] corners(Shape s) {
        if (s instanceof Rect r) {
            double x = r.x(), y = r.y(), right = x + r.w(), bottom = y + r.h();
            return new double[] {x, y, right, y, right, bottom, x, bottom};
        }
        float[] xy = ((Polygon) s).coordinates();
        double[] d = new double[xy.length];
        for (int i = 0; i < xy.length; i++) {
            d[i] = xy[i];
        }
        return d;
    }

    /** The contact the theorem and the tie rule give, as {nx, ny, depth}; null for none. */
    static double[] expected(Shape a, Shape b) {
        List<BigDecimal[]> pushes = ExactReference.convexPushes(corners(a), corners(b));
        if (pushes == null) {
            return null;
        }
        // In double (to 1e-15, far inside the tie rule's 1e-10) to find the winner, which is
        // then worked out to 34 digits, so that its float is the correctly rounded one.
        double[][] candidates = new double[pushes.size()][];
        double least = Double.POSITIVE_INFINITY;
        for (int i = 0; i < pushes.size(); i++) {
            BigDecimal[] p = pushes.get(i);
            double mx = p[0].doubleValue(), my = p[1].doubleValue(), length = Math.sqrt(mx * mx + my * my);
            candidates[i] = new double[] {mx / length, my / length, p[2].doubleValue() / length, i};
            least = Math.min(least, candidates[i][2]);
        }
        double[] best = null;
        for (double[] c : candidates) {
            if (c[2] <= least * (1 + Contact.TIE) && (best == null || winsTie(c, best))) {
                best = c;
            }
        }
        BigDecimal[] p = pushes.get((int) best[3]);
        BigDecimal length = p[0].pow(2).add(p[1].pow(2)).sqrt(MathContext.DECIMAL128);
        return new double[] {p[0].divide(length, MathContext.DECIMAL128).doubleValue(),
                p[1].divide(length, MathContext.DECIMAL128).doubleValue(), p[2].divide(length, MathContext.DECIMAL128).doubleValue()};
    }

    /** The tie rule: the larger |ny|, then the larger nx ny, then the larger ny, then the larger nx. */
    private static boolean winsTie(double[] c, double[] than) {
        double[][] keys = {{Math.abs(c[1]), Math.abs(than[1])}, {c[0] * c[1], than[0] * than[1]}, {c[1], than[1]}, {c[0], than[0]}};
        for (double[] k : keys) {
            if (Math.abs(k[0] - k[1]) > 1e-12) {
                return k[0] > k[1];
            }
        }
        return false;
    }

    private static Geometry jts(Shape s, double dx, double dy) {
        double[] xy = corners(s);
        Coordinate[] c = new Coordinate[xy.length / 2 + 1];
        for (int i = 0; i < xy.length / 2; i++) {
            c[i] = new Coordinate(xy[2 * i] + dx, xy[2 * i + 1] + dy);
        }
        c[xy.length / 2] = c[0];
        return GF.createPolygon(c).buffer(0);
    }

    /** Do the insides of a and of b moved by (dx, dy) overlap, by JTS? */
    private static boolean jtsOverlap(Shape a, Shape b, double dx, double dy) {
        return jts(a, 0, 0).relate(jts(b, dx, dy), "T********");
    }

    private static void check(Shape a, Shape b, boolean half, boolean jts, String what) {
        Contact got = a.contact(b);
        double[] want = expected(a, b);
        what += ": " + got + ", exactly " + (want == null ? null : want[0] + ", " + want[1] + ", " + want[2]);
        if (want == null) {
            assertNull(got, what);
            return;
        }
        assertTrue(got != null, what);
        // Half-pixel corners: every product is exact, the answer the correctly rounded one.
        double slack = half ? 0 : 2e-7;
        assertEquals((float) want[0], got.nx(), slack, what);
        assertEquals((float) want[1], got.ny(), slack, what);
        assertEquals(Math.max((float) want[2], Float.MIN_VALUE), got.depth(), half ? 0 : 2 * Math.ulp((float) Math.max(1, want[2])), what);
        if (jts && want[2] > 1e-3) {
            // Flat shapes have no inside for JTS to compare.
            double less = got.depth() * 0.999, more = got.depth() * 1.001 + 1e-4;
            if (!jts(a, 0, 0).isEmpty() && !jts(b, 0, 0).isEmpty()) {
                assertTrue(jtsOverlap(a, b, got.nx() * less, got.ny() * less), what + ": clear before the depth");
                assertFalse(jtsOverlap(a, b, got.nx() * more, got.ny() * more), what + ": still overlapping past the depth");
            }
        }
    }

    private static void check(SplittableRandom rnd, boolean half, int cases) {
        int hits = 0;
        for (int i = 0; i < cases; i++) {
            Shape a = ring(rnd, half);
            Shape b = i % 3 == 2 ? rect(rnd, half) : ring(rnd, half);
            if (i % 6 == 5) {
                Shape t = a;
                a = b;
                b = t;
            }
            check(a, b, half, i % 10 == 0, "case " + i + ": " + a + " and " + b);
            hits += a.contact(b) != null ? 1 : 0;
        }
        assertTrue(hits > cases / 5, "hits " + hits);
    }

    @Test
    void halfPixelCornersGiveTheExactContact() {
        check(new SplittableRandom(12), true, 20_000);
    }

    @Test
    void floatCornersGiveTheExactContactToRounding() {
        check(new SplittableRandom(1212), false, 20_000);
    }

    @Test
    void parallelFacesAndSharedCentresKeepTheTieRule() {
        // Squares and octagons about the same centre or on a grid: every push ties with others.
        for (int k = 0; k < 400; k++) {
            float c = 50 + k % 7, d = 50 + k / 7 % 5;
            Shape a = k % 2 == 0 ? Polygon.regular(c, d, 10 + k % 3, 4, (float) (Math.PI / 4))
                    : Polygon.regular(c, d, 10 + k % 3, 8, 0);
            Shape b = k % 3 == 0 ? new Rect(48, 48, 8 + k % 4, 8) : Polygon.regular(50, 50, 12, k % 2 == 0 ? 8 : 4, 0);
            check(a, b, false, true, "case " + k + ": " + a + " and " + b);
        }
    }
}
