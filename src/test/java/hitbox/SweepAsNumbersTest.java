package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The world's mover asks every candidate's sweep as numbers ({@code Sweep.timeOfImpact} with
 * an {@code out} array), which makes no {@link Hit}: its answers must be the public sweep's,
 * for every pair of kinds, and the numbers form must leave the public one handing out real
 * hits afterwards, even when a bad argument made it throw.
 */
class SweepAsNumbersTest {

    @Test
    void theNumbersAreThePublicHitsFields_forEveryPairOfKinds() {
        Random rnd = new Random(2911);
        float[] out = new float[3];
        int hits = 0, overlapping = 0, misses = 0;
        for (int i = 0; i < 40_000; i++) {
            Shape mover = Sampled.any(rnd), obstacle = Sampled.any(rnd);
            float vx = (rnd.nextFloat() - 0.5f) * 160, vy = (rnd.nextFloat() - 0.5f) * 160;
            Hit h = Sweep.timeOfImpact(mover, vx, vy, obstacle);
            out[0] = out[1] = out[2] = Float.NaN;
            Side side = Sweep.timeOfImpact(mover, vx, vy, obstacle, out);
            String what = mover + " by (" + vx + ", " + vy + ") into " + obstacle;
            if (h == null) {
                assertNull(side, what);
                misses++;
                continue;
            }
            assertEquals(h.side(), side, what);
            assertEquals(h.t(), out[0], what);
            assertEquals(h.nx(), out[1], what);
            assertEquals(h.ny(), out[2], what);
            if (h.alreadyOverlapping()) {
                overlapping++;
            } else {
                hits++;
            }
        }
        // Every kind of answer was asked many times.
        assertEquals(true, hits > 5_000 && overlapping > 5_000 && misses > 5_000,
                hits + " hits, " + overlapping + " overlapping, " + misses + " misses");
    }

    @Test
    void afterANumbersSweepThrows_thePublicSweepStillHandsOutRealHits() {
        Rect box = new Rect(0, 0, 10, 10);
        assertThrows(IllegalArgumentException.class,
                () -> Sweep.timeOfImpact(box, Float.NaN, 0, new Rect(20, 0, 10, 10), new float[3]));
        Hit h = Sweep.timeOfImpact(box, 20, 0, new Rect(20, 0, 10, 10));
        assertNotNull(h);
        assertEquals(0.5f, h.t());
        assertEquals(1f, h.nx());
        assertEquals(Side.LEFT, h.side());
    }
}
