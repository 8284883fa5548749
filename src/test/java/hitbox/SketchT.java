package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The oracle for a sweep's {@code t}, independent of how Sweep computes it: the mover, moved
 * the way a sketch moves it ({@code x + t * vx} in float), does not overlap the obstacle at
 * {@code t} (by {@link Collide}), does at the next float up, and {@code t} lies within the
 * float positions' rounding of the exact time of impact.
 */
final class SketchT {
    private SketchT() {
    }

    /** Does the mover, moved by t in float as a sketch moves it, overlap the obstacle? */
    interface At {
        boolean overlaps(float t);
    }

    /**
     * @param exact   the exact time of impact: +infinity for no hit, 0 for already
     *                overlapping or touching and moving in
     * @param got     the sweep's answer
     * @param plateau how far t may lie from the exact time because float positions stand
     *                still over a range of t (see {@link #plateau})
     */
    static void check(double exact, float got, At at, double plateau, String what) {
        if (exact == Double.POSITIVE_INFINITY) {
            assertEquals(Float.POSITIVE_INFINITY, got, what + ": no hit");
            return;
        }
        if (at.overlaps(0)) {
            assertEquals(0f, got, what + ": already overlapping");
            return;
        }
        assertTrue(got >= 0 && got <= 1, what + ": t = " + got);
        assertFalse(at.overlaps(got), what + ": the mover at t = " + got + " overlaps");
        if (got == 1 && exact < 1 - plateau - 1e-6) {
            // A graze, which Sweep documents: the exact paths overlap for less time than the
            // float positions stand still, so no float position overlaps and t is 1. Seen with
            // coordinates near 1e6 (a float step of 1/16 px). Checked, not taken on trust:
            // every float t within the rounding of the exact entry is clear.
            float from = (float) Math.max(0, exact - plateau), to = (float) Math.min(1, exact + plateau);
            for (float s = from; s <= to; s = Math.nextUp(s)) {
                assertFalse(at.overlaps(s), what + ": t = 1 (a graze), but the mover at t = " + s + " overlaps");
            }
            return;
        }
        if (got == 0 && exact == 0) {
            // Touching at the start and moving in: t = 0 exactly (Hit's promise), though the
            // float position may stand still for a hair above 0.
            return;
        }
        if (got < 1) {
            assertTrue(at.overlaps(Math.nextUp(got)), what + ": the next float after t = " + got + " is still clear");
        }
        assertEquals(exact, got, plateau + 1e-6, what + ": t far from the exact time " + exact);
    }

    /**
     * Two float steps of the largest coordinate, in units of the slower moving axis's motion:
     * how long a float position can stand still while t grows.
     */
    static double plateau(float vx, float vy, float... coords) {
        double p = 0;
        for (float v : new float[] {vx, vy}) {
            if (v != 0) {
                p = Math.max(p, plateauAlong(Math.abs(v), coords));
            }
        }
        return p;
    }

    /**
     * Two float steps of the largest coordinate over a speed (the motion's part along the
     * direction that decides the hit): how long t can grow while the rounded positions do
     * not move along it. Infinite for a speed of 0.
     */
    static double plateauAlong(double speed, float... coords) {
        float m = 0;
        for (float c : coords) {
            m = Math.max(m, Math.abs(c));
        }
        return 2 * Math.ulp(m) / speed;
    }
}
