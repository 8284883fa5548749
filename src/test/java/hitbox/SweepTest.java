package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Swept tests, one table per pair of shapes. Every row is also checked with the roles swapped
 * (the obstacle moving back into the mover: the normal turned round) and moved by a million
 * pixels. The table's time is the exact time of impact; the sweep's float {@code t} is
 * checked by {@link SketchT}: the mover moved as a sketch moves it is clear at t and overlaps
 * at the next float, within the positions' rounding of the exact time. An expected time of
 * Infinity means no hit (null for the Hit methods).
 */
class SweepTest {

    @Test
    void rectSegmentHit_segmentEndCrossesTheBoxCornerBriefly_isAHit() {
        // Found by SweepPropertiesTest: the end (4, -4.5) is strictly inside the moving box
        // only for t in (3/44, 4/58.5), a window of 0.0002 of the frame. Still a hit.
        Hit hit = Raw.sweepRectSegmentHit(0, -8, 0.5f, 0.5f, 58.5f, 44, 0, 0, 4, -4.5f);
        assertNotNull(hit);
        assertEquals(3 / 44f, hit.t(), 1e-6f);
        float t = (3 / 44f + 4 / 58.5f) / 2;
        assertTrue(Collide.rectPoint(58.5f * t, -8 + 44 * t, 0.5f, 0.5f, 4, -4.5f), "inside in the window");
    }


    private static final float FAR = 1_000_000f;

    // ------------------------------------------------------------------ rect and rect

