package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Geometry;

/**
 * Issue 23, item 4: {@link Sweep#turningTimeOfImpact(Polygon, float, float, float, float, float,
 * Polygon, float, float, float, float, float)}, two bodies that both move and turn, against
 * dense sampling in time with JTS: each body built here in double at 400 times (turned by
 * {@code t * turn} about its pivot, moved by {@code t * v}). The same promises as the standing
 * obstacle's ({@link TurningSweepSampledTest}): already overlapping exactly when they overlap
 * at 0; never through (no sample before the hit, or before 1 for a miss, overlaps); not
 * overlapping at the hit, and closer than the documented 1e-3 pixels there; the normal from a
 * into b; the same t with the roles swapped.
 */
class TurningSweepTwoMoversTest {

    private static final double TOUCH = TurningSweepSampledTest.TOUCH;
    private static final int SAMPLES = 400;

    /** A thin bar of length 2 half about (cx, cy), at an angle. */
    private static Polygon bar(double cx, double cy, double half, double thick, double angle) {
        double c = Math.cos(angle), s = Math.sin(angle);
        double[][] p = {{-half, -thick}, {half, -thick}, {half, thick}, {-half, thick}};
        float[] xy = new float[8];
        for (int k = 0; k < 4; k++) {
            xy[2 * k] = (float) (cx + c * p[k][0] - s * p[k][1]);
            xy[2 * k + 1] = (float) (cy + s * p[k][0] + c * p[k][1]);
        }
        return Polygon.of(xy);
    }

    /** A body at time t, shifted by (sx, sy), as JTS geometry: the sampled test's own. */
    private static Geometry at(Polygon body, double px, double py, double vx, double vy, double turn, double t,
                               double sx, double sy) {
        return TurningSweepSampledTest.moverAt(body, px, py, vx, vy, turn, t, sx, sy);
    }

    /** One body of the pair: the polygon, its pivot, its motion and its turn. */
    private record Body(Polygon p, float px, float py, float vx, float vy, float turn) {
        Geometry at(double t, double sx, double sy) {
            return TurningSweepTwoMoversTest.at(p, px, py, vx, vy, turn, t, sx, sy);
        }

        double speed() {
            double r = 0;
            float[] xy = p.coordinates();
            for (int i = 0; i < xy.length; i += 2) {
                r = Math.max(r, Math.hypot(xy[i] - px, xy[i + 1] - py));
            }
            return Math.hypot(vx, vy) + Math.abs(turn) * r;
        }
    }

    private static Hit sweep(Body a, Body b) {
        return Sweep.turningTimeOfImpact(a.p, a.px, a.py, a.vx, a.vy, a.turn, b.p, b.px, b.py, b.vx, b.vy, b.turn);
    }

    /** Checks one pair against the samples; true if it hit (not overlapping at the start). */
    private static boolean check(Body a, Body b, String name) {
        Hit hit = sweep(a, b);
        String what = name + ": " + a + " and " + b + ": " + hit;
        boolean atStart = a.at(0, 0, 0).relate(b.at(0, 0, 0), "T********");
        assertEquals(atStart, hit != null && hit.alreadyOverlapping(), what + ": overlapping at the start");
        if (atStart) {
            return false;
        }
        double end = hit == null ? 1 : hit.t();
        for (int k = 0; k <= SAMPLES && k < SAMPLES * end; k++) {
            double t = (double) k / SAMPLES;
            assertFalse(a.at(t, 0, 0).relate(b.at(t, 0, 0), "T********"), what + ": overlaps at " + t);
        }
        if (hit == null) {
            return false;
        }
        Geometry ga = a.at(hit.t(), 0, 0), gb = b.at(hit.t(), 0, 0);
        assertFalse(ga.relate(gb, "T********"), what + ": overlaps at the hit");
        double speed = a.speed() + b.speed();
        assertTrue(ga.distance(gb) <= TOUCH + 2 * Math.ulp(hit.t()) * speed, what + ": gap at the hit " + ga.distance(gb));
        double step = 0.05;
        double closer = a.at(hit.t(), step * hit.nx(), step * hit.ny()).distance(gb);
        double farther = a.at(hit.t(), -step * hit.nx(), -step * hit.ny()).distance(gb);
        assertTrue(closer < farther, what + ": the normal points away from b (" + closer + " vs " + farther + ")");
        // The other role: the same moment, to within the stopping rule's time, and the normal turned round.
        Hit back = sweep(b, a);
        assertNotNull(back, what + ": swapped, no hit");
        assertFalse(back.alreadyOverlapping(), what);
        assertEquals(hit.t(), back.t(), 2 * TOUCH / Math.max(speed, 1e-9) + 1e-6, what + ": swapped gives " + back);
        return true;
    }

