package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The face-query SAT contact ({@link SeparatingAxis}: b pushed out through a's faces and back
 * through its own, the edge loop on cached corners) against the old search over both ways along
 * every axis ({@link SeparatingAxisOld}), through {@link Contact#between} as a sketch calls it.
 * On half-pixel corners, where every product is exact, the answers must be the same floats,
 * touching and tie rule included; on random float corners the same hit or miss and the same
 * contact to a float's rounding.
 */
class SeparatingAxisAgreementTest {

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

    private static Contact old(Shape a, Shape b) {
        return SeparatingAxisOld.contact(Polygons.corners(a), Polygons.corners(b));
    }

    private static void agree(SplittableRandom rnd, boolean half, int cases) {
        int hits = 0;
        for (int i = 0; i < cases; i++) {
            Shape a = ring(rnd, half);
            Shape b = i % 3 == 2 ? rect(rnd, half) : ring(rnd, half);
            if (i % 6 == 5) {
                Shape t = a;
                a = b;
                b = t;
            }
            Contact now = Contact.between(a, b), was = old(a, b);
            String what = "case " + i + ": " + a + " and " + b + ": " + now + " was " + was;
            assertEquals(was == null, now == null, what);
            if (now == null) {
                continue;
            }
            hits++;
            if (half) {
                assertEquals(was, now, what);
            } else {
                assertEquals(was.nx(), now.nx(), 2e-7, what);
                assertEquals(was.ny(), now.ny(), 2e-7, what);
                assertEquals(was.depth(), now.depth(), 1e-6 * (1 + was.depth()), what);
            }
        }
        assertTrue(hits > cases / 5, "hits " + hits);
    }

    @Test
    void halfPixelCornersGiveTheSameFloats() {
        agree(new SplittableRandom(12), true, 20_000);
    }

    @Test
    void floatCornersGiveTheSameContactToRounding() {
        agree(new SplittableRandom(1212), false, 20_000);
    }

    @Test
    void parallelFacesAndSharedCentresKeepTheTieRule() {
        // Squares and octagons about the same centre or on a grid: every push ties with others.
        for (int k = 0; k < 400; k++) {
            float c = 50 + k % 7, d = 50 + k / 7 % 5;
            Shape a = k % 2 == 0 ? Polygon.regular(c, d, 10 + k % 3, 4, (float) (Math.PI / 4))
                    : Polygon.regular(c, d, 10 + k % 3, 8);
            Shape b = k % 3 == 0 ? new Rect(48, 48, 8 + k % 4, 8) : Polygon.regular(50, 50, 12, k % 2 == 0 ? 8 : 4);
            Contact now = Contact.between(a, b), was = old(a, b);
            assertEquals(was, now, "case " + k + ": " + a + " and " + b);
        }
    }
}
