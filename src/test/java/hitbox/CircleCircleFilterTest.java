package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.junit.jupiter.api.Test;

/**
 * {@link Collide#circleCircle} decides most pairs with float squares and leaves the pairs near
 * its band to the exact comparison in double. Its answer must be the exact one on every input,
 * so these cases sit where a float filter could go wrong: within a few float steps of touching
 * (inside the band and just outside it), at every scale from subnormal squares to squares that
 * overflow a float, centres so far apart that their float difference overflows, and the bad
 * inputs of the NaN rule. The oracle is exact arithmetic ({@link ExactReference}).
 */
class CircleCircleFilterTest {

    /** Two circles whose centres lie (r1 + r2)(1 + k 2^-e) apart along a random direction, at scale 2^s. */
    @Provide
    Arbitrary<float[]> nearlyTouching() {
        Arbitrary<Integer> scale = Arbitraries.integers().between(-75, 62);
        Arbitrary<Integer> offset = Arbitraries.integers().between(-64, 64);
        Arbitrary<Integer> exponent = Arbitraries.integers().between(12, 30);
        Arbitrary<Double> angle = Arbitraries.doubles().between(0, 6.28).ofScale(4);
        Arbitrary<Double> share = Arbitraries.doubles().between(0, 1).ofScale(6);
        return Combinators.combine(scale, offset, exponent, angle, share).as((s, k, e, a, f) -> {
            double size = Math.scalb(1.0, s);
            float r1 = (float) (size * f), r2 = (float) (size * (1 - f));
            double d = ((double) r1 + r2) * (1 + k * Math.scalb(1.0, -e));
            float x1 = (float) (size * 3), y1 = (float) (-size * 5);
            float x2 = (float) (x1 + d * Math.cos(a)), y2 = (float) (y1 + d * Math.sin(a));
            return new float[] {x1, y1, r1, x2, y2, r2};
        });
    }

    @Property(tries = 5000)
    void nearlyTouching_sameAsExact_bothOrders(@ForAll("nearlyTouching") float[] c) {
        assertExact(c[0], c[1], c[2], c[3], c[4], c[5]);
    }

    /** Any floats at all, finite, as large and as small as floats go. */
    @Provide
    Arbitrary<float[]> anyFinite() {
        Arbitrary<Float> coordinate = Arbitraries.floats().between(-Float.MAX_VALUE, Float.MAX_VALUE)
                .edgeCases(config -> config.add(0f, -0f, Float.MIN_VALUE, Float.MAX_VALUE, -Float.MAX_VALUE));
        Arbitrary<Float> radius = Arbitraries.floats().between(0, Float.MAX_VALUE)
                .edgeCases(config -> config.add(0f, Float.MIN_VALUE, Float.MAX_VALUE, 0x1p-50f, 0x1p64f));
        return Combinators.combine(coordinate, coordinate, radius, coordinate, coordinate, radius)
                .as((x1, y1, r1, x2, y2, r2) -> new float[] {x1, y1, r1, x2, y2, r2});
    }

    @Property(tries = 5000)
    void anyFiniteInput_sameAsExact_bothOrders(@ForAll("anyFinite") float[] c) {
        assertExact(c[0], c[1], c[2], c[3], c[4], c[5]);
    }

    @Test
    void extremes_sameAsExact() {
        float max = Float.MAX_VALUE;
        // Centres whose float difference overflows, with radii that reach or do not.
        assertExact(-max, 0, max, max, 0, max);
        assertExact(-max, 0, 0x1p64f, max, 0, 0x1p64f);
        // A reach whose float square overflows while the centres are close, or far.
        assertExact(0, 0, 0x1p64f, 1, 1, 0x1p64f);
        assertExact(0, 0, 0x1p64f, 0x1p66f, 0, 0x1p64f);
        assertExact(0, 0, 0x1p64f, 0x1p65f, 0, 0x1p64f);  // touching: no overlap
        // Squares that are subnormal in float.
        assertExact(0, 0, 0x1p-70f, 0x1p-69f, 0, 0x1p-70f);  // touching
        assertExact(0, 0, 0x1p-70f, Math.nextDown(0x1p-69f), 0, 0x1p-70f);
        assertExact(0, 0, Float.MIN_VALUE, Float.MIN_VALUE, 0, Float.MIN_VALUE);
        // Sizes 60 binades apart: in double the small radius and the small offset are lost
        // from both sums, so the squares come out equal while the exact reach is one float step
        // of the small radius longer than the distance (they overlap), or exactly as long.
        float a = 1048576.125f, b = 0x1p-40f;
        assertExact(a, 0, a, -b, 0, Math.nextUp(b));
        assertEquals(true, Collide.circleCircle(a, 0, a, -b, 0, Math.nextUp(b)), "overlap by a float step of 2^-40");
        assertExact(a, 0, a, -b, 0, b);
        assertEquals(true, Collide.circlePoint(a, 0, a, b, 0), "a point 2^-40 inside the edge");
        assertEquals(false, Collide.circlePoint(a, 0, a, -b, 0), "a point 2^-40 outside it");
        // Two points never meet; a point strictly inside a circle does.
        assertExact(1, 2, 0, 1, 2, 0);
        assertExact(1, 2, 0, 1, 2.5f, 1);
    }

    @Test
    void badInput_false() {
        float nan = Float.NaN, inf = Float.POSITIVE_INFINITY;
        assertFalse(Collide.circleCircle(nan, 0, 1, 0, 0, 1));
        assertFalse(Collide.circleCircle(0, 0, nan, 0, 0, 1));
        assertFalse(Collide.circleCircle(0, 0, 1, 0, 0, nan));
        assertFalse(Collide.circleCircle(0, 0, -1, 0, 0, 5));
        assertFalse(Collide.circleCircle(0, 0, 5, 0, 0, -1));
        assertFalse(Collide.circleCircle(inf, 0, 1, inf, 0, 1), "inf - inf is NaN");
        assertFalse(Collide.circleCircle(inf, 0, 1, 0, 0, 1));
        assertEquals(true, Collide.circleCircle(0, 0, inf, 5, 5, 1), "an infinite radius reaches every finite centre");
    }

    private static void assertExact(float x1, float y1, float r1, float x2, float y2, float r2) {
        boolean exact = ExactReference.circleCircle(x1, y1, r1, x2, y2, r2);
        String what = "circleCircle(" + x1 + ", " + y1 + ", " + r1 + ", " + x2 + ", " + y2 + ", " + r2 + ")";
        assertEquals(exact, Collide.circleCircle(x1, y1, r1, x2, y2, r2), what);
        assertEquals(exact, Collide.circleCircle(x2, y2, r2, x1, y1, r1), what + " the other way round");
    }
}
