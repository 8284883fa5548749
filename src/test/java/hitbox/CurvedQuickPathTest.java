package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The cheap first answers of the curved pairs (the discs and closest-point rounds in front of
 * {@link Collide#ellipseCapsule}) never disagree with the long way they stand in front of:
 * random, whole and half-pixel (touching-heavy) and far-apart cases.
 */
class CurvedQuickPathTest {

    private static float pick(SplittableRandom rnd, int kind, float lo, float hi) {
        float v = lo + (float) rnd.nextDouble() * (hi - lo);
        return kind == 0 ? v : kind == 1 ? Math.round(v) : Math.round(2 * v) / 2f;
    }

    @Test
    void ellipseCapsuleQuickAgreesWithTheLongWay() {
        SplittableRandom rnd = new SplittableRandom(12);
        int decided = 0;
        for (int i = 0; i < 200_000; i++) {
            int kind = i % 3;
            float span = i % 7 == 0 ? 1e5f : 12;
            float x = pick(rnd, kind, -span, span), y = pick(rnd, kind, -span, span);
            float a = pick(rnd, kind, 0.5f, 6), b = pick(rnd, kind, 0.5f, 6);
            float x1 = pick(rnd, kind, -12, 12), y1 = pick(rnd, kind, -12, 12);
            float x2 = pick(rnd, kind, -12, 12), y2 = pick(rnd, kind, -12, 12);
            float r = pick(rnd, kind, 0.5f, 4);
            if (i % 5 == 0) { // the capsule near the ellipse, as after a broad phase
                x1 += x;
                y1 += y;
                x2 += x;
                y2 += y;
            }
            if (!(a > 0 && b > 0 && r > 0)) {
                continue;
            }
            boolean slow = Ellipses.segmentWithin(x, y, a, b, x1, y1, x2, y2, r);
            int quick = Ellipses.capsuleQuick(a, b, (double) x1 - x, (double) y1 - y, (double) x2 - x, (double) y2 - y, r);
            if (quick != 0) {
                decided++;
                String what = "case " + i + ": " + x + ", " + y + ", " + a + ", " + b + " / "
                        + x1 + ", " + y1 + ", " + x2 + ", " + y2 + ", " + r;
                assertEquals(slow, quick > 0, what);
            }
            assertEquals(slow, Collide.ellipseCapsule(x, y, a, b, x1, y1, x2, y2, r));
        }
        // The point of the quick path: it decides most cases.
        org.junit.jupiter.api.Assertions.assertTrue(decided > 150_000, "decided " + decided);
    }
}
