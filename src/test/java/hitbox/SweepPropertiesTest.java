package hitbox;

import hitbox.internal.*;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;

/**
 * Properties of the swept tests: the promised float t ({@link SketchT}: clear at t, overlapping
 * at the next float, within the float positions' rounding of the exact time) with the roles
 * swapped and far away, agreement with the exact reference ({@link SweepReference}), and
 * with sampling the motion at many moments. Coordinates are whole or half numbers (exact in
 * float and double); samples are allowed the rounding of the float positions.
 */
class SweepPropertiesTest {

    /** Samples at dyadic times k / 1024, so sampled positions are exact too. */
    private static final int SAMPLES = 1024;

    @Property(tries = 3000)
    void rectRect_rolesSwapped_sameTime(@ForAll @IntRange(min = -40, max = 40) int x, @ForAll @IntRange(min = -40, max = 40) int y,
                                        @ForAll @IntRange(min = 0, max = 30) int w, @ForAll @IntRange(min = 0, max = 30) int h,
                                        @ForAll @IntRange(min = -60, max = 60) int vx, @ForAll @IntRange(min = -60, max = 60) int vy,
                                        @ForAll @IntRange(min = -40, max = 40) int ox, @ForAll @IntRange(min = -40, max = 40) int oy,
                                        @ForAll @IntRange(min = 0, max = 30) int ow, @ForAll @IntRange(min = 0, max = 30) int oh) {
        SweepReference.Q q = SweepReference.rectRect(x, y, w, h, vx, vy, ox, oy, ow, oh);
        double exact = q == null ? Double.POSITIVE_INFINITY : q.value();
        double near = SketchT.plateau(vx, vy, x, y, ox, oy, x + w, y + h, ox + ow, oy + oh);
        SketchT.check(exact, Sweep.rectRect(x, y, w, h, vx, vy, ox, oy, ow, oh),
                s -> Collide.rectRect(x + s * vx, y + s * vy, w, h, ox, oy, ow, oh), near, "mover, obstacle");
        SketchT.check(exact, Sweep.rectRect(ox, oy, ow, oh, -vx, -vy, x, y, w, h),
                s -> Collide.rectRect(ox + s * -vx, oy + s * -vy, ow, oh, x, y, w, h), near, "roles swapped");
    }

    /**
     * Found by the property below: moved near (1e6, -7.5e5), where a float step is 1/16 px,
     * the paths overlap for about 0.002 of the move, shorter than the positions stand still,
     * so no float position overlaps: a graze, t = 1 (SketchT checks every float near the entry).
     */
    @Test
    void rectRect_translatedFarAway_grazeFound() {
        rectRect_translatedByWholeNumbers_sameTime(37, -33, 20, 21, 37, 15, 32, -10, 919031, -752857);
        assertEquals(1f, Sweep.rectRect(37 + 919031, -33 - 752857, 20, 21, 37, 15, 32 + 919031, -10 - 752857, 10, 10));
    }

    @Property(tries = 3000)
    void rectRect_translatedByWholeNumbers_sameTime(@ForAll @IntRange(min = -40, max = 40) int x, @ForAll @IntRange(min = -40, max = 40) int y,
                                                    @ForAll @IntRange(min = 0, max = 30) int w, @ForAll @IntRange(min = 0, max = 30) int h,
                                                    @ForAll @IntRange(min = -60, max = 60) int vx, @ForAll @IntRange(min = -60, max = 60) int vy,
                                                    @ForAll @IntRange(min = -40, max = 40) int ox, @ForAll @IntRange(min = -40, max = 40) int oy,
                                                    @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
                                                    @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        SweepReference.Q q = SweepReference.rectRect(x, y, w, h, vx, vy, ox, oy, 10, 10);
        double exact = q == null ? Double.POSITIVE_INFINITY : q.value();
        float fx = x + dx, fy = y + dy, fox = ox + dx, foy = oy + dy;
        SketchT.check(exact, Sweep.rectRect(fx, fy, w, h, vx, vy, fox, foy, 10, 10),
                s -> Collide.rectRect(fx + s * vx, fy + s * vy, w, h, fox, foy, 10, 10),
                SketchT.plateau(vx, vy, fx, fy, fox, foy, fx + w, fy + h, fox + 10, foy + 10), "translated");
    }