    @ParameterizedTest(name = "[{index}] {12}")
    @CsvSource({
            // x, y, w, h, vx, vy, ox, oy, ow, oh, t, side, scenario
            "0, 0, 10, 10, 20, 0, 15, 0, 10, 10, 0.25, LEFT, from the left",
            "30, 0, 10, 10, -20, 0, 15, 0, 10, 10, 0.25, RIGHT, from the right",
            "0, 0, 10, 10, 0, 20, 0, 15, 10, 10, 0.25, TOP, falling onto it",
            "0, 30, 10, 10, 0, -20, 0, 15, 10, 10, 0.25, BOTTOM, jumping into it",
            "0, 0, 10, 10, 6, 0, 15, 0, 10, 10, 0.8333333333333334, LEFT, a fraction",
            "0, 0, 10, 10, 5, 0, 10, 0, 10, 10, 0, LEFT, touching and moving in",
            "0, 0, 10, 10, -5, 0, 10, 0, 10, 10, Infinity, NONE, touching and moving away",
            "0, 0, 10, 10, 0, 5, 10, 0, 10, 10, Infinity, NONE, touching and sliding along the side",
            "0, 0, 10, 10, 30, 0, 15, 10, 10, 10, Infinity, NONE, grazing along the top edge",
            "0, 0, 10, 10, 5, 0, 15, 0, 10, 10, Infinity, NONE, reaching it only at the end",
            "0, 0, 10, 10, 5, 5, 5, 5, 10, 10, 0, NONE, already overlapping",
            "0, 0, 10, 10, -50, 0, 5, 5, 10, 10, 0, NONE, already overlapping and moving away",
            "0, 0, 10, 10, 0, 0, 5, 5, 10, 10, 0, NONE, already overlapping and standing still",
            "0, 0, 10, 10, 0, 0, 20, 0, 10, 10, Infinity, NONE, standing still apart",
            "0, 0, 10, 10, 0, 0, 10, 0, 10, 10, Infinity, NONE, standing still touching",
            "0, 0, 10, 10, -20, 0, 15, 0, 10, 10, Infinity, NONE, obstacle behind",
            "0, 0, 10, 10, 20, 20, 20, 0, 10, 10, Infinity, NONE, passing a corner that it only touches",
            "0, 0, 10, 10, 20, 20, 20, 20, 10, 10, 0.5, TOP, exactly onto the corner counts as landing",
            "20, 20, 10, 10, -20, -20, 0, 0, 10, 10, 0.5, BOTTOM, exactly into the corner from below",
            "0, 0, 10, 10, 1, 1, 10, 10, 10, 10, 0, TOP, corner to corner and moving in",
            "0, 0, 10, 10, 1, -1, 10, 10, 10, 10, Infinity, NONE, corner to corner and moving past",
            "0, 0, 10, 10, 40, 10, 20, 5, 10, 10, 0.25, LEFT, diagonal into a side",
            "0, 0, 10, 10, 40, 10, 20, 15, 10, 10, 0.5, TOP, diagonal onto a top",
            "0, 0, 2, 2, 10000, 0, 5000, 0, 1, 2, 0.4998, LEFT, tiny and very fast into a thin wall",
            "0, 0, 2, 2, 10000, 0, 5000, 0, 0.5, 2, 0.4998, LEFT, into a half-pixel wall",
            "0, 5, 0, 0, 20, 0, 10, 0, 10, 10, 0.5, LEFT, a point into a box",
            "0, 0, 0, 0, 20, 0, 10, 0, 10, 10, Infinity, NONE, a point along an edge",
            "0, 5, 0, 0, 20, 0, 10, 0, 0, 10, Infinity, NONE, a point through a zero-width box",
            "0, 0, 0, 10, 20, 0, 10, 2, 0, 6, Infinity, NONE, zero-width through zero-width",
            "0, 0, 0, 10, 20, 0, 10, 2, 5, 6, 0.5, LEFT, zero-width into a box",
    })
    void rectRect_table(float x, float y, float w, float h, float vx, float vy,
                        float ox, float oy, float ow, float oh, double t, Side side, String scenario) {
        double near = SketchT.plateau(vx, vy, x, y, ox, oy, x + w, y + h, ox + ow, oy + oh);
        SketchT.check(t, Sweep.rectRect(x, y, w, h, vx, vy, ox, oy, ow, oh),
                s -> Collide.rectRect(x + s * vx, y + s * vy, w, h, ox, oy, ow, oh), near, "mover, obstacle");
        SketchT.check(t, Sweep.rectRect(ox, oy, ow, oh, -vx, -vy, x, y, w, h),
                s -> Collide.rectRect(ox + s * -vx, oy + s * -vy, ow, oh, x, y, w, h), near, "roles swapped");
        float fx = x + FAR, fy = y - FAR, fox = ox + FAR, foy = oy - FAR;
        SketchT.check(t, Sweep.rectRect(fx, fy, w, h, vx, vy, fox, foy, ow, oh),
                s -> Collide.rectRect(fx + s * vx, fy + s * vy, w, h, fox, foy, ow, oh),
                SketchT.plateau(vx, vy, FAR), "far away");

        Hit hit = Sweep.timeOfImpact(new Rect(x, y, w, h), vx, vy, new Rect(ox, oy, ow, oh));
        Hit back = Sweep.timeOfImpact(new Rect(ox, oy, ow, oh), -vx, -vy, new Rect(x, y, w, h));
        checkHit(t, near, side, hit);
        checkReversed(hit, back);
        assertEquals(hit, Raw.sweepRectRectHit(x, y, w, h, vx, vy, ox, oy, ow, oh));
    }

    @ParameterizedTest
    @CsvSource({
            "0, 0, 10, 10, 5, 5, 10, 10",
            "0, 0, 10, 10, 10, 0, 10, 10",
            "0, 0, 10, 10, 9.5, 9.5, 1, 1",
            "0, 0, 0, 0, 5, 5, 10, 10",
            "0, 0, 0, 0, 0, 0, 0, 0",
    })
    void rectRect_zeroIffCollideAtStart(float x, float y, float w, float h, float ox, float oy, float ow, float oh) {
        boolean overlapping = Collide.rectRect(x, y, w, h, ox, oy, ow, oh);
        for (float[] v : new float[][] {{0, 0}, {-3, 0}, {0, -3}, {3, 3}, {-7, 2}}) {
            float t = Sweep.rectRect(x, y, w, h, v[0], v[1], ox, oy, ow, oh);
            if (overlapping) {
                assertEquals(0f, t);
            } else {
                assertTrue(t > 0 || touchingAndMovingIn(x, y, w, h, v[0], v[1], ox, oy, ow, oh), "t = " + t);
            }
        }
    }