    @Test
    void twoMovingTurningBodies_agreeWithDenseSampling() {
        SplittableRandom rnd = new SplittableRandom(2323);
        int hits = 0, cases = 400;
        for (int i = 0; i < cases; i++) {
            double ax = rnd.nextDouble() * 200, ay = rnd.nextDouble() * 200;
            double bx = rnd.nextDouble() * 200, by = rnd.nextDouble() * 200;
            Polygon pa = i % 5 == 0 ? bar(ax, ay, 10 + rnd.nextDouble() * 30, 0.5 + rnd.nextDouble(), rnd.nextDouble() * 3)
                    : TurningSweepSampledTest.regular(rnd, ax, ay, 3 + rnd.nextInt(6), 5 + rnd.nextDouble() * 25);
            Polygon pb = i % 7 == 0 ? Polygon.of((float) bx, (float) by, (float) bx + 30, (float) by, (float) bx + 30, (float) by + 30,
                    (float) bx + 15, (float) by + 10, (float) bx, (float) by + 30)
                    : TurningSweepSampledTest.regular(rnd, bx, by, 3 + rnd.nextInt(6), 5 + rnd.nextDouble() * 25);
            // Towards each other, each about half the way, with some scatter; turning or not.
            float vax = (float) (0.7 * (bx - ax) + rnd.nextDouble() * 40 - 20), vay = (float) (0.7 * (by - ay) + rnd.nextDouble() * 40 - 20);
            float vbx = (float) (0.7 * (ax - bx) + rnd.nextDouble() * 40 - 20), vby = (float) (0.7 * (ay - by) + rnd.nextDouble() * 40 - 20);
            float ta = i % 3 == 0 ? 0 : (float) (rnd.nextDouble() * 6 - 3), tb = i % 4 == 0 ? 0 : (float) (rnd.nextDouble() * 6 - 3);
            Body a = new Body(pa, (float) ax, (float) ay, vax, vay, ta);
            Body b = new Body(pb, (float) bx, (float) by, vbx, vby, tb);
            hits += check(a, b, "case " + i) ? 1 : 0;
        }
        assertTrue(hits > cases / 4, "hits " + hits);
    }

    @Test
    void fastRotationAgainstFastRotation_noTunnelling() {
        // dyn4j's case: two long thin bars, each spinning more than a turn a frame about its
        // own centre, the hubs close enough that the tips must meet; sampled at the frame's
        // ends only, they never overlap.
        Body a = new Body(bar(0, 0, 20, 0.5, 0), 0, 0, 0, 0, 7);
        Body b = new Body(bar(30, 0, 20, 0.5, Math.PI / 2), 30, 0, 0, 0, -5);
        assertFalse(a.at(0, 0, 0).relate(b.at(0, 0, 0), "T********"));
        assertFalse(a.at(1, 0, 0).relate(b.at(1, 0, 0), "T********"));
        assertTrue(check(a, b, "blades"), "the spinning blades meet");
        assertTrue(check(b, a, "blades, swapped"));
        Hit h = sweep(a, b);
        assertTrue(h.t() > 0.79 && h.t() < 0.794, "they meet near t = 0.793: " + h);
        // Moving past each other while spinning, in both roles.
        Body c = new Body(bar(-40, 5, 15, 0.25, 0.3), -40, 5, 80, 0, 9);
        Body d = new Body(bar(40, -5, 15, 0.25, 1.1), 40, -5, -80, 0, -11);
        assertTrue(check(c, d, "passing blades"));
        assertTrue(check(d, c, "passing blades, swapped"));
    }