    @Property(tries = 5000)
    void rectRect_matchesExactReference(@ForAll @IntRange(min = -80, max = 80) int x2, @ForAll @IntRange(min = -80, max = 80) int y2,
                                        @ForAll @IntRange(min = 0, max = 40) int w2, @ForAll @IntRange(min = 0, max = 40) int h2,
                                        @ForAll @IntRange(min = -120, max = 120) int vx2, @ForAll @IntRange(min = -120, max = 120) int vy2,
                                        @ForAll @IntRange(min = -80, max = 80) int ox2, @ForAll @IntRange(min = -80, max = 80) int oy2,
                                        @ForAll @IntRange(min = 0, max = 40) int ow2, @ForAll @IntRange(min = 0, max = 40) int oh2) {
        float x = x2 / 2f, y = y2 / 2f, w = w2 / 2f, h = h2 / 2f, vx = vx2 / 2f, vy = vy2 / 2f;
        float ox = ox2 / 2f, oy = oy2 / 2f, ow = ow2 / 2f, oh = oh2 / 2f;
        float t = Sweep.rectRect(x, y, w, h, vx, vy, ox, oy, ow, oh);
        SweepReference.Q exact = SweepReference.rectRect(x, y, w, h, vx, vy, ox, oy, ow, oh);
        if (exact == null) {
            assertEquals(Float.POSITIVE_INFINITY, t);
            assertTrue(Raw.sweepRectRectHit(x, y, w, h, vx, vy, ox, oy, ow, oh) == null);
        } else {
            SketchT.check(exact.value(), t, s -> Collide.rectRect(x + s * vx, y + s * vy, w, h, ox, oy, ow, oh),
                    SketchT.plateau(vx, vy, x, y, ox, oy, x + w, y + h, ox + ow, oy + oh), "exact " + exact);
            Hit hit = Raw.sweepRectRectHit(x, y, w, h, vx, vy, ox, oy, ow, oh);
            assertNotNull(hit);
            assertEquals(t, hit.t());
            assertEquals(Collide.rectRect(x, y, w, h, ox, oy, ow, oh), hit.alreadyOverlapping());
        }
        // Sampling: wherever a sample overlaps, the impact is no later.
        for (int k = 0; k <= SAMPLES; k++) {
            double s = (double) k / SAMPLES;
            double px = x + s * vx, py = y + s * vy;
            boolean overlap = px + w > ox && px < (double) ox + ow && py + h > oy && py < (double) oy + oh;
            if (overlap) {
                assertTrue(t <= s + SketchT.plateau(vx, vy, x, y, ox, oy, x + w, y + h, ox + ow, oy + oh),
                        "sample " + s + " overlaps but t = " + t);
                break;
            }
        }
    }

    @Property(tries = 3000)
    void circleCircle_rolesSwappedOrTranslated_sameTime(@ForAll @IntRange(min = -40, max = 40) int x, @ForAll @IntRange(min = -40, max = 40) int y,
                                                        @ForAll @IntRange(min = 0, max = 20) int r,
                                                        @ForAll @IntRange(min = -60, max = 60) int vx, @ForAll @IntRange(min = -60, max = 60) int vy,
                                                        @ForAll @IntRange(min = -40, max = 40) int ox, @ForAll @IntRange(min = -40, max = 40) int oy,
                                                        @ForAll @IntRange(min = 0, max = 20) int or,
                                                        @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx) {
        float t = Raw.sweepCircleCircle(x, y, r, vx, vy, ox, oy, or);
        double near = 2 * SketchT.plateau(vx, vy, x, y, ox, oy, r, or);
        SketchT.check(t == Float.POSITIVE_INFINITY ? Double.POSITIVE_INFINITY : t, t,
                s -> Collide.circleCircle(x + s * vx, y + s * vy, r, ox, oy, or), near, "mover, obstacle");
        // A position rounds by up to a float step on each axis, and a circle meets the other
        // along the line of centres, so the time moves by that step over the speed along that
        // line, not along an axis: a glancing approach (slow along the line) has its time
        // moved the most. The untranslated t gives the line.
        double along = Double.POSITIVE_INFINITY;
        if (t > 0 && t <= 1) {
            double cx = x + (double) t * vx - ox, cy = y + (double) t * vy - oy, c = Math.hypot(cx, cy);
            along = c > 0 ? Math.abs(vx * cx + vy * cy) / c : 0;
        }
        // With the roles swapped the other circle moves, and its own positions round: where it
        // meets glancingly, the first float position that overlaps can come before the exact
        // time by that rounding along the line (seed 7's third case: 15, -10, 13, -42, 16, -25,
        // -29, 19, the float positions overlap 1.9e-6 before the exact time, along the line at
        // 0.77 a frame).
        double swappedRounding = t > 0 && t <= 1
                ? SketchT.plateauAlong(along, ox, oy, x, y, (float) (ox - (double) t * vx), (float) (oy - (double) t * vy)) : 0;
        SketchT.check(t == Float.POSITIVE_INFINITY ? Double.POSITIVE_INFINITY : t, Raw.sweepCircleCircle(ox, oy, or, -vx, -vy, x, y, r),
                s -> Collide.circleCircle(ox + s * -vx, oy + s * -vy, or, x, y, r), near + swappedRounding, "roles swapped");
        float fx = x + dx, fy = y - dx, fox = ox + dx, foy = oy - dx;
        double rounding = Math.max(SketchT.plateau(vx, vy, fx, fy, fox, foy), SketchT.plateauAlong(along, fx, fy, fox, foy));
        SketchT.check(t == Float.POSITIVE_INFINITY ? Double.POSITIVE_INFINITY : t, Raw.sweepCircleCircle(fx, fy, r, vx, vy, fox, foy, or),
                s -> Collide.circleCircle(fx + s * vx, fy + s * vy, r, fox, foy, or),
                near + rounding, "translated");
        assertEquals(Collide.circleCircle(x, y, r, ox, oy, or), Raw.sweepCircleCircleHit(x, y, r, vx, vy, ox, oy, or) != null
                && Raw.sweepCircleCircleHit(x, y, r, vx, vy, ox, oy, or).alreadyOverlapping());
    }