    private static boolean touchingAndMovingIn(float x, float y, float w, float h, float vx, float vy,
                                               float ox, float oy, float ow, float oh) {
        // A tiny step along the motion overlaps.
        return Collide.rectRect(x + vx * 1e-3f, y + vy * 1e-3f, w, h, ox, oy, ow, oh);
    }

    @Test
    void rectRect_nanOrInfiniteVelocity_noHit() {
        assertEquals(Float.POSITIVE_INFINITY, Sweep.rectRect(0, 0, 10, 10, Float.NaN, 0, 15, 0, 10, 10));
        assertEquals(Float.POSITIVE_INFINITY, Sweep.rectRect(0, 0, 10, 10, Float.POSITIVE_INFINITY, 0, 15, 0, 10, 10));
        assertEquals(Float.POSITIVE_INFINITY, Sweep.rectRect(0, 0, 10, 10, 0, Float.NaN, 0, 15, 10, 10));
        assertEquals(Float.POSITIVE_INFINITY, Sweep.rectRect(Float.NaN, 0, 10, 10, 20, 0, 15, 0, 10, 10));
        assertThrows(IllegalArgumentException.class, () -> Raw.sweepRectRectHit(0, 0, 10, 10, Float.NaN, 0, 15, 0, 10, 10),
                "on shapes a NaN velocity is refused");
    }

    // ------------------------------------------------------------------ circle and circle

    @ParameterizedTest(name = "[{index}] {10}")
    @CsvSource({
            // x, y, r, vx, vy, ox, oy, or, t, side, scenario
            "0, 0, 1, 10, 0, 10, 0, 1, 0.8, LEFT, head on from the left",
            "0, 0, 1, 0, 10, 0, 10, 1, 0.8, TOP, falling onto it",
            "0, 0, 1, 6, 8, 6, 8, 4, 0.5, TOP, three-four-five",
            "0, 0, 1, 10, 0, 5, 1, 1, 0.32679491924311227, LEFT, off centre",
            "0, 0, 1, 1, 0, 2, 0, 1, 0, LEFT, touching and moving in",
            "0, 0, 1, -1, 0, 2, 0, 1, Infinity, NONE, touching and moving away",
            "0, 0, 1, 0, 10, 2, 0, 1, Infinity, NONE, touching and moving sideways",
            "0, 0, 1, 10, 0, 5, 2, 1, Infinity, NONE, path grazes the outline",
            "0, 0, 1, 8, 0, 10, 0, 1, Infinity, NONE, reaching it only at the end",
            "0, 0, 1, 0, 0, 1, 0, 1, 0, NONE, already overlapping",
            "0, 0, 1, -9, 0, 1, 0, 1, 0, NONE, already overlapping and moving away",
            "0, 0, 1, 0, 0, 10, 0, 1, Infinity, NONE, standing still apart",
            "0, 0, 1, -10, 0, 10, 0, 1, Infinity, NONE, obstacle behind",
            "0, 0, 0, 10, 0, 10, 0, 2, 0.8, LEFT, a point into a circle",
            "0, 0, 0, 10, 0, 5, 0, 0, Infinity, NONE, a point through a point",
            "0, 0, 0, 0, 0, 0, 0, 0, Infinity, NONE, a point on a point",
            "0, 0, 1, 10000, 0, 5000, 0, 0.5, 0.49985, LEFT, tiny and very fast",
    })
    void circleCircle_table(float x, float y, float r, float vx, float vy, float ox, float oy, float or,
                            double t, Side side, String scenario) {
        double near = SketchT.plateau(vx, vy, x, y, ox, oy, r, or);
        float got = Raw.sweepCircleCircle(x, y, r, vx, vy, ox, oy, or);
        SketchT.check(t, got, s -> Collide.circleCircle(x + s * vx, y + s * vy, r, ox, oy, or), near, "mover, obstacle");
        SketchT.check(t, Raw.sweepCircleCircle(ox, oy, or, -vx, -vy, x, y, r),
                s -> Collide.circleCircle(ox + s * -vx, oy + s * -vy, or, x, y, r), near, "roles swapped");
        float fx = x + FAR, fy = y - FAR, fox = ox + FAR, foy = oy - FAR;
        SketchT.check(t, Raw.sweepCircleCircle(fx, fy, r, vx, vy, fox, foy, or),
                s -> Collide.circleCircle(fx + s * vx, fy + s * vy, r, fox, foy, or), SketchT.plateau(vx, vy, FAR), "far away");
        assertEquals(Collide.circleCircle(x, y, r, ox, oy, or), side == Side.NONE && got == 0, "t = 0 for overlap");

        Hit hit = Sweep.timeOfImpact(new Circle(x, y, r), vx, vy, new Circle(ox, oy, or));
        Hit back = Sweep.timeOfImpact(new Circle(ox, oy, or), -vx, -vy, new Circle(x, y, r));
        checkHit(t, near, side, hit);
        checkReversed(hit, back);
    }

