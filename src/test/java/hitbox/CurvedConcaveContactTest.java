package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Contacts between a curved shape (an ellipse, aligned or turned, or a capsule) and a
 * concave polygon, in both orders, against a brute-force oracle that shares only the
 * overlap test: for 720 directions, the shortest push of the curved shape along it that
 * clears the polygon, found by stepping out and bisecting on {@link Shape#overlaps} of the
 * moved shapes. The contact's push must clear, and must be no longer than the oracle's best
 * (to 1e-3 of a pixel), and no shorter than it by more than the oracle's sampling can miss.
 */
class CurvedConcaveContactTest {

    private static final int DIRECTIONS = 720;

    /** The arrow head and a U with a narrow slot: concave polygons where the nearest piece's push is wrong. */
    private static Polygon concave(Random rnd) {
        float x = Sampled.coord(rnd), y = Sampled.coord(rnd);
        if (rnd.nextBoolean()) {
            return Polygon.of(x, y, x + 40, y + 10, x + 15, y + 15, x + 10, y + 40);
        }
        float gap = 3 + rnd.nextInt(12);
        return Polygon.of(x, y, x + 20, y, x + 20, y + 30, x + 20 + gap, y + 30, x + 20 + gap, y,
                x + 40 + gap, y, x + 40 + gap, y + 45, x, y + 45);
    }

    private static Shape curved(Random rnd) {
        return switch (rnd.nextInt(3)) {
            case 0 -> Sampled.ellipse(rnd);
            case 1 -> Sampled.turnedEllipse(rnd);
            default -> Sampled.capsule(rnd);
        };
    }

    /** The shortest push of k along (nx, ny) that clears p, by stepping then bisecting. */
    private static double bruteForcePush(Shape k, Polygon p, double nx, double ny) {
        double step = 0.25, d = 0;
        while (k.translated((float) (nx * d), (float) (ny * d)).overlaps(p)) {
            d += step;
        }
        double lo = Math.max(0, d - step), hi = d;
        if (d == 0) {
            return 0;
        }
        for (int i = 0; i < 40; i++) {
            double m = (lo + hi) / 2;
            if (k.translated((float) (nx * m), (float) (ny * m)).overlaps(p)) {
                lo = m;
            } else {
                hi = m;
            }
        }
        return hi;
    }

    @Test
    void contacts_clearAndAreShortest_bothOrders() {
        Random rnd = new Random(140);
        int checked = 0, notNearest = 0;
        for (int i = 0; i < 400 && checked < 60; i++) {
            Shape k = curved(rnd);
            Polygon p = concave(rnd);
            Contact c = k.contact(p);
            Contact back = p.contact(k);
            assertEquals(k.overlaps(p), c != null, k + " " + p);
            if (c == null) {
                assertNull(back);
                continue;
            }
            checked++;
            assertNotNull(back);
            // From k to p: moving k by -normal * depth (a hair more) clears the polygon.
            double push = c.depth() + 1e-3;
            assertFalse(k.translated((float) (-c.nx() * push), (float) (-c.ny() * push)).overlaps(p), "does not clear: " + k + " " + p + " " + c);
            assertEquals(c.depth(), back.depth(), 1e-3, k + " " + p);
            assertFalse(k.translated((float) (back.nx() * push), (float) (back.ny() * push)).overlaps(p), "reversed does not clear: " + k + " " + p + " " + back);
            double best = Double.POSITIVE_INFINITY;
            for (int j = 0; j < DIRECTIONS; j++) {
                double a = 2 * Math.PI * j / DIRECTIONS;
                best = Math.min(best, bruteForcePush(k, p, Math.cos(a), Math.sin(a)));
            }
            assertTrue(c.depth() <= best + 1e-3, "longer than the brute force's " + best + ": " + k + " " + p + " " + c);
            // 720 directions are 0.5 degrees apart: the brute force can be longer by about best * 0.0087.
            assertTrue(c.depth() >= best * (1 - 0.01) - 1e-3, "shorter than any push found, " + best + ": " + k + " " + p + " " + c);
            // Where the nearest convex piece alone would say less, the whole polygon was needed.
            double nearestPiece = Double.POSITIVE_INFINITY;
            for (Object piece : ConvexSweep.pieces(p)) {
                double[] xy = (double[]) piece;
                float[] f = new float[xy.length];
                for (int m = 0; m < xy.length; m++) {
                    f[m] = (float) xy[m];
                }
                Polygon part = Polygon.of(f);
                Contact q = k.contact(part);
                if (q != null) {
                    nearestPiece = Math.min(nearestPiece, q.depth());
                }
            }
            if (nearestPiece < c.depth() - 1e-2) {
                notNearest++;
            }
        }
        assertTrue(checked >= 40, checked + " contacts checked");
        assertTrue(notNearest > 0, "no case needed more than the nearest piece's push");
    }

    /**
     * A capsule lying in a deep U's slot, wider than the slot: pushed out of either arm alone
     * it goes 1 pixel sideways, into the other arm; out of the whole U it goes up through the
     * slot's open top until its lower round end clears the arms' corners: 10 + sqrt(4^2 - 3^2).
     */
    @Test
    void capsuleInASlot_leavesThroughTheOpening() {
        Polygon u = Polygon.of(0, 0, 40, 0, 40, 30, 46, 30, 46, 0, 86, 0, 86, 45, 0, 45);
        Capsule k = new Capsule(43, 5, 43, 10, 4);
        Contact c = k.contact(u);
        assertNotNull(c);
        assertEquals(0, c.nx(), 1e-4);
        assertEquals(1, c.ny(), 1e-4); // from the capsule to the U: the capsule goes up
        assertEquals(10 + Math.sqrt(7), c.depth(), 1e-3);
        Contact back = u.contact(k);
        assertEquals(-1, back.ny(), 1e-4);
        assertEquals(c.depth(), back.depth(), 1e-4);
    }
}