    /**
     * Found by the property above: moved 4121 px away (a float step of 1/2048 px) a glancing
     * approach (speed along the line of centres about 1/5 of the motion) moves the time by
     * about two axis plateaus.
     */
    @Test
    void circleCircle_translatedGlancing_withinTheRoundingAlongTheLineOfCentres() {
        circleCircle_rolesSwappedOrTranslated_sameTime(0, 31, 1, 18, -15, 22, 40, 20, 4121);
    }

    @Property(tries = 5000)
    void circleCircle_hitsExactlyWhenThePathComesCloseEnough(
            @ForAll @IntRange(min = -80, max = 80) int x2, @ForAll @IntRange(min = -80, max = 80) int y2,
            @ForAll @IntRange(min = 0, max = 20) int r2,
            @ForAll @IntRange(min = -120, max = 120) int vx2, @ForAll @IntRange(min = -120, max = 120) int vy2,
            @ForAll @IntRange(min = -80, max = 80) int ox2, @ForAll @IntRange(min = -80, max = 80) int oy2,
            @ForAll @IntRange(min = 0, max = 20) int or2) {
        float x = x2 / 2f, y = y2 / 2f, r = r2 / 2f, vx = vx2 / 2f, vy = vy2 / 2f, ox = ox2 / 2f, oy = oy2 / 2f, or = or2 / 2f;
        float t = Raw.sweepCircleCircle(x, y, r, vx, vy, ox, oy, or);
        boolean exact = SweepReference.circleCircleHits(x, y, r, vx, vy, ox, oy, or);
        // The reference includes t = 1 (a path that overlaps only at the very end): the
        // overlap is open, so it would have started before the end.
        assertEquals(exact, t <= 1, "t = " + t);
        double reach = (double) r + or;
        for (int k = 0; k <= SAMPLES; k++) {
            double s = (double) k / SAMPLES;
            double dx = x + s * vx - ox, dy = y + s * vy - oy;
            boolean overlap = dx * dx + dy * dy < reach * reach;
            double near = SketchT.plateau(vx, vy, x, y, ox, oy, r, or) + 1e-6;
            if (overlap) {
                assertTrue(t <= s + near, "sample " + s + " overlaps but t = " + t);
            } else if (s < t - near && t <= 1) {
                continue;
            }
            if (s < t - near) {
                assertFalse(overlap, "sample " + s + " overlaps before t = " + t);
            }
        }
    }