    @Test
    void circleCircleHit_normalPointsFromMoverIntoObstacle() {
        Hit hit = Raw.sweepCircleCircleHit(0, 0, 1, 6, 8, 6, 8, 4);
        assertEquals(0.6f, hit.nx(), 1e-6f);
        assertEquals(0.8f, hit.ny(), 1e-6f);
    }

    // ------------------------------------------------------------------ circle and rect

    @ParameterizedTest(name = "[{index}] {11}")
    @CsvSource({
            // cx, cy, r, vx, vy, rx, ry, rw, rh, t, side, scenario
            "0, 5, 1, 20, 0, 10, 0, 1, 10, 0.45, LEFT, into a wall face",
            "15, 5, 1, -10, 0, 0, 0, 10, 10, 0.4, RIGHT, from the right",
            "5, -5, 1, 0, 10, 0, 0, 10, 10, 0.4, TOP, falling onto it",
            "5, 15, 1, 0, -10, 0, 0, 10, 10, 0.4, BOTTOM, from below",
            "0, 5, 1, 10000, 0, 5000, 0, 0.5, 10, 0.4999, LEFT, fast ball into a half-pixel wall",
            "0, 0, 1, 10, 10, 5, 5, 10, 10, 0.42928932188134527, TOP, onto the corner (45 degrees)",
            "0, -1, 1, 20, 0, 5, 0, 10, 10, Infinity, NONE, rolling along the top",
            "9, 5, 1, 1, 0, 10, 0, 1, 10, 0, LEFT, touching a face and moving in",
            "9, 0, 1, 1, 0, 10, 0, 1, 10, 0, LEFT, touching a corner and moving in",
            "9, 5, 1, -1, 0, 10, 0, 1, 10, Infinity, NONE, touching and moving away",
            "9, 5, 1, 0, 0, 10, 0, 1, 10, Infinity, NONE, touching and standing still",
            "10, 5, 1, 0, 0, 10, 0, 1, 10, 0, NONE, already overlapping",
            "0, 5, 1, 9, 0, 10, 0, 1, 10, Infinity, NONE, reaching it only at the end",
            "0, 5, 0, 20, 0, 10, 0, 10, 10, 0.5, LEFT, a point into a box",
            "0, 0, 0, 20, 0, 10, 0, 10, 10, Infinity, NONE, a point along an edge",
            "0, 5, 1, 20, 0, 10, 0, 0, 10, 0.45, LEFT, into a zero-width box",
            "0, 5, 0, 20, 0, 10, 0, 0, 10, Infinity, NONE, a point through a zero-width box",
            "0, 0, 1, 20, 0, 10, 0, 0, 0, 0.45, LEFT, into a zero-size box",
    })
    void circleRect_table(float cx, float cy, float r, float vx, float vy, float rx, float ry, float rw, float rh,
                          double t, Side side, String scenario) {
        double near = SketchT.plateau(vx, vy, cx, cy, r, rx, ry, rx + rw, ry + rh);
        Hit hit = Raw.sweepCircleRectHit(cx, cy, r, vx, vy, rx, ry, rw, rh);
        checkHit(t, near, side, hit);
        if (hit != null) {
            SketchT.check(t, hit.t(), s -> Collide.circleRect(cx + s * vx, cy + s * vy, r, rx, ry, rw, rh), near, "t");
        }
        assertEquals(hit, Sweep.timeOfImpact(new Circle(cx, cy, r), vx, vy, new Rect(rx, ry, rw, rh)));
        Hit back = Sweep.timeOfImpact(new Rect(rx, ry, rw, rh), -vx, -vy, new Circle(cx, cy, r));
        checkReversed(hit, back);
        if (back != null) {
            SketchT.check(t, back.t(), s -> Collide.circleRect(cx, cy, r, rx + s * -vx, ry + s * -vy, rw, rh), near, "roles swapped");
        }
        float fcx = cx + FAR, fcy = cy - FAR, frx = rx + FAR, fry = ry - FAR;
        Hit far = Raw.sweepCircleRectHit(fcx, fcy, r, vx, vy, frx, fry, rw, rh);
        checkHit(t, SketchT.plateau(vx, vy, FAR), side, far);
        if (far != null) {
            SketchT.check(t, far.t(), s -> Collide.circleRect(fcx + s * vx, fcy + s * vy, r, frx, fry, rw, rh),
                    SketchT.plateau(vx, vy, FAR), "far away");
        }
    }

