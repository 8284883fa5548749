package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The reworked turning sweep (exact gaps for polygon pieces, the step bound along the gap's
 * normal) against the old code ({@link TurningSweepOld}) on random convex polygons, rectangles,
 * segments and concave polygons, turning or not: the same hit or miss, the same time to a
 * thousandth of the motion, and never a hit time at which the mover already overlaps, nor a
 * miss that passes through the obstacle (checked at 400 times along the motion).
 */
class TurningSweepAgreementTest {

    private static Polygon regular(SplittableRandom rnd, double cx, double cy, int n, double r) {
        float[] xy = new float[2 * n];
        double start = rnd.nextDouble() * Math.PI;
        for (int k = 0; k < n; k++) {
            xy[2 * k] = (float) (cx + r * Math.cos(start + 2 * Math.PI * k / n));
            xy[2 * k + 1] = (float) (cy + r * Math.sin(start + 2 * Math.PI * k / n));
        }
        return Polygon.of(xy);
    }

    @Test
    void agreesWithTheOldCode() {
        SplittableRandom rnd = new SplittableRandom(1212);
        int hits = 0, differ = 0, cases = 600;
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
            Hit now = TurningSweep.timeOfImpact(mover, px, py, vx, vy, turn, obstacle);
            Hit old = TurningSweepOld.timeOfImpact(mover, px, py, vx, vy, turn, obstacle);
            String what = "case " + i + ": " + mover + " " + vx + ", " + vy + ", turn " + turn + " into " + obstacle;
            if (now == SweptPairs.OVERLAPPING || old == SweptPairs.OVERLAPPING) {
                assertTrue(now == old, what);
                continue;
            }
            if ((now == null) != (old == null)) {
                differ++;
            } else if (now != null) {
                hits++;
                double speed = Math.hypot(vx, vy) + Math.abs(turn) * 60;
                assertEquals(old.t(), now.t(), 2e-3 + 0.01 / speed, what);
            }
            // Never through the obstacle before the answer's time.
            float end = now == null ? 1 : now.t();
            for (int k = 0; k <= 400; k++) {
                float t = end * k / 400;
                assertFalse(Overlaps.test(Sweep.turnedAt(mover, px, py, vx, vy, turn, t), obstacle), what + " overlaps at " + t);
            }
        }
        assertTrue(hits > cases / 4, "hits " + hits);
        assertTrue(differ <= cases / 100, "hit or miss differs in " + differ);
    }
}