    @Property(tries = 5000)
    void circleRect_hitsExactlyWhenThePathComesCloseEnough(
            @ForAll @IntRange(min = -80, max = 80) int x2, @ForAll @IntRange(min = -80, max = 80) int y2,
            @ForAll @IntRange(min = 0, max = 20) int r2,
            @ForAll @IntRange(min = -120, max = 120) int vx2, @ForAll @IntRange(min = -120, max = 120) int vy2,
            @ForAll @IntRange(min = -60, max = 60) int rx2, @ForAll @IntRange(min = -60, max = 60) int ry2,
            @ForAll @IntRange(min = 0, max = 30) int rw2, @ForAll @IntRange(min = 0, max = 30) int rh2) {
        float x = x2 / 2f, y = y2 / 2f, r = r2 / 2f, vx = vx2 / 2f, vy = vy2 / 2f;
        float rx = rx2 / 2f, ry = ry2 / 2f, rw = rw2 / 2f, rh = rh2 / 2f;
        Hit hit = Raw.sweepCircleRectHit(x, y, r, vx, vy, rx, ry, rw, rh);
        boolean exact = SweepReference.circleRectHits(x, y, r, vx, vy, rx, ry, rw, rh);
        assertEquals(exact, hit != null, () -> "hit = " + hit);
        float t = hit == null ? Float.POSITIVE_INFINITY : hit.t();
        for (int k = 0; k <= SAMPLES; k++) {
            double s = (double) k / SAMPLES;
            boolean overlap = Collide.circleRect((float) (x + s * vx), (float) (y + s * vy), r, rx, ry, rw, rh);
            double near = SketchT.plateau(vx, vy, x, y, r, rx, ry, rx + rw, ry + rh) + 1e-6;
            if (overlap) {
                assertTrue(t <= s + near, "sample " + s + " overlaps but t = " + t);
                break;
            }
        }
        // The rectangle moving back into the circle: the same time, to the rounding of positions.
        Hit back = Sweep.timeOfImpact(new Rect(rx, ry, rw, rh), -vx, -vy, new Circle(x, y, r));
        assertEquals(hit == null, back == null);
        if (hit != null) {
            assertEquals(hit.t(), back.t(), 2 * SketchT.plateau(vx, vy, x, y, r, rx, ry, rx + rw, ry + rh) + 1e-6);
            if (!hit.alreadyOverlapping()) {
                SketchT.check(hit.t(), back.t(), s -> Collide.circleRect(x, y, r, rx - s * vx, ry - s * vy, rw, rh),
                        2 * SketchT.plateau(vx, vy, x, y, r, rx, ry, rx + rw, ry + rh), "roles swapped");
            }
        }
    }

    @Property(tries = 5000)
    void rectSegment_neverMissesASampledOverlap(
            @ForAll @IntRange(min = -60, max = 60) int x2, @ForAll @IntRange(min = -60, max = 60) int y2,
            @ForAll @IntRange(min = 0, max = 30) int w2, @ForAll @IntRange(min = 0, max = 30) int h2,
            @ForAll @IntRange(min = -120, max = 120) int vx2, @ForAll @IntRange(min = -120, max = 120) int vy2,
            @ForAll @IntRange(min = -60, max = 60) int ax2, @ForAll @IntRange(min = -60, max = 60) int ay2,
            @ForAll @IntRange(min = -60, max = 60) int bx2, @ForAll @IntRange(min = -60, max = 60) int by2) {
        float x = x2 / 2f, y = y2 / 2f, w = w2 / 2f, h = h2 / 2f, vx = vx2 / 2f, vy = vy2 / 2f;
        float ax = ax2 / 2f, ay = ay2 / 2f, bx = bx2 / 2f, by = by2 / 2f;
        Hit hit = Raw.sweepRectSegmentHit(x, y, w, h, vx, vy, ax, ay, bx, by);
        float t = hit == null ? Float.POSITIVE_INFINITY : hit.t();
        boolean atStart = SweepReference.openBoxSegment(x, y, w, h, ax, ay, bx, by);
        assertEquals(atStart, hit != null && hit.alreadyOverlapping(), () -> "hit = " + hit);
        for (int k = 0; k <= SAMPLES; k++) {
            double s = (double) k / SAMPLES;
            boolean overlap = SweepReference.openBoxSegment(x + s * vx, y + s * vy, w, h, ax, ay, bx, by);
            if (overlap) {
                assertTrue(t <= s + SketchT.plateau(vx, vy, x, y, x + w, y + h, ax, ay, bx, by) + 1e-6,
                        "sample " + s + " overlaps but t = " + t);
                break;
            }
        }
        if (hit != null && !hit.alreadyOverlapping() && hit.t() < 0.999) {
            // Just after the impact the shapes do overlap. The overlap can be very short (a
            // segment's end crossing a box's corner), so search evenly and also ever closer to
            // t, halving the gap each time.
            boolean found = false;
            for (int k = 1; k <= 4096 && !found; k++) {
                double s = hit.t() + k * (1 - hit.t()) / 4096;
                found = SweepReference.openBoxSegment(x + s * vx, y + s * vy, w, h, ax, ay, bx, by);
            }
            for (int k = 1; k <= 60 && !found; k++) {
                double s = hit.t() + (1 - hit.t()) / Math.pow(2, k);
                found = SweepReference.openBoxSegment(x + s * vx, y + s * vy, w, h, ax, ay, bx, by);
            }
            assertTrue(found, () -> "no overlap after t = " + hit.t());
        }
        Hit back = Sweep.timeOfImpact(new Segment(ax, ay, bx, by), -vx, -vy, new Rect(x, y, w, h));
        assertEquals(hit == null, back == null);
    }