    @Test
    void circleRectHit_cornerNormalPointsFromCentreToCorner() {
        Hit hit = Raw.sweepCircleRectHit(0, 0, 1, 10, 10, 5, 5, 10, 10);
        assertEquals(0.70710678f, hit.nx(), 1e-6f);
        assertEquals(0.70710678f, hit.ny(), 1e-6f);
        // Just off the diagonal the corner normal leans to one side.
        Hit wall = Raw.sweepCircleRectHit(0, 1, 1, 10, 10, 5, 5, 10, 10);
        assertEquals(Side.LEFT, wall.side());
    }

    // ------------------------------------------------------------------ rect and segment

    @ParameterizedTest(name = "[{index}] {12}")
    @CsvSource({
            // x, y, w, h, vx, vy, x1, y1, x2, y2, t, side, scenario
            "0, 0, 2, 2, 10, 0, 5, -5, 5, 5, 0.3, LEFT, into a vertical line",
            "0, 0, 2, 2, 10000, 0, 5000, -1, 5000, 3, 0.4998, LEFT, very fast into a vertical line",
            "0, 0, 2, 2, 0, 10, -5, 5, 5, 5, 0.3, TOP, falling onto a horizontal line",
            "0, 0, 2, 2, 0, 10, 0, 10, 10, 0, 0.6, TOP, falling onto a slope",
            "0, 0, 2, 2, 0, 10, 10, 0, 0, 10, 0.6, TOP, falling onto a slope given the other way",
            "9, -12, 2, 2, 0, 20, 0, 10, 10, 0, 0.5, TOP, landing on the top end of a slope",
            "8, 0, 2, 2, 0, 10, 0, 10, 10, 0, 0, NONE, a slope through the box",
            "0, 0, 2, 2, 10, 0, 5, 2, 10, 2, Infinity, NONE, grazing along a line",
            "0, 0, 2, 2, 10, 0, 5, 2, 5, 10, Infinity, NONE, grazing a line's end",
            "0, 0, 2, 2, 1, 0, 2, -1, 2, 3, 0, LEFT, touching and moving in",
            "0, 0, 2, 2, -1, 0, 2, -1, 2, 3, Infinity, NONE, touching and moving away",
            "0, 0, 4, 4, 0, 0, 1, 1, 2, 2, 0, NONE, already overlapping",
            "0, 0, 4, 4, 7, 0, 1, 1, 2, 2, 0, NONE, already overlapping and moving",
            "0, 0, 0, 2, 10, 0, 5, -5, 5, 5, Infinity, NONE, a zero-width box never hits a line",
            "0, 0, 2, 2, 10, 0, 5, 1, 5, 1, 0.3, LEFT, into a line of length 0",
            "0, 0, 2, 2, -10, 0, 5, -5, 5, 5, Infinity, NONE, moving away",
            "0, 0, 2, 2, 3, 0, 5, -5, 5, 5, Infinity, NONE, reaching it only at the end",
    })
    void rectSegment_table(float x, float y, float w, float h, float vx, float vy,
                           float x1, float y1, float x2, float y2, double t, Side side, String scenario) {
        double near = SketchT.plateau(vx, vy, x, y, x + w, y + h, x1, y1, x2, y2);
        Hit hit = Raw.sweepRectSegmentHit(x, y, w, h, vx, vy, x1, y1, x2, y2);
        checkHit(t, near, side, hit);
        if (hit != null) {
            SketchT.check(t, hit.t(), s -> Collide.lineRect(x1, y1, x2, y2, x + s * vx, y + s * vy, w, h), near, "t");
        }
        assertEquals(hit, Sweep.timeOfImpact(new Rect(x, y, w, h), vx, vy, new Segment(x1, y1, x2, y2)));
        Hit back = Sweep.timeOfImpact(new Segment(x1, y1, x2, y2), -vx, -vy, new Rect(x, y, w, h));
        checkReversed(hit, back);
        if (back != null) {
            SketchT.check(t, back.t(), s -> Collide.lineRect(x1 - s * vx, y1 - s * vy, x2 - s * vx, y2 - s * vy, x, y, w, h),
                    near, "roles swapped");
        }
        float fx = x + FAR, fy = y - FAR;
        Hit far = Raw.sweepRectSegmentHit(fx, fy, w, h, vx, vy, x1 + FAR, y1 - FAR, x2 + FAR, y2 - FAR);
        checkHit(t, SketchT.plateau(vx, vy, FAR), side, far);
        if (far != null) {
            float fx1 = x1 + FAR, fy1 = y1 - FAR, fx2 = x2 + FAR, fy2 = y2 - FAR;
            SketchT.check(t, far.t(), s -> Collide.lineRect(fx1, fy1, fx2, fy2, fx + s * vx, fy + s * vy, w, h),
                    SketchT.plateau(vx, vy, FAR), "far away");
        }
    }

