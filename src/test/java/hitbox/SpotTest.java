package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import hitbox.internal.Extents;
import hitbox.internal.Poses;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * A world's walk keeps a moving box or circle as numbers ({@link Spot}); every answer it asks
 * of them must be the shape's own: its translation, extents, reach and reference point, its
 * overlap with any kind of obstacle, and its sweep into one (time, normal and side). The
 * oracle is the public shape API on the same shape; the pairs are random, of every kind.
 */
class SpotTest {

    @Test
    void aSpotAnswersAsItsShape_forEveryKindOfObstacle() {
        Random rnd = new Random(2929);
        float[] out = new float[3];
        int hits = 0, overlaps = 0;
        for (int i = 0; i < 40_000; i++) {
            Shape s = rnd.nextBoolean()
                    ? new Rect(Sampled.coord(rnd), Sampled.coord(rnd), rnd.nextInt(4) == 0 ? 0 : 1 + rnd.nextInt(40), 1 + rnd.nextInt(40) + rnd.nextFloat())
                    : new Circle(Sampled.coord(rnd), Sampled.coord(rnd), rnd.nextInt(8) == 0 ? 0 : 1 + rnd.nextInt(25) + rnd.nextFloat());
            Shape other = Sampled.any(rnd);
            // As numbers (no shape kept), moved as the shape moves.
            float dx = (rnd.nextFloat() - 0.5f) * 40, dy = (rnd.nextFloat() - 0.5f) * 40;
            Spot spot = asNumbers(s).translate(dx, dy);
            Shape moved = s.translated(dx, dy);
            String what = moved + " with " + other;
            assertEquals(moved, spot.shape(), what);
            spot = asNumbers(s).translate(dx, dy);  // again, its shape not made
            Spot otherSpot = asNumbers(other);  // a box or a circle as numbers too, anything else as itself
            assertEquals(Extents.minX(moved), spot.minX(), what);
            assertEquals(Extents.minY(moved), spot.minY(), what);
            assertEquals(Extents.maxX(moved), spot.maxX(), what);
            assertEquals(Extents.maxY(moved), spot.maxY(), what);
            assertEquals(Extents.reach(moved), spot.reach(), what);
            assertEquals(Poses.refX(moved), spot.refX(), what);
            assertEquals(Poses.refY(moved), spot.refY(), what);
            boolean overlap = moved.overlaps(other);
            assertEquals(overlap, spot.overlaps(other), what);
            assertEquals(overlap, spot.overlaps(otherSpot), what);
            assertEquals(overlap, otherSpot.overlaps(spot), what);
            overlaps += overlap ? 1 : 0;
            float vx = (rnd.nextFloat() - 0.5f) * 160, vy = (rnd.nextFloat() - 0.5f) * 160;
            Hit h = Sweep.timeOfImpact(moved, vx, vy, other);
            what += " by (" + vx + ", " + vy + ")";
            for (Spot obstacle : new Spot[] {otherSpot, new Spot().set(other)}) {  // as numbers, and with the shape made
                out[0] = out[1] = out[2] = Float.NaN;
                Side side = spot.sweep(vx, vy, obstacle, out);
                if (h == null) {
                    assertNull(side, what);
                    continue;
                }
                assertEquals(h.side(), side, what);
                assertEquals(h.t(), out[0], what);
                assertEquals(h.nx(), out[1], what);
                assertEquals(h.ny(), out[2], what);
            }
            hits += h != null && !h.alreadyOverlapping() ? 1 : 0;
        }
        assertTrue(hits > 3_000 && overlaps > 3_000, hits + " hits, " + overlaps + " overlaps");
    }

    @Test
    void aSpotRefusesAMoveOutOfTheFloatRange_asItsShapeDoes() {
        Spot box = new Spot().setBox(3e38f, 0, 10, 10);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> box.translate(3e38f, 0));
        IllegalArgumentException f = assertThrows(IllegalArgumentException.class, () -> new Rect(3e38f, 0, 10, 10).translated(3e38f, 0));
        assertEquals(f.getMessage(), e.getMessage());
    }

    /** A box or a circle as numbers, no shape made; any other shape as itself. */
    private static Spot asNumbers(Shape s) {
        if (s instanceof Rect r) {
            return new Spot().setBox(r.x(), r.y(), r.w(), r.h());
        }
        return s instanceof Circle c ? numbersOf(c) : new Spot().set(s);
    }

    /** A circle's spot as numbers: taken from a body that has not made its shape. */
    private static Spot numbersOf(Circle c) {
        World w = new World();
        Body b = w.add(new Circle(0, 0, c.r()));
        b.moveTo(c.x(), c.y());  // a pose: the shape is not made until asked
        Spot s = new Spot().set(b);
        assertEquals(c, s.shape(), "the body's circle");
        return new Spot().set(b);
    }
}