    @Test
    void oneBodyAtRest_isTheStandingSweep() {
        SplittableRandom rnd = new SplittableRandom(77);
        for (int i = 0; i < 60; i++) {
            Polygon pa = TurningSweepSampledTest.regular(rnd, 0, 0, 3 + rnd.nextInt(5), 8);
            Polygon pb = TurningSweepSampledTest.regular(rnd, 40 + rnd.nextDouble() * 20, rnd.nextDouble() * 20 - 10, 3 + rnd.nextInt(5), 10);
            float vx = 60, vy = (float) (rnd.nextDouble() * 20 - 10), turn = (float) (rnd.nextDouble() * 4 - 2);
            Hit standing = Sweep.turningTimeOfImpact(pa, 0, 0, vx, vy, turn, pb);
            Hit both = Sweep.turningTimeOfImpact(pa, 0, 0, vx, vy, turn, pb, 50, 0, 0, 0, 0);
            assertEquals(standing == null, both == null, i + ": " + standing + " vs " + both);
            if (standing != null) {
                assertEquals(standing.t(), both.t(), 2 * TOUCH / (60 + 2 * 8 + 10) + 1e-6, i + ": " + standing + " vs " + both);
            }
        }
    }

    @Test
    void bothAtRest_apartIsNoHit_overlappingIsOverlapping() {
        Polygon a = Polygon.of(0, 0, 10, 0, 10, 10, 0, 10), b = Polygon.of(20, 0, 30, 0, 30, 10, 20, 10);
        assertNull(Sweep.turningTimeOfImpact(a, 5, 5, 0, 0, 0, b, 25, 5, 0, 0, 0));
        assertTrue(Sweep.turningTimeOfImpact(a, 5, 5, 0, 0, 0, a.translated(5, 0), 25, 5, 0, 0, 0).alreadyOverlapping());
        // Moving together along x, both the same way at the same speed: never closer.
        assertNull(Sweep.turningTimeOfImpact(a, 5, 5, 100, 0, 0, b, 25, 5, 100, 0, 0));
        // Closing in from both sides: they meet half way, at t = 0.5 (within the stopping rule).
        Hit h = Sweep.turningTimeOfImpact(a, 5, 5, 10, 0, 0, b, 25, 5, -10, 0, 0);
        assertEquals(0.5f, h.t(), 1e-4f);
        assertEquals(1f, h.nx(), 1e-6f);
    }

    @Test
    void badArguments_areRefused_concaveBodiesAreTheirPieces() {
        Polygon cup = Polygon.of(0, 0, 4, 0, 4, 8, 6, 8, 6, 0, 10, 0, 10, 12, 0, 12);
        Polygon box = Polygon.of(20, 0, 30, 0, 30, 10, 20, 10);
        assertThrows(IllegalArgumentException.class, () -> Sweep.turningTimeOfImpact(box, 0, 0, Float.NaN, 0, 0, cup, 0, 0, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> Sweep.turningTimeOfImpact(box, 0, 0, 0, 0, 0, null, 0, 0, 0, 0, 0));
        // A concave body is taken as its convex pieces, in either role: a box dropped into the
        // cup's notch (x in (4, 6)) falls past the rim to the notch's floor at y = 8.
        Polygon peg = Polygon.of(4.5f, -10, 5.5f, -10, 5.5f, -5, 4.5f, -5);
        Hit down = Sweep.turningTimeOfImpact(peg, 5, -7.5f, 0, 20, 0, cup, 5, 6, 0, 0, 0);
        assertEquals(0.65f, down.t(), 1e-4f, "from y = -5 to the floor at 8: 13 of 20");
        Hit up = Sweep.turningTimeOfImpact(cup, 5, 6, 0, -20, 0, peg, 5, -7.5f, 0, 0, 0);
        assertEquals(0.65f, up.t(), 1e-4f);
        assertEquals(-1f, up.ny(), 1e-6f);
    }
}