    @Test
    void rectSegmentHit_slopeNormalIsPerpendicular() {
        Hit hit = Raw.sweepRectSegmentHit(0, 0, 2, 2, 0, 10, 0, 10, 10, 0);
        assertEquals(0.70710678f, hit.nx(), 1e-6f);
        assertEquals(0.70710678f, hit.ny(), 1e-6f);
    }

    // ------------------------------------------------------------------ circle and segment

    @ParameterizedTest(name = "[{index}] {10}")
    @CsvSource({
            // cx, cy, r, vx, vy, x1, y1, x2, y2, t, side, scenario
            "0, 0, 1, 10, 0, 5, -5, 5, 5, 0.4, LEFT, into a vertical line",
            "0, 0, 1, 10000, 0, 5000, -5, 5000, 5, 0.4999, LEFT, very fast into a vertical line",
            "0, 0, 1, 10, 0, 5, 0, 10, 0, 0.4, LEFT, head on into a line's end",
            "5, 0, 1, 0, 10, 0, 10, 10, 0, 0.3585786437626905, TOP, falling onto a slope",
            "0, -1, 1, 10, 0, 5, 0, 10, 0, Infinity, NONE, rolling along a line",
            "4, 0, 1, 1, 0, 5, -5, 5, 5, 0, LEFT, touching and moving in",
            "4, 0, 1, -1, 0, 5, -5, 5, 5, Infinity, NONE, touching and moving away",
            "5, 0, 1, 3, 3, 5, -5, 5, 5, 0, NONE, already overlapping",
            "0, 0, 0, 10, 0, 5, -5, 5, 5, Infinity, NONE, a point never hits a line",
            "0, 0, 1, 10, 0, 5, 0, 5, 0, 0.4, LEFT, into a line of length 0",
            "0, 0, 1, 4, 0, 5, -5, 5, 5, Infinity, NONE, reaching it only at the end",
    })
    void circleSegment_table(float cx, float cy, float r, float vx, float vy,
                             float x1, float y1, float x2, float y2, double t, Side side, String scenario) {
        double near = SketchT.plateau(vx, vy, cx, cy, r, x1, y1, x2, y2);
        Hit hit = Raw.sweepCircleSegmentHit(cx, cy, r, vx, vy, x1, y1, x2, y2);
        checkHit(t, near, side, hit);
        if (hit != null) {
            SketchT.check(t, hit.t(), s -> Collide.lineCircle(x1, y1, x2, y2, cx + s * vx, cy + s * vy, r), near, "t");
        }
        assertEquals(hit, Sweep.timeOfImpact(new Circle(cx, cy, r), vx, vy, new Segment(x1, y1, x2, y2)));
        Hit back = Sweep.timeOfImpact(new Segment(x1, y1, x2, y2), -vx, -vy, new Circle(cx, cy, r));
        checkReversed(hit, back);
        Hit far = Raw.sweepCircleSegmentHit(cx + FAR, cy - FAR, r, vx, vy, x1 + FAR, y1 - FAR, x2 + FAR, y2 - FAR);
        assertEquals(hit == null, far == null, "far away");
        if (hit != null) {
            assertEquals(hit.t(), far.t(), SketchT.plateau(vx, vy, FAR) + 1e-6, "far away");
            assertEquals(hit.side(), far.side(), "far away");
        }
    }

