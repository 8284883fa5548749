package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.EnumSet;
import java.util.Set;
import net.jqwik.api.Assume;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.FloatRange;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class EdgesTest {

    // The tables below name sides in the bits the tests have always used (LEFT 1, RIGHT 2,
    // TOP 4, BOTTOM 8); bits() and set() translate to and from the library's Set<Side>.
    private static final int NONE = 0, LEFT = 1, RIGHT = 2, TOP = 4, BOTTOM = 8;
    private static final Side[] IN_ORDER = {Side.LEFT, Side.RIGHT, Side.TOP, Side.BOTTOM};

    /** The bits of a set the library handed back, checking it holds no NONE and cannot be changed. */
    private static int bits(Set<Side> sides) {
        assertFalse(sides.contains(Side.NONE), "NONE names no side");
        assertThrows(UnsupportedOperationException.class, () -> sides.add(Side.LEFT), "handed back unmodifiable");
        int b = 0;
        for (int i = 0; i < 4; i++) {
            b |= sides.contains(IN_ORDER[i]) ? 1 << i : 0;
        }
        return b;
    }

    private static Set<Side> set(int bits) {
        Set<Side> s = EnumSet.noneOf(Side.class);
        for (int i = 0; i < 4; i++) {
            if ((bits & 1 << i) != 0) {
                s.add(IN_ORDER[i]);
            }
        }
        return s;
    }

    private static String describe(int bits) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < 4; i++) {
            if ((bits & 1 << i) != 0) {
                b.append(b.length() == 0 ? "" : "|").append(IN_ORDER[i].name());
            }
        }
        return b.length() == 0 ? "NONE" : b.toString();
    }

    private static boolean has(int bits, int side) {
        return (bits & side) != 0;
    }

    private static final float W = 400;
    private static final float H = 300;

    // ---- crossing ---------------------------------------------------------------------

    @ParameterizedTest(name = "point ({0}, {1}) crosses {2}")
    @CsvSource({
            "200, 150, NONE",
            "0, 0, NONE",            // on the corner: touching, not crossed
            "400, 300, NONE",
            "-0.001, 150, LEFT",
            "400.001, 150, RIGHT",
            "200, -1, TOP",
            "200, 301, BOTTOM",
            "-1, -1, LEFT|TOP",
            "401, 301, RIGHT|BOTTOM",
            "-1000000, 1000000, LEFT|BOTTOM",
    })
    void pointCrossed_table(float px, float py, String expected) {
        assertEquals(expected, describe(bits(Edges.crossed(new Circle(px, py, 0), W, H))));
    }

    @ParameterizedTest(name = "circle ({0}, {1}) r={2} crosses {3}")
    @CsvSource({
            "200, 150, 10, NONE",
            "10, 150, 10, NONE",        // touching the left edge
            "390, 150, 10, NONE",       // touching the right edge
            "200, 10, 10, NONE",        // touching the top
            "200, 290, 10, NONE",       // touching the bottom
            "10, 10, 10, NONE",         // touching two edges at a corner
            "9.5, 150, 10, LEFT",
            "390.5, 150, 10, RIGHT",
            "200, 9, 10, TOP",
            "200, 291, 10, BOTTOM",
            "5, 295, 10, LEFT|BOTTOM",
            "200, 150, 160, TOP|BOTTOM",   // taller than the window
            "200, 150, 1000, LEFT|RIGHT|TOP|BOTTOM",
            "0, 150, 0, NONE",          // radius 0 is a point on the edge
            "-0.5, 150, 0, LEFT",
            "-1000000, 150, 10, LEFT",
            "1000000, 1000000, 10, RIGHT|BOTTOM",
    })
    void circleCrossed_table(float cx, float cy, float r, String expected) {
        assertEquals(expected, describe(bits(Edges.crossed(new Circle(cx, cy, r), W, H))));
        assertEquals(expected, describe(bits(Edges.crossed(new Circle(cx, cy, r), W, H))));
    }

    @ParameterizedTest(name = "rect ({0}, {1}, {2}, {3}) crosses {4}")
    @CsvSource({
            "100, 100, 50, 50, NONE",
            "0, 0, 400, 300, NONE",      // exactly the window: touching all four edges
            "0, 0, 50, 50, NONE",
            "350, 250, 50, 50, NONE",
            "-1, 100, 50, 50, LEFT",
            "351, 100, 50, 50, RIGHT",
            "100, -0.25, 50, 50, TOP",
            "100, 251, 50, 50, BOTTOM",
            "-1, -1, 402, 302, LEFT|RIGHT|TOP|BOTTOM",
            "400, 100, 0, 0, NONE",      // zero size on the right edge
            "400.5, 100, 0, 0, RIGHT",
            "100, 300, 10, 0, NONE",     // zero height lying on the bottom edge
            "-1000000, -1000000, 10, 10, LEFT|TOP",
    })
    void rectCrossed_table(float x, float y, float w, float h, String expected) {
        assertEquals(expected, describe(bits(Edges.crossed(new Rect(x, y, w, h), W, H))));
        assertEquals(expected, describe(bits(Edges.crossed(new Rect(x, y, w, h), W, H))));
    }

    @Test
    void crossed_otherShapesUseTheirBounds() {
        assertEquals(NONE, bits(Edges.crossed(new Segment(0, 0, 400, 300), W, H)));
        assertEquals(RIGHT, bits(Edges.crossed(new Segment(0, 10, 401, 10), W, H)));
        assertEquals(TOP, bits(Edges.crossed(Polygon.of(10, -1, 20, 20, 0, 20), W, H)));
        assertEquals(NONE, bits(Edges.crossed(Polygon.of(10, 0, 20, 20, 0, 20), W, H)));
    }

    @Test
    void crossed_nullShape_namesTheParameter() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> bits(Edges.crossed(null, W, H)));
        assertEquals("shape must not be null", e.getMessage());
    }

    @Test
    void crossed_nanOrNegativeWindow_crossesNothing() {
        // The shapes refuse NaN themselves; a NaN or negative window is no window.
        assertEquals(NONE, bits(Edges.crossed(new Circle(-10, 10, 5), Float.NaN, H)));
        assertEquals(NONE, bits(Edges.crossed(new Circle(-10, 10, 5), W, -1)));
        assertThrows(IllegalArgumentException.class, () -> new Circle(Float.NaN, 10, 5));
    }

    /** The crossing rule, decided exactly in BigDecimal: strictly past an edge. */
    private static int reference(BigDecimal left, BigDecimal right, BigDecimal top, BigDecimal bottom, float w, float h) {
        int e = 0;
        if (left.signum() < 0) {
            e |= LEFT;
        }
        if (right.compareTo(new BigDecimal(w)) > 0) {
            e |= RIGHT;
        }
        if (top.signum() < 0) {
            e |= TOP;
        }
        if (bottom.compareTo(new BigDecimal(h)) > 0) {
            e |= BOTTOM;
        }
        return e;
    }

    @Property
    void rectCrossed_agreesWithExactReference(@ForAll @FloatRange(min = -2000, max = 2000) float x,
                                              @ForAll @FloatRange(min = -2000, max = 2000) float y,
                                              @ForAll @FloatRange(min = 0, max = 900) float w,
                                              @ForAll @FloatRange(min = 0, max = 900) float h) {
        BigDecimal bx = new BigDecimal(x), by = new BigDecimal(y);
        assertEquals(reference(bx, bx.add(new BigDecimal(w)), by, by.add(new BigDecimal(h)), W, H),
                bits(Edges.crossed(new Rect(x, y, w, h), W, H)));
    }

    @Property
    void circleCrossed_agreesWithExactReference(@ForAll @FloatRange(min = -2000, max = 2000) float cx,
                                                @ForAll @FloatRange(min = -2000, max = 2000) float cy,
                                                @ForAll @FloatRange(min = 0, max = 900) float r) {
        BigDecimal bx = new BigDecimal(cx), by = new BigDecimal(cy), br = new BigDecimal(r);
        assertEquals(reference(bx.subtract(br), bx.add(br), by.subtract(br), by.add(br), W, H),
                bits(Edges.crossed(new Circle(cx, cy, r), W, H)));
    }

    @Property
    void circleCrossed_radiusZeroIsThePoint(@ForAll @FloatRange(min = -2000, max = 2000) float x,
                                            @ForAll @FloatRange(min = -2000, max = 2000) float y) {
        assertEquals(bits(Edges.crossed(new Circle(x, y, 0), W, H)), bits(Edges.crossed(new Circle(x, y, 0), W, H)));
    }

    @Property
    void crossed_mirrorLeftIsRight(@ForAll @IntRange(min = -1000, max = 1000) int x,
                                   @ForAll @IntRange(min = 0, max = 500) int w) {
        // Mirroring the window swaps LEFT and RIGHT: the two edges follow the same rule.
        int crossed = bits(Edges.crossed(new Rect(x, 100, w, 10), W, H));
        int mirrored = bits(Edges.crossed(new Rect(W - x - w, 100, w, 10), W, H));
        assertEquals(has(crossed, LEFT), has(mirrored, RIGHT));
        assertEquals(has(crossed, RIGHT), has(mirrored, LEFT));
    }

    // ---- bounce -----------------------------------------------------------------------

    @ParameterizedTest(name = "bounceX({0}, {1}) = {2}")
    @CsvSource({
            "NONE, 3, 3",
            "NONE, -3, -3",
            "LEFT, -3, 3",
            "LEFT, 3, 3",       // already heading back in: keep it (a flip would send it out)
            "RIGHT, 3, -3",
            "RIGHT, -3, -3",
            "LEFT|RIGHT, 3, 3", // wider than the window: no inside direction
            "TOP, -3, -3",      // vertical edges leave vx alone
            "LEFT|TOP, -2, 2",
            "LEFT, 0, 0",
    })
    void bounceX_table(String crossed, float vx, float expected) {
        assertEquals(expected, Edges.bounceX(set(flags(crossed)), vx));
    }

    @ParameterizedTest(name = "bounceY({0}, {1}) = {2}")
    @CsvSource({
            "NONE, 3, 3",
            "TOP, -3, 3",
            "TOP, 3, 3",
            "BOTTOM, 3, -3",
            "BOTTOM, -3, -3",
            "TOP|BOTTOM, -3, -3",
            "LEFT, -3, -3",
            "RIGHT|BOTTOM, 5, -5",
    })
    void bounceY_table(String crossed, float vy, float expected) {
        assertEquals(expected, Edges.bounceY(set(flags(crossed)), vy));
    }

    private static int flags(String names) {
        int f = 0;
        for (String n : names.split("\\|")) {
            f |= switch (n) {
                case "NONE" -> NONE;
                case "LEFT" -> LEFT;
                case "RIGHT" -> RIGHT;
                case "TOP" -> TOP;
                case "BOTTOM" -> BOTTOM;
                default -> throw new IllegalArgumentException(n);
            };
        }
        return f;
    }

    @Property
    void bounce_afterCrossingPointsInsideAndKeepsSpeed(@ForAll @FloatRange(min = -2000, max = 2000) float cx,
                                                       @ForAll @FloatRange(min = -2000, max = 2000) float cy,
                                                       @ForAll @FloatRange(min = 0, max = 100) float r,
                                                       @ForAll @FloatRange(min = -50, max = 50) float vx,
                                                       @ForAll @FloatRange(min = -50, max = 50) float vy) {
        int crossed = bits(Edges.crossed(new Circle(cx, cy, r), W, H));
        float bx = Edges.bounceX(set(crossed), vx);
        float by = Edges.bounceY(set(crossed), vy);
        assertEquals(Math.abs(vx), Math.abs(bx));
        assertEquals(Math.abs(vy), Math.abs(by));
        int xs = crossed & (LEFT | RIGHT);
        int ys = crossed & (TOP | BOTTOM);
        if (xs == LEFT) {
            assertTrue(bx >= 0);
        } else if (xs == RIGHT) {
            assertTrue(bx <= 0);
        } else {
            assertEquals(vx, bx);
        }
        if (ys == TOP) {
            assertTrue(by >= 0);
        } else if (ys == BOTTOM) {
            assertTrue(by <= 0);
        } else {
            assertEquals(vy, by);
        }
    }

    @Property
    void bounce_ballFarOutsideComesBackInsteadOfJittering(@ForAll @IntRange(min = 1, max = 500) int outside,
                                                          @ForAll @IntRange(min = 1, max = 20) int speed,
                                                          @ForAll boolean headingOut) {
        // A ball placed well beyond the left edge, moving either way. With a blind flip it
        // would swap direction every frame and stay outside; with bounceX it walks back in.
        float r = 10;
        float x = r - outside;
        float vx = headingOut ? -speed : speed;
        int frames = 0;
        while (has(bits(Edges.crossed(new Circle(x, 150, r), W, H)), LEFT)) {
            vx = Edges.bounceX(set(bits(Edges.crossed(new Circle(x, 150, r), W, H))), vx);
            x += vx;
            frames++;
            assertTrue(frames <= outside / speed + 2, "the ball should come back inside, not jitter");
        }
        assertTrue(vx > 0);
    }

    @Test
    void bounce_blindFlipJittersButBounceDoesNot() {
        // The failure bounceX avoids: a ball 25 px past the edge with speed 3.
        float r = 10;
        float flipX = -15, flipVx = -3;
        for (int frame = 0; frame < 100; frame++) {
            if (flipX < r) {
                flipVx *= -1;
            }
            flipX += flipVx;
        }
        assertTrue(flipX < r, "the tutorial's flip leaves the ball stuck beyond the edge");

        float x = -15, vx = -3;
        for (int frame = 0; frame < 100; frame++) {
            vx = Edges.bounceX(set(bits(Edges.crossed(new Circle(x, 150, r), W, H))), vx);
            x += vx;
        }
        assertEquals(NONE, bits(Edges.crossed(new Circle(x, 150, r), W, H)) & LEFT);
    }

    // ---- wrap -------------------------------------------------------------------------

    @ParameterizedTest(name = "circleWrapX({0}, r={1}) = {2}")
    @CsvSource({
            "200, 10, 200",       // inside: unchanged
            "-5, 10, -5",         // half out: not yet fully left
            "-10, 10, -10",       // fully left, touching from outside: same place as 410
            "410, 10, 410",
            "-11, 10, 409",       // 1 px past: comes in 1 px on the right (loop 420)
            "411, 10, -9",
            "-431, 10, 409",      // more than a whole loop away
            "1271, 10, 11",       // 3 loops of 420 to the right of 11
            "0, 0, 0",            // a point on the edge
            "-1, 0, 399",
            "401, 0, 1",
    })
    void circleWrapX_table(float cx, float r, float expected) {
        assertEquals(expected, Edges.circleWrapX(cx, r, W));
        // The same rule runs vertically, with the height in place of the width.
        assertEquals(expected, Edges.circleWrapY(cx, r, W));
    }

    @ParameterizedTest(name = "rectWrapX({0}, w={1}) = {2}")
    @CsvSource({
            "100, 50, 100",
            "-50, 50, -50",      // fully left, right edge touching x = 0
            "400, 50, 400",      // fully right, left edge touching x = width
            "-51, 50, 399",      // loop 450
            "401, 50, -49",
            "-1000000, 50, 350", // far-left end -999950 + 2223 loops of 450 = 400
            "5, 0, 5",
            "-2, 0, 398",
    })
    void rectWrapX_table(float x, float w, float expected) {
        assertEquals(expected, Edges.rectWrapX(x, w, W));
        assertEquals(expected, Edges.rectWrapY(x, w, W));
    }

    @Property
    void circleWrap_keepsShapeInRangeAndNeverOnBothSides(@ForAll @FloatRange(min = -1e6f, max = 1e6f) float cx,
                                                         @ForAll @FloatRange(min = 0, max = 150) float r) {
        float wrapped = Edges.circleWrapX(cx, r, W);
        assertTrue((double) wrapped >= -(double) r && (double) wrapped <= (double) W + r,
                () -> "wrapped " + wrapped + " out of range");
        // Never drawn half on each side (the circle fits in the window here).
        int crossed = bits(Edges.crossed(new Circle(wrapped, 150, r), W, H));
        assertFalse(has(crossed, LEFT) && has(crossed, RIGHT));
        assertEquals(wrapped, Edges.circleWrapX(wrapped, r, W), "wrapping twice changes nothing");
    }

    @Property
    void rectWrap_keepsShapeInRange(@ForAll @FloatRange(min = -1e6f, max = 1e6f) float y,
                                    @ForAll @FloatRange(min = 0, max = 1000) float h) {
        float wrapped = Edges.rectWrapY(y, h, H);
        assertTrue(wrapped >= -h && wrapped <= H, () -> "wrapped " + wrapped + " out of range");
        assertEquals(wrapped, Edges.rectWrapY(wrapped, h, H));
    }

    @Property
    void rectWrap_movesByWholeLoops(@ForAll @IntRange(min = -1_000_000, max = 1_000_000) int x,
                                    @ForAll @IntRange(min = 0, max = 300) int w) {
        float wrapped = Edges.rectWrapX(x, w, W);
        int loop = (int) W + w;
        assertEquals(0, Math.floorMod((long) (wrapped - x), loop), "moved by a whole number of loops");
        assertEquals(wrapped == x, x + w >= 0 && x <= W, "a rect not fully gone stays put");
    }

    @Property
    void wrap_movingSteadilyLeavesOnOneSideAndEntersOnTheOther(@ForAll @IntRange(min = 1, max = 30) int speed,
                                                               @ForAll @IntRange(min = 1, max = 60) int r) {
        // Pac-Man: walk left until wrapped once; the circle reappears on the right, coming in.
        float x = 200;
        boolean wrappedOnce = false;
        for (int frame = 0; frame < 2000 && !wrappedOnce; frame++) {
            float before = x - speed;
            x = Edges.circleWrapX(before, r, W);
            if (x != before) {
                wrappedOnce = true;
                assertTrue(x - r >= W - speed && x - r < W, "comes in from the right: " + x);
                assertEquals(before + W + 2 * r, x);
            } else {
                assertTrue(x + r >= 0, "not wrapped before it has fully left: " + x);
            }
        }
        assertTrue(wrappedOnce);
    }

    // ---- clamp ------------------------------------------------------------------------

    @ParameterizedTest(name = "circleClampX({0}, r={1}) = {2}")
    @CsvSource({
            "200, 10, 200",
            "10, 10, 10",        // touching is inside
            "5, 10, 10",
            "-1000000, 10, 10",
            "395, 10, 390",
            "1000000, 10, 390",
            "50, 250, 200",      // wider than the window: centred
            "0, 0, 0",
            "-3, 0, 0",
    })
    void circleClampX_table(float cx, float r, float expected) {
        assertEquals(expected, Edges.circleClampX(cx, r, W));
        assertEquals(expected, Edges.circleClampY(cx, r, W));
    }

    @ParameterizedTest(name = "rectClampX({0}, w={1}) = {2}")
    @CsvSource({
            "100, 50, 100",
            "-1, 50, 0",
            "360, 50, 350",
            "350, 50, 350",
            "0, 400, 0",         // exactly the window
            "-30, 500, -50",     // wider: centred, 50 out on each side
            "401, 0, 400",
    })
    void rectClampX_table(float x, float w, float expected) {
        assertEquals(expected, Edges.rectClampX(x, w, W));
        assertEquals(expected, Edges.rectClampY(x, w, W));
    }

    @Property
    void clamp_resultIsInsideAndMovesOnlyWhenNeeded(@ForAll @FloatRange(min = -1e6f, max = 1e6f) float cx,
                                                    @ForAll @FloatRange(min = -1e6f, max = 1e6f) float cy,
                                                    @ForAll @FloatRange(min = 0, max = 150) float r) {
        float x = Edges.circleClampX(cx, r, W);
        float y = Edges.circleClampY(cy, r, H);
        assertEquals(NONE, bits(Edges.crossed(new Circle(x, y, r), W, H)));
        if (bits(Edges.crossed(new Circle(cx, cy, r), W, H)) == NONE) {
            assertEquals(cx, x);
            assertEquals(cy, y);
        }
        assertEquals(x, Edges.circleClampX(x, r, W), "clamping twice changes nothing");
    }

    @Property
    void rectClamp_resultIsInsideForAnyFloats(@ForAll @FloatRange(min = -1e6f, max = 1e6f) float x,
                                              @ForAll @FloatRange(min = 0, max = 300) float w,
                                              @ForAll @FloatRange(min = 1, max = 1000) float width) {
        Assume.that(w <= width);
        float clamped = Edges.rectClampX(x, w, width);
        assertEquals(NONE, bits(Edges.crossed(new Rect(clamped, 0, w, 0), width, 1)));
    }

    @Test
    void clamp_nanStaysNan() {
        assertTrue(Float.isNaN(Edges.circleClampX(Float.NaN, 10, W)));
        assertTrue(Float.isNaN(Edges.rectWrapX(Float.NaN, 10, W)));
    }

    // ---- a negative size or window: no answer, as for NaN (the package's bad-input rule) ----

    @ParameterizedTest(name = "{0}: crossing NONE, wrap and clamp hand {1} back")
    @CsvSource({
            // what,            x,    size, window
            "negative radius,   -10,  -5,   400",
            "negative radius,   420,  -5,   400",
            "negative window,   50,   5,    -100",
            "negative window,   -50,  5,    -100",
            "both negative,     -10,  -5,   -100",
            "-0 radius,         -10,  -0.0, 400",
    })
    void negativeSizeOrWindow_noCrossingAndPositionUnchanged(String what, float x, float size, float window) {
        boolean noShape = size < 0 || window < 0;  // -0 is a size of 0: a point, answered as one
        if (noShape) {
            if (size < 0) {
                // A negative size makes no shape to ask about (the raw crossing forms went).
                assertThrows(IllegalArgumentException.class, () -> new Circle(x, 50, size), what);
                assertThrows(IllegalArgumentException.class, () -> new Rect(x, 50, size, 10), what);
            } else {
                assertEquals(NONE, bits(Edges.crossed(new Circle(x, 50, size), window, 300)), what);
                assertEquals(NONE, bits(Edges.crossed(new Circle(50, x, size), 400, window)), what);
                assertEquals(NONE, bits(Edges.crossed(new Rect(x, 50, size, 10), window, 300)), what);
                assertEquals(NONE, bits(Edges.crossed(new Rect(50, x, 10, size), 400, window)), what);
            }
            assertEquals(x, Edges.circleWrapX(x, size, window), what);
            assertEquals(x, Edges.circleWrapY(x, size, window), what);
            assertEquals(x, Edges.rectWrapX(x, size, window), what);
            assertEquals(x, Edges.rectWrapY(x, size, window), what);
            assertEquals(x, Edges.circleClampX(x, size, window), what);
            assertEquals(x, Edges.circleClampY(x, size, window), what);
            assertEquals(x, Edges.rectClampX(x, size, window), what);
            assertEquals(x, Edges.rectClampY(x, size, window), what);
        } else {
            assertEquals(bits(Edges.crossed(new Circle(x, 50, 0), window, 300)), bits(Edges.crossed(new Circle(x, 50, size), window, 300)), what);
            // == rather than assertEquals: clamping against a -0 edge may give -0, which is 0.
            assertTrue(Edges.circleClampX(x, 0, window) == Edges.circleClampX(x, size, window), what);
        }
        if (window < 0) {
            assertEquals(NONE, bits(Edges.crossed(new Circle(x, 50, 0), window, 300)), what);
            assertEquals(NONE, bits(Edges.crossed(new Circle(x, 50, 5), window, 300)), what);
        }
    }
}
