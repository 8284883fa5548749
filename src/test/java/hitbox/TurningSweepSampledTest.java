package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;

/**
 * {@link Sweep#turningTimeOfImpact} against dense sampling in time: the turned mover built
 * here in double (turned by {@code t * turn} about the pivot, moved by {@code t * (vx, vy)}, as
 * the javadoc says), compared with the obstacle by JTS at 400 times along the motion. Random
 * convex polygons, turning or not, into convex polygons, rectangles, segments and a concave
 * polygon. What the javadoc promises:
 * <ul>
 *   <li>already overlapping exactly when the mover overlaps the obstacle at t = 0;</li>
 *   <li>never late, never through: no sample before the hit's t (or before 1, for a miss)
 *       overlaps the obstacle, and at t the mover does not overlap it;</li>
 *   <li>never early: at t the gap is below the documented {@value #TOUCH} pixels (with a
 *       float's rounding of the mover's place);</li>
 *   <li>the normal points from the mover into the obstacle: a small step along it closes the
 *       gap, one against it opens it.</li>
 * </ul>
 */
class TurningSweepSampledTest {

    /** The documented gap below which a closing mover counts as hitting. */
    static final double TOUCH = 1e-3;
    private static final int SAMPLES = 400;
    private static final GeometryFactory GF = new GeometryFactory();

    /** A regular n-gon of radius r about (cx, cy), turned at random. */
    static Polygon regular(SplittableRandom rnd, double cx, double cy, int n, double r) {
        float[] xy = new float[2 * n];
        double start = rnd.nextDouble() * Math.PI;
        for (int k = 0; k < n; k++) {
            xy[2 * k] = (float) (cx + r * Math.cos(start + 2 * Math.PI * k / n));
            xy[2 * k + 1] = (float) (cy + r * Math.sin(start + 2 * Math.PI * k / n));
        }
        return Polygon.of(xy);
    }

    /** A closed ring (or a line for two points) through the coordinates. */
    private static Geometry jts(double[] xy) {
        int n = xy.length / 2;
        Coordinate[] c = new Coordinate[n == 2 ? 2 : n + 1];
        for (int i = 0; i < c.length; i++) {
            c[i] = new Coordinate(xy[2 * (i % n)], xy[2 * (i % n) + 1]);
        }
        return n == 2 ? GF.createLineString(c) : GF.createPolygon(c);
    }

    private static Geometry jts(Shape s) {
        float[] xy = s instanceof Rect r ? ExactReference.rectPolygon(r.x(), r.y(), r.w(), r.h())
                : s instanceof Segment g ? new float[] {g.x1(), g.y1(), g.x2(), g.y2()} : ((Polygon) s).coordinates();
        double[] d = new double[xy.length];
        for (int i = 0; i < xy.length; i++) {
            d[i] = xy[i];
        }
        return jts(d);
    }

    /** The mover at time t, shifted by (sx, sy): turned by t turn about the pivot, moved by t v. */
    static Geometry moverAt(Polygon mover, double px, double py, double vx, double vy, double turn, double t,
                                    double sx, double sy) {
        float[] xy = mover.coordinates();
        double c = Math.cos(t * turn), s = Math.sin(t * turn);
        double[] out = new double[xy.length];
        for (int i = 0; i < xy.length; i += 2) {
            double x = xy[i] - px, y = xy[i + 1] - py;
            out[i] = px + t * vx + c * x - s * y + sx;
            out[i + 1] = py + t * vy + s * x + c * y + sy;
        }
        return jts(out);
    }

    /** The open mover meets the obstacle: the insides overlap, or the closed segment reaches into it. */
    private static boolean overlap(Geometry mover, Geometry obstacle) {
        return obstacle.getDimension() == 1 ? obstacle.relate(mover, "T********") || obstacle.relate(mover, "***T*****")
                : mover.relate(obstacle, "T********");
    }

    @Test
    void agreesWithDenseSampling() {
        SplittableRandom rnd = new SplittableRandom(1212);
        int hits = 0, turning = 0, overlapping = 0, cases = 600;
        for (int i = 0; i < cases; i++) {
            double x = rnd.nextDouble() * 200, y = rnd.nextDouble() * 200;
            Polygon mover = regular(rnd, x, y, 3 + rnd.nextInt(6), 5 + rnd.nextDouble() * 25);
            double ox = rnd.nextDouble() * 200, oy = rnd.nextDouble() * 200;
            Shape obstacle = switch (i % 4) {
                case 0 -> regular(rnd, ox, oy, 3 + rnd.nextInt(6), 5 + rnd.nextDouble() * 25);
                case 1 -> new Rect((float) ox, (float) oy, 1 + (float) rnd.nextDouble() * 30, 1 + (float) rnd.nextDouble() * 30);
                case 2 -> new Segment((float) ox, (float) oy, (float) (ox + rnd.nextDouble() * 40 - 20), (float) (oy + rnd.nextDouble() * 40 - 20));
                default -> Polygon.of((float) ox, (float) oy, (float) ox + 30, (float) oy, (float) ox + 30, (float) oy + 30,
                        (float) ox + 15, (float) oy + 10, (float) ox, (float) oy + 30);
            };
            float vx = (float) (1.4 * (ox - x) + rnd.nextDouble() * 60 - 30), vy = (float) (1.4 * (oy - y) + rnd.nextDouble() * 60 - 30);
            float turn = i % 3 == 0 ? 0 : (float) (rnd.nextDouble() * 4 - 2);
            float px = (float) x, py = (float) y;
            Hit hit = Sweep.turningTimeOfImpact(mover, px, py, vx, vy, turn, obstacle);
            String what = "case " + i + ": " + mover + " " + vx + ", " + vy + ", turn " + turn + " into " + obstacle + ": " + hit;
            Geometry wall = jts(obstacle);
            boolean atStart = overlap(moverAt(mover, px, py, vx, vy, turn, 0, 0, 0), wall);
            assertEquals(atStart, hit != null && hit.alreadyOverlapping(), what + ": overlapping at the start");
            if (atStart) {
                overlapping++;
                continue;
            }
            double end = hit == null ? 1 : hit.t();
            for (int k = 0; k <= SAMPLES && k < SAMPLES * end; k++) {
                double t = (double) k / SAMPLES;
                assertFalse(overlap(moverAt(mover, px, py, vx, vy, turn, t, 0, 0), wall), what + ": overlaps at " + t);
            }
            if (hit == null) {
                continue;
            }
            hits++;
            turning += turn != 0 ? 1 : 0;
            Geometry at = moverAt(mover, px, py, vx, vy, turn, hit.t(), 0, 0);
            assertFalse(overlap(at, wall), what + ": overlaps at the hit");
            // The float t rounds the mover's place by up to a float step times its fastest point's speed.
            double speed = Math.hypot(vx, vy) + Math.abs(turn) * 60;
            assertTrue(at.distance(wall) <= TOUCH + 2 * Math.ulp(hit.t()) * speed, what + ": gap at the hit " + at.distance(wall));
            double step = 0.05;
            double closer = moverAt(mover, px, py, vx, vy, turn, hit.t(), step * hit.nx(), step * hit.ny()).distance(wall);
            double farther = moverAt(mover, px, py, vx, vy, turn, hit.t(), -step * hit.nx(), -step * hit.ny()).distance(wall);
            assertTrue(closer < farther, what + ": the normal points away from the obstacle (" + closer + " vs " + farther + ")");
        }
        String counts = "hits " + hits + ", turning " + turning + ", overlapping at the start " + overlapping;
        assertTrue(hits > cases / 4, counts);
        assertTrue(turning > cases / 8, counts);
    }
}