    // ------------------------------------------------------------------ the shape dispatcher

    @Test
    void timeOfImpact_anyShape_routesToThePairMethod() {
        Shape box = new Rect(0, 0, 2, 2), ball = new Circle(1, 1, 1), wall = new Segment(5, -5, 5, 5);
        assertEquals(Sweep.timeOfImpact((Rect) box, 10, 0, (Segment) wall), Sweep.timeOfImpact(box, 10, 0, wall));
        assertEquals(Sweep.timeOfImpact((Circle) ball, 10, 0, (Segment) wall), Sweep.timeOfImpact(ball, 10, 0, wall));
        assertEquals(Sweep.timeOfImpact((Segment) wall, -10, 0, (Circle) ball), Sweep.timeOfImpact(wall, -10, 0, ball));
        assertEquals(Sweep.timeOfImpact((Segment) wall, -10, 0, (Rect) box), Sweep.timeOfImpact(wall, -10, 0, box));
        assertEquals(Sweep.timeOfImpact((Rect) box, 10, 0, (Circle) ball.translated(6, 0)),
                Sweep.timeOfImpact(box, 10, 0, ball.translated(6, 0)));
        assertNotNull(Sweep.timeOfImpact(box, 10, 0, box.translated(5, 0)));
        assertNotNull(Sweep.timeOfImpact(ball, 10, 0, ball.translated(5, 0)));
        assertNotNull(Sweep.timeOfImpact(ball, 10, 0, box.translated(5, 0)));
    }

