package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import net.jqwik.api.Assume;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.FloatRange;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class SnapTest {

    // ---- the ground line --------------------------------------------------------------

    @ParameterizedTest(name = "standY(h={0}, ground={1}) = {2}")
    @CsvSource({
            "20, 300, 280",
            "0, 300, 300",
            "20, 0, -20",
            "20, 1000000, 999980",
            "0.5, -1000000, -1000000.5",
    })
    void standY_table(float h, float groundY, float expected) {
        assertEquals(expected, Snap.standY(h, groundY));
    }

    @ParameterizedTest(name = "y={0} h={1} ground={2}: onGround {3}, landY {4}")
    @CsvSource({
            "200, 20, 300, false, 200",
            "279, 20, 300, false, 279",
            "280, 20, 300, true, 280",      // standing exactly on it counts
            "285, 20, 300, true, 280",
            "1000, 20, 300, true, 280",     // fell far through: lifted back up
            "300, 0, 300, true, 300",       // zero height
            "299.5, 0, 300, false, 299.5",
            "999979, 20, 1000000, false, 999979",
            "999990, 20, 1000000, true, 999980",
    })
    void onGround_landY_table(float y, float h, float groundY, boolean onGround, float landY) {
        assertEquals(onGround, Snap.onGround(y, h, groundY));
        assertEquals(landY, Snap.landY(y, h, groundY));
    }

    @Property
    void standY_putsTheBottomOnTheGroundAsCloseAsFloatsAllow(@ForAll @FloatRange(min = 0, max = 1000) float h,
                                                             @ForAll @FloatRange(min = -1e6f, max = 1e6f) float groundY) {
        float y = Snap.standY(h, groundY);
        assertTrue((double) y + h <= groundY, "never below the ground");
        assertWithinAStep(y, new BigDecimal(groundY).subtract(new BigDecimal(h)));
        assertTrue(Snap.onGround(y, h, groundY), "a player that has landed is on the ground");
        // As a rectangle, it touches a ground rectangle and does not overlap it.
        assertFalse(Collide.rectRect(0, y, 10, h, -5, groundY, 20, 50));
    }

    @Property
    void landY_neverLeavesTheRectBelowTheGround(@ForAll @FloatRange(min = -1e6f, max = 1e6f) float y,
                                                @ForAll @FloatRange(min = 0, max = 1000) float h,
                                                @ForAll @FloatRange(min = -1e6f, max = 1e6f) float groundY) {
        float landed = Snap.landY(y, h, groundY);
        assertTrue((double) landed + h <= groundY);
        assertTrue(landed <= y, "landing only moves up");
        if ((double) y + h < groundY) {
            assertEquals(y, landed, "above the ground: unchanged");
        }
        assertEquals(landed, Snap.landY(landed, h, groundY));
    }

    @Property
    void falling_landsExactlyOnTheGround(@ForAll @IntRange(min = 0, max = 200) int startY,
                                         @ForAll @IntRange(min = 1, max = 60) int h,
                                         @ForAll @IntRange(min = 1, max = 5) int gravity) {
        float groundY = 400, y = startY, vy = 0;
        boolean landed = false;
        for (int frame = 0; frame < 200; frame++) {
            vy += gravity;
            y += vy;
            if (Snap.onGround(y, h, groundY)) {
                y = Snap.standY(h, groundY);
                vy = 0;
                landed = true;
            }
            assertTrue(y + h <= groundY);
        }
        assertTrue(landed);
        assertEquals(groundY, y + h);
    }

    // ---- pushOut ----------------------------------------------------------------------

    @ParameterizedTest(name = "[{0},{1},{2},{3}] out of [{4},{5},{6},{7}]: ({8}, {9}) {10}")
    @CsvSource({
            // mover          obstacle          result
            "10, -5, 10, 10,  0, 0, 100, 20,   10, -10, TOP",     // landed
            "10, 15, 10, 10,  0, 0, 100, 20,   10, 20, BOTTOM",   // bumped its head
            "-5, 5, 10, 10,   0, 0, 100, 20,   -10, 5, LEFT",
            "95, 5, 10, 10,   0, 0, 100, 20,   100, 5, RIGHT",
            "-5, -5, 10, 10,  0, 0, 100, 20,   -5, -10, TOP",     // corner tie: vertical wins
            "95, 15, 10, 10,  0, 0, 100, 20,   95, 20, BOTTOM",   // corner tie: vertical wins
            "10, 5, 10, 10,   0, 0, 100, 20,   10, -10, TOP",     // up and down tie: TOP
            "5, 5, 10, 90,    0, 0, 20, 100,   -10, 5, LEFT",     // left and right tie: LEFT
            "-10, 5, 20, 10,  0, 0, 20, 20,    -20, 5, LEFT",     // more outside than in
            "10, -10, 10, 10, 0, 0, 100, 20,   10, -10, NONE",    // touching: no push
            "500, 500, 10, 10, 0, 0, 100, 20,  500, 500, NONE",
            "50, 5, 0, 0,     0, 0, 100, 20,   50, 0, TOP",       // a point mover
            "10, 5, 10, 10,   0, 10, 100, 0,   10, 0, TOP",       // a zero-height obstacle
            "0, 0, 0, 0,      0, 0, 0, 0,      0, 0, NONE",       // two points never overlap
            "1000010, 999995, 10, 10, 1000000, 1000000, 100, 20, 1000010, 999990, TOP",
    })
    void pushOut_table(float x, float y, float w, float h, float ox, float oy, float ow, float oh,
                       float ex, float ey, Side side) {
        Snap.Push expected = new Snap.Push(ex, ey, side);
        assertEquals(expected, Snap.pushOut(x, y, w, h, ox, oy, ow, oh));
        assertFalse(Collide.rectRect(ex, ey, w, h, ox, oy, ow, oh));
    }

    @Test
    void pushOut_bothOrders_moveTheSameDistanceFromOppositeSides() {
        Rect a = new Rect(10, -5, 10, 10);
        Rect b = new Rect(0, 0, 100, 20);
        Snap.Push ab = Snap.pushOut(a.x(), a.y(), a.w(), a.h(), b.x(), b.y(), b.w(), b.h());
        Snap.Push ba = Snap.pushOut(b.x(), b.y(), b.w(), b.h(), a.x(), a.y(), a.w(), a.h());
        assertEquals(Side.TOP, ab.side());
        assertEquals(Side.BOTTOM, ba.side());
        assertEquals(-5, ab.y() - a.y());
        assertEquals(5, ba.y() - b.y());
    }

    @Property
    void pushOut_leavesTheRectsTouchingNotOverlapping(@ForAll @FloatRange(min = -200, max = 200) float x,
                                                      @ForAll @FloatRange(min = -200, max = 200) float y,
                                                      @ForAll @FloatRange(min = 0, max = 300) float w,
                                                      @ForAll @FloatRange(min = 0, max = 300) float h,
                                                      @ForAll @FloatRange(min = -200, max = 200) float ox,
                                                      @ForAll @FloatRange(min = -200, max = 200) float oy,
                                                      @ForAll @FloatRange(min = 0, max = 300) float ow,
                                                      @ForAll @FloatRange(min = 0, max = 300) float oh) {
        Snap.Push p = Snap.pushOut(x, y, w, h, ox, oy, ow, oh);
        assertTouchingNotOverlapping(p, x, y, w, h, ox, oy, ow, oh);
    }

    @Property
    void pushOut_overlappingRectsAreAlwaysPushed_andWholeNumbersTouchExactly(
            @ForAll @IntRange(min = -50, max = 50) int x, @ForAll @IntRange(min = -50, max = 50) int y,
            @ForAll @IntRange(min = 0, max = 60) int w, @ForAll @IntRange(min = 0, max = 60) int h,
            @ForAll @IntRange(min = 0, max = 60) int ow, @ForAll @IntRange(min = 0, max = 60) int oh,
            @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
            @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        Assume.that(Collide.rectRect(x, y, w, h, 0, 0, ow, oh));
        Snap.Push p = Snap.pushOut(x, y, w, h, 0, 0, ow, oh);
        assertTrue(p.hit());
        switch (p.side()) {
            case TOP -> assertEquals(0, p.y() + h);
            case BOTTOM -> assertEquals(oh, p.y());
            case LEFT -> assertEquals(0, p.x() + w);
            case RIGHT -> assertEquals(ow, p.x());
            default -> throw new AssertionError(p);
        }
        // The shortest way out: no other side is strictly closer.
        double moved = Math.abs(p.x() - x) + Math.abs(p.y() - y);
        double least = Math.min(Math.min(y + h, oh - y), Math.min(x + w, ow - x));
        assertEquals(least, moved);
        // Translation invariant, far from the origin.
        Snap.Push far = Snap.pushOut(x + dx, y + dy, w, h, dx, dy, ow, oh);
        assertEquals(new Snap.Push(p.x() + dx, p.y() + dy, p.side()), far);
    }

    @Property
    void pushOut_bothOrders_oppositeSides(
            @ForAll @IntRange(min = -50, max = 50) int x, @ForAll @IntRange(min = -50, max = 50) int y,
            @ForAll @IntRange(min = 0, max = 60) int w, @ForAll @IntRange(min = 0, max = 60) int h,
            @ForAll @IntRange(min = 0, max = 60) int ow, @ForAll @IntRange(min = 0, max = 60) int oh) {
        Assume.that(Collide.rectRect(x, y, w, h, 0, 0, ow, oh));
        int[] depths = {y + h, oh - y, x + w, ow - x};
        int least = Math.min(Math.min(depths[0], depths[1]), Math.min(depths[2], depths[3]));
        Assume.that(java.util.Arrays.stream(depths).filter(d -> d == least).count() == 1);
        Snap.Push ab = Snap.pushOut(x, y, w, h, 0, 0, ow, oh);
        Snap.Push ba = Snap.pushOut(0, 0, ow, oh, x, y, w, h);
        assertEquals(opposite(ab.side()), ba.side());
        // Equal and opposite moves (compared with ==, where 0 and -0 are the same).
        assertTrue(ab.x() - x == -ba.x(), () -> ab + " vs " + ba);
        assertTrue(ab.y() - y == -ba.y(), () -> ab + " vs " + ba);
    }

    private static Side opposite(Side s) {
        return switch (s) {
            case TOP -> Side.BOTTOM;
            case BOTTOM -> Side.TOP;
            case LEFT -> Side.RIGHT;
            case RIGHT -> Side.LEFT;
            case NONE -> Side.NONE;
        };
    }

    // ---- pushBack ---------------------------------------------------------------------

    @ParameterizedTest(name = "[{0},{1},{2},{3}] moving ({4},{5}) into [{6},{7},{8},{9}]: ({10}, {11}) {12}")
    @CsvSource({
            // mover after the move   speed    obstacle            result
            "50, 98, 20, 20,    0, 30,    0, 100, 200, 10,    50, 80, TOP",    // fast faller lands
            "50, 98, 20, 20,    0, -30,   0, 100, 200, 10,    50, 110, BOTTOM",
            "-5, -2, 10, 10,    10, 10,   0, 0, 100, 100,     -10, -2, LEFT",  // entered through the left last
            "-2, -5, 10, 10,    10, 10,   0, 0, 100, 100,     -2, -10, TOP",
            "-5, -5, 10, 10,    10, 10,   0, 0, 100, 100,     -5, -10, TOP",   // exactly at the corner: TOP
            "-8, 98, 10, 10,    5, 0,     0, 0, 100, 100,     -10, 98, LEFT",  // pushOut would say BOTTOM
            "10, -5, 10, 10,    0, -3,    0, 0, 100, 20,      10, 20, BOTTOM", // the speed is trusted
            "10, -5, 10, 10,    0, 0,     0, 0, 100, 20,      10, -10, TOP",   // no speed: pushOut
            "10, -10, 10, 10,   0, 30,    0, 0, 100, 20,      10, -10, NONE",  // touching
            "1000050, 98, 20, 20, 0, 30,  1000000, 100, 200, 10, 1000050, 80, TOP",
    })
    void pushBack_table(float x, float y, float w, float h, float vx, float vy,
                        float ox, float oy, float ow, float oh, float ex, float ey, Side side) {
        Snap.Push expected = new Snap.Push(ex, ey, side);
        assertEquals(expected, Snap.pushBack(x, y, w, h, vx, vy, ox, oy, ow, oh));
    }

    @Test
    void pushBack_fastFaller_pushOutPicksTheWrongSide() {
        // Why pushBack exists: 18 px in from the top, 12 px from the bottom.
        assertEquals(Side.BOTTOM, Snap.pushOut(50, 98, 20, 20, 0, 100, 200, 10).side());
        assertEquals(Side.TOP, Snap.pushBack(50, 98, 20, 20, 0, 30, 0, 100, 200, 10).side());
    }

    @Property
    void pushBack_leavesTheRectsTouchingNotOverlapping(@ForAll @FloatRange(min = -200, max = 200) float x,
                                                       @ForAll @FloatRange(min = -200, max = 200) float y,
                                                       @ForAll @FloatRange(min = 0, max = 300) float w,
                                                       @ForAll @FloatRange(min = 0, max = 300) float h,
                                                       @ForAll @FloatRange(min = -50, max = 50) float vx,
                                                       @ForAll @FloatRange(min = -50, max = 50) float vy,
                                                       @ForAll @FloatRange(min = -200, max = 200) float ox,
                                                       @ForAll @FloatRange(min = -200, max = 200) float oy,
                                                       @ForAll @FloatRange(min = 0, max = 300) float ow,
                                                       @ForAll @FloatRange(min = 0, max = 300) float oh) {
        Snap.Push p = Snap.pushBack(x, y, w, h, vx, vy, ox, oy, ow, oh);
        assertTouchingNotOverlapping(p, x, y, w, h, ox, oy, ow, oh);
    }

    @Property(tries = 3000, maxDiscardRatio = 10)
    void pushBack_exitsThroughTheSideItCameFrom(
            @ForAll @IntRange(min = -30, max = 40) int x, @ForAll @IntRange(min = -30, max = 40) int y,
            @ForAll @IntRange(min = 0, max = 30) int w, @ForAll @IntRange(min = 0, max = 30) int h,
            @ForAll @IntRange(min = -40, max = 40) int vx, @ForAll @IntRange(min = -40, max = 40) int vy,
            @ForAll @IntRange(min = 0, max = 40) int ow, @ForAll @IntRange(min = 0, max = 40) int oh) {
        // This frame's move went from (x0, y0), outside the obstacle (0, 0, ow, oh), to
        // (x, y), overlapping it.
        Assume.that(Collide.rectRect(x, y, w, h, 0, 0, ow, oh));
        int x0 = x - vx, y0 = y - vy;
        Assume.that(!Collide.rectRect(x0, y0, w, h, 0, 0, ow, oh));
        Snap.Push p = Snap.pushBack(x, y, w, h, vx, vy, 0, 0, ow, oh);
        switch (p.side()) {
            case TOP -> assertTrue(y0 + h <= 0, "landed, so it was above");
            case BOTTOM -> assertTrue(y0 >= oh, "hit its head, so it was below");
            case LEFT -> assertTrue(x0 + w <= 0, "hit the left side, so it was to the left");
            case RIGHT -> assertTrue(x0 >= ow, "hit the right side, so it was to the right");
            case NONE -> throw new AssertionError("overlapping, so it must be pushed");
        }
    }

    @Property
    void pushBack_withoutSpeedIsPushOut(@ForAll @IntRange(min = -100, max = 100) int x,
                                        @ForAll @IntRange(min = -100, max = 100) int y,
                                        @ForAll @IntRange(min = 0, max = 80) int w,
                                        @ForAll @IntRange(min = 0, max = 80) int h) {
        assertEquals(Snap.pushOut(x, y, w, h, 0, 0, 50, 30), Snap.pushBack(x, y, w, h, 0, 0, 0, 0, 50, 30));
    }

    /** {@code actual} is {@code exact}, or within one float step of it. */
    private static void assertWithinAStep(float actual, BigDecimal exact) {
        BigDecimal gap = exact.subtract(new BigDecimal(actual)).abs();
        assertTrue(gap.compareTo(new BigDecimal(Math.ulp(actual))) <= 0,
                () -> actual + " is more than a float step from " + exact);
    }

    /** Not overlapping after the push; if pushed, the edges meet to within one float step. */
    private static void assertTouchingNotOverlapping(Snap.Push p, float x, float y, float w, float h,
                                                     float ox, float oy, float ow, float oh) {
        assertFalse(Collide.rectRect(p.x(), p.y(), w, h, ox, oy, ow, oh), () -> "still overlapping: " + p);
        boolean overlapped = Collide.rectRect(x, y, w, h, ox, oy, ow, oh);
        assertEquals(overlapped, p.hit());
        switch (p.side()) {
            case NONE -> {
                assertEquals(x, p.x());
                assertEquals(y, p.y());
            }
            case TOP -> {
                assertWithinAStep(p.y(), bd(oy).subtract(bd(h)));
                assertEquals(x, p.x(), "the other axis is not moved");
            }
            case BOTTOM -> {
                assertWithinAStep(p.y(), bd(oy).add(bd(oh)));
                assertEquals(x, p.x());
            }
            case LEFT -> {
                assertWithinAStep(p.x(), bd(ox).subtract(bd(w)));
                assertEquals(y, p.y());
            }
            case RIGHT -> {
                assertWithinAStep(p.x(), bd(ox).add(bd(ow)));
                assertEquals(y, p.y());
            }
        }
    }

    private static BigDecimal bd(float f) {
        return new BigDecimal(f);
    }

    // ---- the Push record --------------------------------------------------------------

    @ParameterizedTest(name = "{0}: vxAfter({1}) = {2}, vyAfter({3}) = {4}")
    @CsvSource({
            "NONE, 3, 3, 4, 4",
            "TOP, 3, 3, 4, 0",      // landed: stop falling, keep walking
            "TOP, 3, 3, -4, -4",    // already jumping up: keep it
            "BOTTOM, 3, 3, -4, 0",  // hit its head: stop rising
            "BOTTOM, 3, 3, 4, 4",
            "LEFT, 3, 0, 4, 4",     // walked into the wall from the left
            "LEFT, -3, -3, 4, 4",
            "RIGHT, -3, 0, 4, 4",
            "RIGHT, 3, 3, 4, 4",
    })
    void push_speedsAfter(Side side, float vx, float vxAfter, float vy, float vyAfter) {
        Snap.Push p = new Snap.Push(1, 2, side);
        assertEquals(vxAfter, p.vxAfter(vx));
        assertEquals(vyAfter, p.vyAfter(vy));
        assertEquals(side != Side.NONE, p.hit());
        assertEquals(side == Side.TOP, p.landed());
    }

    @Test
    void push_applyTo_movesTheMover() {
        Rect mover = new Rect(10, -5, 10, 12);
        Snap.Push p = Snap.pushOut(mover.x(), mover.y(), mover.w(), mover.h(), 0, 0, 100, 20);
        assertEquals(new Rect(10, -12, 10, 12), p.applyTo(mover));
    }

    @Test
    void badInput_isNamed() {
        assertEquals("side must not be null",
                assertThrows(IllegalArgumentException.class, () -> new Snap.Push(0, 0, null)).getMessage());
        assertEquals("mover must not be null",
                assertThrows(IllegalArgumentException.class, () -> new Snap.Push(0, 0, Side.TOP).applyTo(null)).getMessage());
    }

    @Test
    void nan_isNoPush() {
        Snap.Push p = Snap.pushOut(Float.NaN, 0, 10, 10, 0, 0, 10, 10);
        assertEquals(Side.NONE, p.side());
        assertTrue(Float.isNaN(p.x()));
        assertEquals(Side.NONE, Snap.pushBack(0, Float.NaN, 10, 10, 1, 1, 0, 0, 10, 10).side());
        assertFalse(Snap.onGround(Float.NaN, 10, 100));
    }

    // ---- a negative height: no answer, as for NaN (the package's bad-input rule) ----------

    @ParameterizedTest(name = "y {0}, h {1}, ground {2}")
    @CsvSource({
            "120, -10, 100",   // below the ground with a negative height
            "95, -10, 100",
            "80, -0.5, 100",
            "0, -1e30, 0",
    })
    void negativeHeight_noStandNoGroundYUnchanged(float y, float h, float groundY) {
        assertTrue(Float.isNaN(Snap.standY(h, groundY)));
        assertFalse(Snap.onGround(y, h, groundY));
        assertEquals(y, Snap.landY(y, h, groundY));
        // A height of 0 (and -0) is a flat rectangle, answered as one.
        assertEquals(groundY, Snap.standY(-0f, groundY));
        assertEquals(groundY, Snap.landY(y + 1000, 0, groundY));
    }
}
