package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.PropertyDefaults;
import net.jqwik.api.Provide;
import net.jqwik.api.ShrinkingMode;
import org.junit.jupiter.api.Test;

/**
 * Issue 23's broken promises at the edges: a mover touching at the start and moving in gets
 * t = 0 exactly (Hit's promise) from every sweep pair; the box sweep's walk cannot jump over
 * an overlap that float rounding has shortened; Edges' wraps stay in their promised range for
 * huge sizes.
 */
@PropertyDefaults(shrinking = ShrinkingMode.OFF)
class SweepStartAndWindowTest {

    @Test
    void rectRect_touchingAtStartAndMovingIn_isExactlyZero() {
        // Before: 1.78e-16, the largest float at which x + t * vx had not yet moved.
        assertEquals(0f, Sweep.rectRect(0, 0, 10, 10, 5, 0, 10, 0, 10, 10));
        Hit h = Raw.sweepRectRectHit(0, 0, 10, 10, 5, 0, 10, 0, 10, 10);
        assertEquals(new Hit(0, 1, 0, Side.LEFT), h);
        assertEquals(0f, Sweep.rectRect(0, 0, 10, 10, 0, -3, 2, -10, 5, 10), "from below, moving up");
    }

    @Test
    void rawFloatPairs_touchingAtStartAndMovingIn_areExactlyZero() {
        assertEquals(0f, Raw.sweepCircleCircle(0, 0, 5, 3, 0, 10, 0, 5));
        assertEquals(0f, Raw.sweepCircleRect(0, 0, 5, 3, 0, 5, -5, 10, 10));
        assertEquals(0f, Raw.sweepCircleRectHit(0, 0, 5, 3, 4, 3, 4, 10, 10).t(), "against a corner");
        assertEquals(0f, Raw.sweepRectSegmentHit(0, 0, 10, 10, 5, 0, 10, -5, 10, 20).t());
        assertEquals(0f, Raw.sweepCircleSegmentHit(0, 0, 5, 5, 0, 5, -5, 5, 20).t());
    }

    @Test
    void everyShapePair_touchingAtStartAndMovingIn_isExactlyZero() {
        // Each mover's right side on x = 10, each obstacle's left side on x = 10, moving right.
        Shape[] movers = {new Rect(0, 0, 10, 10), new Circle(5, 5, 5), Polygon.of(0, 0, 10, 0, 10, 10, 0, 10),
            Polygon.of(0, 0, 10, 0, 10, 10, 5, 5, 0, 10), new Ellipse(5, 5, 5, 5), new Capsule(5, 5, 5, 5.5f, 5),
            new Segment(10, 0, 10, 10)};
        Shape[] obstacles = {new Rect(10, 0, 10, 10), new Circle(15, 5, 5), Polygon.of(10, 0, 20, 0, 20, 10, 10, 10),
            Polygon.of(10, 0, 20, 0, 20, 10, 15, 5, 10, 10), new Ellipse(15, 5, 5, 5), new Capsule(15, -5, 15, 15, 5),
            new Segment(10, -5, 10, 15)};
        for (Shape m : movers) {
            for (Shape o : obstacles) {
                if (m instanceof Segment && o instanceof Segment) {
                    continue;  // two segments on one line already meet: overlapping, not touching
                }
                assertFalse(m.overlaps(o), () -> m + " " + o);
                Hit h = Sweep.timeOfImpact(m, 5, 0, o);
                assertNotNull(h, () -> m + " into " + o);
                assertEquals(0f, h.t(), () -> m + " into " + o + ": " + h);
                assertFalse(h.alreadyOverlapping(), () -> m + " into " + o);
                assertEquals(1f, h.nx(), 1e-6f, () -> m + " into " + o + ": " + h);
            }
        }
    }

    @Test
    void rectRect_overlapShortenedByRounding_isNotJumpedOver() {
        // y = 524373 moves in steps of 1/16: the float overlap starts at t = 0.2031, not at the
        // exact 0.2, and ends at 0.2034; the walk up from 0.2, doubling, jumped from 0.20195
        // to 0.2039 and answered 1 (it made SweepPropertiesTest's translated-by-whole-numbers
        // property flake).
        float t = Sweep.rectRect(-30, 524373, 0, 7, 59, 10, -28, 524382, 10, 10);
        assertEquals(0.203125f, t);
        assertFalse(Collide.rectRect(-30 + t * 59, 524373 + t * 10, 0, 7, -28, 524382, 10, 10));
        float next = Math.nextUp(t);
        assertTrue(Collide.rectRect(-30 + next * 59, 524373 + next * 10, 0, 7, -28, 524382, 10, 10));
        assertEquals(t, Raw.sweepRectRectHit(-30, 524373, 0, 7, 59, 10, -28, 524382, 10, 10).t());
    }