    /**
     * Pairs without an exact swept test (two segments, polygons) are answered too, through
     * their convex pieces: the same float t and normal a hand calculation gives (these used
     * to throw "no time of impact").
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("piecewisePairs")
    void timeOfImpact_piecewisePairs_hitWhereTheyTouch(String name, Shape mover, float vx, float vy, Shape obstacle,
                                                       float t, float nx, float ny) {
        Hit hit = Sweep.timeOfImpact(mover, vx, vy, obstacle);
        assertNotNull(hit, name);
        assertEquals(t, hit.t(), 1e-6f, name);
        assertEquals(nx, hit.nx(), 1e-5f, name);
        assertEquals(ny, hit.ny(), 1e-5f, name);
        assertFalse(Overlaps.test(mover.translated(hit.t() * vx, hit.t() * vy), obstacle), name + ": clear at t");
        assertTrue(Overlaps.test(mover.translated(Math.nextUp(hit.t()) * vx, Math.nextUp(hit.t()) * vy), obstacle),
                name + ": overlapping just after t");
        Hit back = Sweep.timeOfImpact(obstacle, -vx, -vy, mover);
        assertNotNull(back, name + " (roles swapped)");
        assertEquals(t, back.t(), 1e-5f, name + " (roles swapped)");
    }

    static Stream<Arguments> piecewisePairs() {
        Shape wall = new Segment(15, -5, 15, 5);
        Polygon triangle = Polygon.of(0, 0, 10, 0, 0, 10);
        Shape arrow = Polygon.of(0, 0, 40, 10, 15, 15, 10, 40); // concave at (15, 15)
        return Stream.of(
                // Segments are closed: touching is a hit, so t is the last float before they meet.
                Arguments.of("segment into segment", new Segment(5, 0, 5, 10), 20f, 0f, wall, 0.5f, 1f, 0f),
                Arguments.of("triangle corner into segment", triangle, 10f, 0f, wall, 0.5f, 1f, 0f),
                Arguments.of("triangle down onto a rect", triangle, 0f, 20f, new Rect(-5, 20, 30, 5), 0.5f, 0f, 1f),
                Arguments.of("concave arrow up into a rect", arrow, 0f, -40f, new Rect(-5, -30, 50, 10), 0.5f, 0f, -1f),
                Arguments.of("circle into a square polygon", new Circle(-20, 0, 5), 20f, 0f,
                        Polygon.of(0, -10, 10, -10, 10, 10, 0, 10), 0.75f, 1f, 0f),
                Arguments.of("two triangles, corner into edge", triangle, 30f, 0f, triangle.translated(25, -5), 0.5f, 1f, 0f));
    }

    @Test
    void timeOfImpact_badArguments_throwWithTheirNames() {
        Rect box = new Rect(0, 0, 2, 2);
        assertEquals("vx must be a finite number, was NaN",
                assertThrows(IllegalArgumentException.class, () -> Sweep.timeOfImpact(box, Float.NaN, 0, box)).getMessage());
        assertEquals("mover must not be null",
                assertThrows(IllegalArgumentException.class, () -> Sweep.timeOfImpact((Rect) null, 0, 0, box)).getMessage());
        assertEquals("obstacle must not be null",
                assertThrows(IllegalArgumentException.class, () -> Sweep.timeOfImpact(box, 0, 0, (Rect) null)).getMessage());
    }

    @Test
    void hit_rejectsImpossibleValues() {
        assertThrows(IllegalArgumentException.class, () -> new Hit(1.5f, 0, -1, Side.TOP));
        assertThrows(IllegalArgumentException.class, () -> new Hit(-0.1f, 0, -1, Side.TOP));
        assertThrows(IllegalArgumentException.class, () -> new Hit(Float.NaN, 0, -1, Side.TOP));
        assertThrows(IllegalArgumentException.class, () -> new Hit(0.5f, Float.NaN, -1, Side.TOP));
        assertThrows(IllegalArgumentException.class, () -> new Hit(0.5f, 0, -1, null));
    }

    // ------------------------------------------------------------------ helpers

    /**
     * A hit near the expected (exact) time, within the positions' rounding {@code near}, on the
     * expected side, or null for no hit (expected = +inf).
     */
    static void checkHit(double expected, double near, Side side, Hit hit) {
        if (expected == Double.POSITIVE_INFINITY) {
            assertNull(hit);
            return;
        }
        assertNotNull(hit, "expected a hit at " + expected);
        assertEquals(expected, hit.t(), near + 1e-6, "t");
        assertEquals(side, hit.side(), "side");
        if (side == Side.NONE) {
            assertTrue(hit.alreadyOverlapping());
            assertEquals(0f, hit.t());
            assertEquals(0f, hit.nx());
            assertEquals(0f, hit.ny());
        } else {
            assertEquals(1.0, Math.hypot(hit.nx(), hit.ny()), 1e-6, "unit normal");
            assertEquals(Side.ofNormal(hit.nx(), hit.ny()), side, "side from the normal");
        }
    }

    /**
     * The same impact seen from the obstacle: the normal turned round (t is the obstacle's
     * own float t, checked by the caller).
     */
    static void checkReversed(Hit hit, Hit back) {
        if (hit == null) {
            assertNull(back, "roles swapped");
            return;
        }
        assertNotNull(back, "roles swapped");
        assertEquals(-hit.nx(), back.nx(), 1e-6f, "roles swapped: nx");
        assertEquals(-hit.ny(), back.ny(), 1e-6f, "roles swapped: ny");
        assertEquals(hit.alreadyOverlapping(), back.alreadyOverlapping());
    }
}
