package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The convex clip of {@link Ray#cast} against the old search over every crossing of the
 * outline ({@link RayPolygonOld}) on random convex polygons: rays from anywhere (inside, on a
 * vertex or an edge, on an edge's line), through corners and along edges, with and without an
 * end. On half-pixel corners and whole-number rays the hits must be the same floats; on float
 * corners the same hit to a float's rounding, and the same hit or miss except where the old
 * search misjudged a sliver thinner than a float (its stretch's middle, rounded to float, fell
 * on the outline): there the answer must be the exact one, worked out in {@link BigDecimal}.
 */
class RayConvexAgreementTest {

    /** A ray's start: anywhere, or on the polygon's vertices, edges and edge lines. */
    private static float[] start(SplittableRandom rnd, Polygon p, boolean half) {
        int i = rnd.nextInt(p.size()), j = (i + 1) % p.size();
        double t = switch (rnd.nextInt(4)) {
            case 0 -> 0;                      // a vertex
            case 1 -> 0.5;                    // an edge's middle
            case 2 -> -1 - rnd.nextInt(3);    // on the edge's line, outside
            default -> Double.NaN;            // anywhere
        };
        double x, y;
        if (Double.isNaN(t)) {
            x = rnd.nextInt(400) / 2.0;
            y = rnd.nextInt(400) / 2.0;
        } else {
            x = p.x(i) + t * (p.x(j) - p.x(i));
            y = p.y(i) + t * (p.y(j) - p.y(i));
        }
        return new float[] {half ? Math.round(2 * x) / 2f : (float) x, half ? Math.round(2 * y) / 2f : (float) y};
    }

    private static void agree(SplittableRandom rnd, boolean half, int cases) {
        int hits = 0, inside = 0, misjudged = 0;
        for (int c = 0; c < cases; c++) {
            Polygon p = TestShapes.convexRing(rnd, 3 + rnd.nextInt(8), 50 + rnd.nextInt(100) / 2.0, 50 + rnd.nextInt(100) / 2.0, half);
            float[] o = start(rnd, p, half);
            // Aimed at a vertex (through a corner, or along an edge), or anywhere near.
            int v = rnd.nextInt(p.size());
            float tx = rnd.nextBoolean() ? p.x(v) : (float) (50 + rnd.nextInt(100)), ty = rnd.nextBoolean() ? p.y(v) : (float) (50 + rnd.nextInt(100));
            float dx = tx - o[0], dy = ty - o[1];
            if (dx == 0 && dy == 0) {
                continue;
            }
            Ray ray = rnd.nextBoolean() ? new Ray(o[0], o[1], dx, dy) : Ray.between(o[0], o[1], tx, ty);
            RayHit now = ray.cast(p), was = RayPolygonOld.cast(ray, p);
            String what = "case " + c + ": " + ray + " at " + p + ": " + now + " was " + was;
            if ((was == null) != (now == null)) {
                // Only where the old search rounded a sliver away, and then the exact answer.
                assertTrue(!half && ++misjudged < cases / 100, what);
                Boolean exact = exactHit(ray, p);
                assertTrue(exact == null || exact == (now != null), what + ", exactly " + exact);
                continue;
            }
            if (now == null) {
                continue;
            }
            hits++;
            inside += now.distance() == 0 ? 1 : 0;
            if (half) {
                // The old search could say -0 for a start on the outline; 0 now.
                assertEquals(was.distance() == 0 ? new RayHit(0, was.x(), was.y(), was.nx(), was.ny()) : was, now, what);
            } else {
                assertEquals(was.distance(), now.distance(), 1e-5 * (1 + was.distance()), what);
                assertEquals(was.x(), now.x(), 1e-5 * (1 + Math.abs(was.x())), what);
                assertEquals(was.y(), now.y(), 1e-5 * (1 + Math.abs(was.y())), what);
                assertEquals(was.nx(), now.nx(), 1e-6, what);
                assertEquals(was.ny(), now.ny(), 1e-6, what);
            }
        }
        assertTrue(hits > cases / 5, "hits " + hits);
        assertTrue(inside > cases / 100, "from inside or the outline " + inside);
    }

    /**
     * Does the ray go into the convex polygon, exactly? Null when its way in and out are so
     * close (within 10 times {@link Ray#SAME_EVENT}) that the cast rightly counts them as one.
     */
    private static Boolean exactHit(Ray ray, Polygon p) {
        int w = p.convexWinding(), n = p.size();
        BigDecimal dx = new BigDecimal(ray.dx()), dy = new BigDecimal(ray.dy());
        BigDecimal ox = new BigDecimal(ray.ox()), oy = new BigDecimal(ray.oy());
        BigDecimal[] in = null, out = null; // {num, den}, den > 0
        boolean inside = true;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            BigDecimal ax = new BigDecimal(p.x(i)), ay = new BigDecimal(p.y(i));
            BigDecimal ex = new BigDecimal(p.x(j)).subtract(ax), ey = new BigDecimal(p.y(j)).subtract(ay);
            BigDecimal den = dx.multiply(ey).subtract(dy.multiply(ex));
            BigDecimal num = ex.multiply(oy.subtract(ay)).subtract(ey.multiply(ox.subtract(ax)));
            inside &= w * num.signum() > 0;
            if (den.signum() == 0) {
                if (w * num.signum() <= 0) {
                    return false;
                }
                continue;
            }
            boolean goingIn = w * den.signum() < 0;
            if (den.signum() < 0) {
                den = den.negate();
                num = num.negate();
            }
            BigDecimal[] t = {num, den};
            if (goingIn && (in == null || less(in, t))) {
                in = t;
            } else if (!goingIn && (out == null || less(t, out))) {
                out = t;
            }
        }
        if (inside) {
            return true;
        }
        double reach = RayCast.limit(ray.dx(), ray.dy(), ray.maxDistance());
        MathContext mc = new MathContext(40);
        BigDecimal tin = in[0].divide(in[1], mc), tout = out[0].divide(out[1], mc);
        BigDecimal near = BigDecimal.valueOf(10 * Ray.SAME_EVENT).multiply(tout.abs().max(BigDecimal.ONE));
        if (tin.signum() < 0 || (reach != Slabs.INF && tin.compareTo(new BigDecimal(reach)) >= 0) || tout.compareTo(tin) <= 0) {
            return false;
        }
        return tout.subtract(tin).compareTo(near) > 0 ? Boolean.TRUE : null;
    }

    private static boolean less(BigDecimal[] a, BigDecimal[] b) {
        return a[0].multiply(b[1]).compareTo(b[0].multiply(a[1])) < 0;
    }

    @Test
    void halfPixelRaysGiveTheSameFloats() {
        agree(new SplittableRandom(12), true, 30_000);
    }

    @Test
    void floatRaysGiveTheSameHitToRounding() {
        agree(new SplittableRandom(1212), false, 30_000);
    }
}