    /**
     * Boxes far from the origin (positions in steps of 1/16 to 1/32) whose paths pass a
     * pixel or so from a corner of the obstacle: the overlaps that rounding shortens most.
     * About 1 in 4000 of these made the walk jump over the overlap before.
     */
    @Provide
    Arbitrary<float[]> farBoxes() {
        return Arbitraries.longs().map(seed -> {
            java.util.SplittableRandom r = new java.util.SplittableRandom(seed);
            float x0 = r.nextInt(1200001) - 600000, y0 = r.nextInt(1200001) - 600000;
            float vx = r.nextInt(129) - 64, vy = r.nextInt(129) - 64;
            float w = r.nextInt(12), h = r.nextInt(12), ow = 1 + r.nextInt(12), oh = 1 + r.nextInt(12);
            double at = r.nextDouble();
            float ox = x0 + Math.round(at * vx) + (vx > 0 ? w : -ow) + r.nextInt(3) - 1;
            float oy = y0 + Math.round(at * vy) + (vy > 0 ? h : -oh) + r.nextInt(3) - 1;
            return new float[] {x0, y0, w, h, vx, vy, ox, oy, ow, oh};
        });
    }

    /**
     * Wherever the box sweep answers a t below 1, it is the largest clear float with an
     * overlapping one next; where it answers 1 or no hit, no float position in between
     * overlaps (sampled on a dense grid of floats).
     */
    @Property(tries = 20000)
    void rectRect_answerIsTheLastClearFloat_farFromTheOrigin(@ForAll("farBoxes") float[] c) {
        float t = Sweep.rectRect(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9]);
        String what = java.util.Arrays.toString(c) + " gave " + t;
        if (Collide.rectRect(c[0], c[1], c[2], c[3], c[6], c[7], c[8], c[9])) {
            assertEquals(0f, t, what);
            return;
        }
        if (t < 1) {
            assertFalse(overlapsAt(c, t), what);
            assertTrue(t == 0 || overlapsAt(c, Math.nextUp(t)), what);
        }
        float end = t < 1 ? t : 1;
        for (int i = 0; i <= 4000; i++) {
            float s = end * i / 4000f;
            if (s < end) {
                assertFalse(overlapsAt(c, s), () -> what + ": overlaps earlier, at " + s);
            }
        }
    }

    private static boolean overlapsAt(float[] c, float t) {
        return Collide.rectRect(c[0] + t * c[4], c[1] + t * c[5], c[2], c[3], c[6], c[7], c[8], c[9]);
    }

    // ---------------------------------------------------------------- Edges' wraps

    @Test
    void rectWrapX_sizeFarAboveTheWindow_staysInRange() {
        // Before: 2, outside [-1e17, 1]: 2 + 1e17 and 1 + 1e17 round to the same double.
        float x = Edges.rectWrapX(2, 1e17f, 1);
        assertTrue(x >= -1e17f && x <= 1, "was " + x);
        float y = Edges.rectWrapY(2, 1e17f, 1);
        assertTrue(y >= -1e17f && y <= 1, "was " + y);
        assertEquals(1f, Edges.rectWrapX(1, 1e17f, 1), "the window's edge is in range: unchanged");
    }

    @Provide
    Arbitrary<Float> anyFinite() {
        return Arbitraries.oneOf(
                Arbitraries.floats().between(-1000, 1000),
                Arbitraries.floats().between(-Float.MAX_VALUE, Float.MAX_VALUE),
                Arbitraries.integers().between(-60, 60).map(i -> (float) Math.scalb(1.0, i)),
                Arbitraries.integers().between(-60, 60).map(i -> (float) -Math.scalb(1.0, i)));
    }

    @Provide
    Arbitrary<Float> anySize() {
        return anyFinite().map(Math::abs);
    }

    @Property(tries = 5000)
    void wraps_alwaysInTheirPromisedRange(@ForAll("anyFinite") float pos, @ForAll("anySize") float size,
                                          @ForAll("anySize") float window) {
        float rx = Edges.rectWrapX(pos, size, window);
        assertTrue(rx >= -size && rx <= window, () -> "rectWrapX(" + pos + ", " + size + ", " + window + ") = " + rx);
        float ry = Edges.rectWrapY(pos, size, window);
        assertTrue(ry >= -size && ry <= window, () -> "rectWrapY(" + pos + ", " + size + ", " + window + ") = " + ry);
        float cx = Edges.circleWrapX(pos, size, window);
        assertTrue(cx >= -size && cx <= (double) window + size,
                () -> "circleWrapX(" + pos + ", " + size + ", " + window + ") = " + cx);
        float cy = Edges.circleWrapY(pos, size, window);
        assertTrue(cy >= -size && cy <= (double) window + size,
                () -> "circleWrapY(" + pos + ", " + size + ", " + window + ") = " + cy);
        if (pos >= -size && pos <= window) {
            assertEquals(pos, rx, "in range: unchanged");
        }
    }
}
