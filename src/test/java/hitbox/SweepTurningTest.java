package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * {@link Sweep#turningTimeOfImpact}: a thin spinning blade that the straight sweep misses, and
 * the "never tunnels" property against every kind of obstacle, checked by stepping the
 * turning mover through the frame in steps shorter than the thinnest thing it could cross.
 */
class SweepTurningTest {

    @Test
    void spinningBlade_hitsWhatItsTipSweeps_whereTheStraightSweepMisses() {
        Polygon blade = Polygon.of(Rect.centered(200, 200, 160, 4)).rotated(0, 200, 200);
        Rect post = new Rect(241, 241, 2, 2); // at 45 degrees, 58 px from the hub
        float turn = (float) (Math.PI / 2);
        assertFalse(blade.overlaps(post), "clear at the start");
        assertFalse(turnedAt(blade, 200, 200, 0, 0, turn, 1).overlaps(post), "clear at the end");
        assertNull(Sweep.timeOfImpact(blade.bounds(), 0, 0, post), "the straight sweep sees nothing");
        Hit hit = Sweep.turningTimeOfImpact(blade, 200, 200, 0, 0, turn, post);
        assertNotNull(hit, "the turning sweep hits the post");
        assertTrue(hit.t() > 0.4 && hit.t() < 0.5, "t " + hit.t());
        assertFalse(turnedAt(blade, 200, 200, 0, 0, turn, hit.t()).overlaps(post), "clear at the hit");
        assertTrue(turnedAt(blade, 200, 200, 0, 0, turn, hit.t() + 0.01f).overlaps(post), "into it just after");
        // Turning clockwise on screen, the blade's lower-right half meets the post: the normal points into the post, down-left of it.
        assertTrue(hit.nx() * -1 + hit.ny() * 1 > 0, "normal " + hit);
    }

    @Test
    void thinWall_atTheTip_againstEveryShapeKind() {
        Polygon blade = Polygon.of(Rect.centered(100, 100, 120, 2)).rotated(0, 100, 100);
        float turn = (float) Math.PI;
        Shape[] walls = {new Segment(100, 150, 100, 170), new Rect(99.5f, 150, 1, 20), new Circle(100, 155, 0.5f),
                new Ellipse(100, 155, 0.5f, 3), new Capsule(100, 150, 100, 158, 0.5f), Polygon.of(99.5f, 150, 100.5f, 150, 100, 170)};
        for (Shape wall : walls) {
            Hit hit = Sweep.turningTimeOfImpact(blade, 100, 100, 0, 0, turn, wall);
            assertNotNull(hit, "hits " + wall);
            assertEquals(0.5, hit.t(), 0.03, "t for " + wall);
            assertFalse(turnedAt(blade, 100, 100, 0, 0, turn, hit.t()).overlaps(wall), "clear at the hit: " + wall);
        }
    }

    @Test
    void touchingAndTurningAway_isNoHit_turningBackIsOne() {
        Polygon blade = Polygon.of(Rect.centered(200, 200, 160, 4)).rotated(0, 200, 200);
        Rect post = new Rect(241, 241, 2, 2);
        float turn = (float) (Math.PI / 2);
        Hit hit = Sweep.turningTimeOfImpact(blade, 200, 200, 0, 0, turn, post);
        Polygon touching = turnedAt(blade, 200, 200, 0, 0, turn, hit.t());
        assertNull(Sweep.turningTimeOfImpact(touching, 200, 200, 0, 0, -turn, post), "turning away");
        Hit again = Sweep.turningTimeOfImpact(touching, 200, 200, 0, 0, turn, post);
        assertNotNull(again, "turning on into it");
        assertEquals(0, again.t(), 0.01);
    }

    @Test
    void startsOverlapping_andBadArguments() {
        Polygon blade = Polygon.of(Rect.centered(100, 100, 120, 2)).rotated(0, 100, 100);
        assertTrue(Sweep.turningTimeOfImpact(blade, 100, 100, 0, 0, 1, new Circle(100, 100, 3)).alreadyOverlapping());
        assertThrows(IllegalArgumentException.class, () -> Sweep.turningTimeOfImpact(blade, 100, 100, 0, 0, Float.NaN, new Circle(0, 0, 1)));
        assertThrows(IllegalArgumentException.class, () -> Sweep.turningTimeOfImpact(
                Polygon.of(0, 0, 10, 0, 5, 2, 10, 10, 0, 10), 0, 0, 0, 0, 1, new Circle(50, 50, 1)));
        assertNull(Sweep.turningTimeOfImpact(blade, 100, 100, 0, 0, 0, new Circle(300, 300, 3)), "standing still");
    }

    /** Random turning movers against random obstacles: never past the first overlap found by fine stepping, never overlapping at the hit. */
    @Test
    void neverTunnels() {
        Random rnd = new Random(2026);
        int hits = 0;
        for (int i = 0; i < 300; i++) {
            float cx = Sampled.coord(rnd), cy = Sampled.coord(rnd);
            Polygon mover = rnd.nextBoolean()
                    ? Polygon.of(Rect.centered(cx, cy, 10 + rnd.nextInt(60), 1 + rnd.nextInt(4))).rotated(rnd.nextFloat() * 3, cx, cy)
                    : Polygon.of(cx, cy, cx + 20 + rnd.nextInt(20), cy + rnd.nextInt(8), cx + rnd.nextInt(8), cy + 15 + rnd.nextInt(20));
            Vec c = mover.centroid();
            float vx = rnd.nextInt(120) - 60, vy = rnd.nextInt(120) - 60, turn = (rnd.nextFloat() - 0.5f) * 12;
            Shape obstacle = Sampled.any(rnd);
            if (mover.overlaps(obstacle)) {
                continue;
            }
            Hit hit = Sweep.turningTimeOfImpact(mover, c.x(), c.y(), vx, vy, turn, obstacle);
            double first = firstOverlap(mover, c.x(), c.y(), vx, vy, turn, obstacle);
            if (first <= 1) {
                assertNotNull(hit, "tunnelled: " + mover + " v " + vx + "," + vy + " turn " + turn + " into " + obstacle + " at " + first);
                assertTrue(hit.t() <= first, "hit at " + hit.t() + " after the overlap at " + first);
            }
            if (hit != null) {
                hits++;
                assertFalse(turnedAt(mover, c.x(), c.y(), vx, vy, turn, hit.t()).overlaps(obstacle), "overlapping at the hit");
            }
        }
        assertTrue(hits > 30, hits + " hits");
    }

    private static double firstOverlap(Polygon mover, float px, float py, float vx, float vy, float turn, Shape obstacle) {
        double reach = 0;
        for (int i = 0; i < mover.size(); i++) {
            reach = Math.max(reach, Math.hypot(mover.x(i) - px, mover.y(i) - py));
        }
        double speed = Math.hypot(vx, vy) + Math.abs(turn) * reach;
        int steps = (int) Math.min(20000, Math.ceil(speed / 0.05) + 1);
        for (int k = 0; k <= steps; k++) {
            float t = (float) k / steps;
            if (turnedAt(mover, px, py, vx, vy, turn, t).overlaps(obstacle)) {
                return t;
            }
        }
        return 2;
    }

    /**
     * The turning mover at time t, as the sweep's contract places it: each vertex turned by
     * {@code t * turn} about the pivot and moved by {@code t * (vx, vy)}, in double precision,
     * then rounded to floats (the test's own placement, not the library's).
     */
    private static Polygon turnedAt(Polygon mover, float px, float py, float vx, float vy, float turn, float t) {
        double c = StrictMath.cos((double) t * turn), s = StrictMath.sin((double) t * turn);
        float[] xy = new float[2 * mover.size()];
        for (int i = 0; i < mover.size(); i++) {
            double x = mover.x(i) - px, y = mover.y(i) - py;
            xy[2 * i] = (float) (px + (double) t * vx + c * x - s * y);
            xy[2 * i + 1] = (float) (py + (double) t * vy + s * x + c * y);
        }
        return Polygon.of(xy);
    }
}