    @Property(tries = 3000)
    void circleSegment_neverMissesASampledOverlap(
            @ForAll @IntRange(min = -60, max = 60) int x2, @ForAll @IntRange(min = -60, max = 60) int y2,
            @ForAll @IntRange(min = 0, max = 20) int r2,
            @ForAll @IntRange(min = -120, max = 120) int vx2, @ForAll @IntRange(min = -120, max = 120) int vy2,
            @ForAll @IntRange(min = -60, max = 60) int ax2, @ForAll @IntRange(min = -60, max = 60) int ay2,
            @ForAll @IntRange(min = -60, max = 60) int bx2, @ForAll @IntRange(min = -60, max = 60) int by2) {
        float x = x2 / 2f, y = y2 / 2f, r = r2 / 2f, vx = vx2 / 2f, vy = vy2 / 2f;
        float ax = ax2 / 2f, ay = ay2 / 2f, bx = bx2 / 2f, by = by2 / 2f;
        Hit hit = Raw.sweepCircleSegmentHit(x, y, r, vx, vy, ax, ay, bx, by);
        float t = hit == null ? Float.POSITIVE_INFINITY : hit.t();
        java.math.BigDecimal r2exact = SweepReference.d(r).multiply(SweepReference.d(r));
        boolean everClose = r > 0 && pathMeetsCapsule(x, y, vx, vy, ax, ay, bx, by, r);
        assertEquals(everClose, hit != null, () -> "hit = " + hit);
        for (int k = 0; k <= SAMPLES; k++) {
            double s = (double) k / SAMPLES;
            boolean overlap = r > 0 && SweepReference.segmentPointCloser(SweepReference.d(ax), SweepReference.d(ay),
                    SweepReference.d(bx - ax), SweepReference.d(by - ay),
                    SweepReference.d(x + s * vx), SweepReference.d(y + s * vy), r2exact);
            if (overlap) {
                assertTrue(t <= s + SketchT.plateau(vx, vy, x, y, r, ax, ay, bx, by) + 1e-6,
                        "sample " + s + " overlaps but t = " + t);
                break;
            }
        }
    }

    /** Does the centre's path come closer than r to the segment? Exact, from the four end-to-segment distances or a crossing. */
    private static boolean pathMeetsCapsule(float x, float y, float vx, float vy, float ax, float ay, float bx, float by, float r) {
        java.math.BigDecimal r2 = SweepReference.d(r).multiply(SweepReference.d(r));
        java.math.BigDecimal px = SweepReference.d(x), py = SweepReference.d(y), pvx = SweepReference.d(vx), pvy = SweepReference.d(vy);
        java.math.BigDecimal sx = SweepReference.d(ax), sy = SweepReference.d(ay);
        java.math.BigDecimal svx = SweepReference.d(bx).subtract(sx), svy = SweepReference.d(by).subtract(sy);
        if (segmentsCross(x, y, x + (double) vx, y + (double) vy, ax, ay, bx, by)) {
            return true;
        }
        return SweepReference.segmentPointCloser(px, py, pvx, pvy, sx, sy, r2)
                || SweepReference.segmentPointCloser(px, py, pvx, pvy, SweepReference.d(bx), SweepReference.d(by), r2)
                || SweepReference.segmentPointCloser(sx, sy, svx, svy, px, py, r2)
                || SweepReference.segmentPointCloser(sx, sy, svx, svy, px.add(pvx), py.add(pvy), r2);
    }

    /** Do two closed segments meet? Orientation signs, exact for these half numbers. */
    private static boolean segmentsCross(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
        double o1 = Lines.orient(ax, ay, bx, by, cx, cy), o2 = Lines.orient(ax, ay, bx, by, dx, dy);
        double o3 = Lines.orient(cx, cy, dx, dy, ax, ay), o4 = Lines.orient(cx, cy, dx, dy, bx, by);
        if (o1 * o2 < 0 && o3 * o4 < 0) {
            return true;
        }
        return o1 == 0 && on(ax, ay, bx, by, cx, cy) || o2 == 0 && on(ax, ay, bx, by, dx, dy)
                || o3 == 0 && on(cx, cy, dx, dy, ax, ay) || o4 == 0 && on(cx, cy, dx, dy, bx, by);
    }

    private static boolean on(double ax, double ay, double bx, double by, double px, double py) {
        return px >= Math.min(ax, bx) && px <= Math.max(ax, bx) && py >= Math.min(ay, by) && py <= Math.max(ay, by);
    }
}
