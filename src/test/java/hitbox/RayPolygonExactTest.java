package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import hitbox.ExactReference.Q;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * {@link Ray#cast} at random polygons, convex and concave, against the exact answer
 * ({@link ExactReference#rayInside}: the ray cut at every point where it meets the outline, the
 * winding number asked between cuts, all in rationals on the given floats). Rays start
 * anywhere: inside, on a vertex or an edge, on an edge's line outside; they aim through corners,
 * along edges or anywhere, with and without an end.
 *
 * <p>What the {@link Ray} and {@link RayHit} javadoc promises, checked case by case:
 * <ul>
 *   <li>a hit exactly when the ray goes into the open polygon before its end (running along an
 *       edge or touching a corner is no hit), at the first place it goes in; a start inside is
 *       a hit at distance 0;</li>
 *   <li>the distance and the point to a float's rounding (two units in the last place);</li>
 *   <li>the normal from the ray into the shape: the inward normal of the edge hit, of both
 *       edges summed at a corner, and along the ray for a start inside.</li>
 * </ul>
 * Hit or miss must be the exact answer on these float cases too, not only on whole numbers,
 * where the javadoc promises it: a ray that grazes a corner or runs a hair inside an edge
 * included (seeded cases, so a change that loses that shows here).
 */
class RayPolygonExactTest {

    /** A ray's start: on a vertex, an edge's middle, an edge's line outside, the centre, or anywhere. */
    private static float[] start(SplittableRandom rnd, Polygon p, double cx, double cy, boolean half) {
        int i = rnd.nextInt(p.size()), j = (i + 1) % p.size();
        double t = switch (rnd.nextInt(5)) {
            case 0 -> 0;
            case 1 -> 0.5;
            case 2 -> -1 - rnd.nextInt(3);
            case 3 -> Double.POSITIVE_INFINITY;
            default -> Double.NaN;
        };
        double x, y;
        if (Double.isNaN(t)) {
            x = rnd.nextInt(400) / 2.0;
            y = rnd.nextInt(400) / 2.0;
        } else if (Double.isInfinite(t)) {
            x = cx;
            y = cy;
        } else {
            x = p.x(i) + t * (p.x(j) - p.x(i));
            y = p.y(i) + t * (p.y(j) - p.y(i));
        }
        return new float[] {half ? Math.round(2 * x) / 2f : (float) x, half ? Math.round(2 * y) / 2f : (float) y};
    }

    /** Within two float steps of the exact value (at least those of 1). */
    private static void near(double exact, float got, String what) {
        assertEquals(exact, got, 2 * Math.ulp((float) Math.max(1, Math.abs(exact))), what);
    }

    private static void check(SplittableRandom rnd, boolean half, boolean convex, int cases) {
        int hits = 0, inside = 0, corners = 0;
        for (int c = 0; c < cases; c++) {
            double cx = 50 + rnd.nextInt(100) / 2.0, cy = 50 + rnd.nextInt(100) / 2.0;
            int sides = 3 + rnd.nextInt(8);
            Polygon p = convex ? TestShapes.convexRing(rnd, sides, cx, cy, half) : TestShapes.starRing(rnd, sides + 1, cx, cy, half);
            float[] o = start(rnd, p, cx, cy, half);
            int v = rnd.nextInt(p.size());
            float tx = rnd.nextBoolean() ? p.x(v) : (float) (50 + rnd.nextInt(100));
            float ty = rnd.nextBoolean() ? p.y(v) : (float) (50 + rnd.nextInt(100));
            float dx = tx - o[0], dy = ty - o[1];
            if (dx == 0 && dy == 0) {
                continue;
            }
            boolean ends = rnd.nextBoolean();
            Ray ray = ends ? Ray.between(o[0], o[1], tx, ty) : new Ray(o[0], o[1], dx, dy);
            RayHit hit = ray.cast(p);
            String what = "case " + c + ": " + ray + " at " + p + ": " + hit;
            // Ray.between ends exactly at (ox + dx, oy + dy): at s = 1.
            List<Q[]> stretches = ExactReference.rayInside(p.coordinates(), o[0], o[1], dx, dy, ends ? Q.ONE : null);
            // The hit is the way into the first stretch inside, exactly; a miss, none.
            if (hit == null || stretches.isEmpty()) {
                assertEquals(stretches.isEmpty(), hit == null, () -> what + (hit == null ? ": misses, but goes in at "
                        + stretches.get(0)[0].toDouble() + " of the direction" : ": hits, but never goes in"));
                continue;
            }
            double length = Math.hypot(dx, dy);
            Q in = stretches.get(0)[0];
            double s = in.toDouble();
            near(s * length, hit.distance(), what + ": distance");
            assertEquals(0, Float.floatToIntBits(hit.distance()) >>> 31, what + ": a distance of -0");
            near(o[0] + s * dx, hit.x(), what + ": x");
            near(o[1] + s * dy, hit.y(), what + ": y");
            // The normal: minus the sum of the facing edges' unit outward normals, else along the ray.
            List<Q[]> facing = ExactReference.facingNormalsAt(p.coordinates(), o[0], o[1], dx, dy, in);
            double nx = 0, ny = 0;
            for (Q[] f : facing) {
                double fx = f[0].toDouble(), fy = f[1].toDouble(), len = Math.hypot(fx, fy);
                nx -= fx / len;
                ny -= fy / len;
            }
            if (facing.isEmpty()) {
                nx = dx;
                ny = dy;
            }
            double len = Math.hypot(nx, ny);
            assertEquals(nx / len, hit.nx(), 1e-6, what + ": normal x");
            assertEquals(ny / len, hit.ny(), 1e-6, what + ": normal y");
            hits++;
            inside += s == 0 ? 1 : 0;
            corners += facing.size() == 2 ? 1 : 0;
        }
        String counts = "hits " + hits + ", from inside or the outline " + inside + ", at corners " + corners;
        assertTrue(hits > cases / 5, counts);
        assertTrue(inside > cases / 100, counts);
        assertTrue(corners > cases / 100, counts);
    }

    @Test
    void convexHalfPixel() {
        check(new SplittableRandom(12), true, true, 20_000);
    }

    @Test
    void convexFloat() {
        check(new SplittableRandom(1212), false, true, 20_000);
    }

    @Test
    void concaveHalfPixel() {
        check(new SplittableRandom(13), true, false, 10_000);
    }

    @Test
    void concaveFloat() {
        check(new SplittableRandom(1313), false, false, 10_000);
    }
}
