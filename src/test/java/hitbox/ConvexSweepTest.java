package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The convex-polygon way of {@link ConvexSweep} against its general way: the moved position
 * tested without making a polygon answers as {@link Polygon#translated} then
 * {@link Shape#overlaps} do, rounding and all (and a mover that rounding cannot bend, as
 * {@link ConvexPolygonSweep#keepsConvex} says, is indeed as convex after it), and the sweep by moving separating axes finds
 * the same float t as conservative advancement over the pieces.
 */
class ConvexSweepTest {

    /** A convex polygon: sorted angles round an ellipse, sometimes a vertex midway along a side, some far away. */
    private static Polygon convex(Random rnd) {
        int n = 3 + rnd.nextInt(8);
        double[] angles = new double[n];
        for (int i = 0; i < n; i++) {
            angles[i] = rnd.nextDouble() * 2 * Math.PI;
        }
        java.util.Arrays.sort(angles);
        float cx = Sampled.coord(rnd), cy = Sampled.coord(rnd);
        if (rnd.nextInt(4) == 0) {
            cx += (rnd.nextBoolean() ? 1 : -1) * (1 << (10 + rnd.nextInt(12)));
        }
        double a = 2 + rnd.nextInt(40), b = rnd.nextInt(5) == 0 ? 0.01 + rnd.nextDouble() : 2 + rnd.nextInt(40);
        float[] xy = new float[2 * n];
        for (int i = 0; i < n; i++) {
            xy[2 * i] = cx + (float) (a * Math.cos(angles[i]));
            xy[2 * i + 1] = cy + (float) (b * Math.sin(angles[i]));
            if (rnd.nextInt(3) == 0) {
                xy[2 * i] = Math.round(xy[2 * i] * 2) / 2f;
                xy[2 * i + 1] = Math.round(xy[2 * i + 1] * 2) / 2f;
            }
        }
        try {
            Polygon p = Polygon.of(xy);
            return p.isConvex() ? p : convex(rnd);
        } catch (IllegalArgumentException notAPolygon) {
            return convex(rnd);
        }
    }

    @Test
    void movedPosition_answersAsATranslatedPolygon() {
        Random rnd = new Random(31);
        int overlapping = 0, kept = 0, total = 200_000;
        for (int i = 0; i < total; i++) {
            Polygon p = convex(rnd), q = convex(rnd);
            // Move p near q, by a fraction of a pixel too, so that rounding and touching both come up.
            float[] pc = p.raw(), qc = q.raw();
            float dx = qc[0] - pc[0] + rnd.nextInt(60) - 30 + (rnd.nextBoolean() ? rnd.nextFloat() : 0);
            float dy = qc[1] - pc[1] + rnd.nextInt(60) - 30 + (rnd.nextBoolean() ? rnd.nextFloat() : 0);
            boolean general = ConvexSweep.movedOverlaps((Shape) p, dx, dy, q);
            String where = p + " moved by (" + dx + ", " + dy + ") against " + q;
            float[] moved = new float[pc.length];
            assertEquals(general, ConvexPolygonSweep.movedOverlaps(p, dx, dy, q, moved, false, true), where);
            assertEquals(general, ConvexPolygonSweep.movedOverlaps(p, dx, dy, q, moved, false, false), where);
            if (ConvexPolygonSweep.keepsConvex(p, Math.max(Math.abs(dx), Math.abs(dy)))) {
                // The claim behind skipping the check: rounded, the outline is as convex as before.
                assertEquals(p.convexWinding(), Polygons.convexWinding(moved), where);
                assertEquals(general, ConvexPolygonSweep.movedOverlaps(p, dx, dy, q, moved, true, rnd.nextBoolean()), where);
                kept++;
            }
            overlapping += general ? 1 : 0;
        }
        assertTrue(overlapping > total / 10 && overlapping < total * 9 / 10, overlapping + " of " + total);
        assertTrue(kept > total / 4 && kept < total, kept + " of " + total + " moves could not bend the mover");
    }

    @Test
    void convexPolygons_sameTimeAsByPieces() {
        Random rnd = new Random(32);
        int hits = 0, total = 20_000;
        for (int i = 0; i < total; i++) {
            Polygon p = convex(rnd), q = convex(rnd);
            float[] pc = p.raw(), qc = q.raw();
            float vx = qc[0] - pc[0] + rnd.nextInt(81) - 40 + (rnd.nextBoolean() ? rnd.nextFloat() : 0);
            float vy = qc[1] - pc[1] + rnd.nextInt(81) - 40 + (rnd.nextBoolean() ? rnd.nextFloat() : 0);
            Hit hit = Sweep.timeOfImpact(p, vx, vy, q);
            if (hit != null && hit.alreadyOverlapping()) {
                continue;
            }
            Hit pieces = ConvexSweep.byPieces(p, vx, vy, q);
            String where = p + " by (" + vx + ", " + vy + ") into " + q + ": " + hit + ", by pieces " + pieces;
            assertEquals(pieces == null, hit == null, where);
            if (hit != null) {
                assertEquals(pieces.t(), hit.t(), where);
                hits++;
            }
        }
        assertTrue(hits > total / 10, hits + " hits");
    }

    /** A box near the polygon: whole numbers, halves or any float, sometimes of a single pixel. */
    private static Rect boxNear(Random rnd, Polygon q) {
        float[] qc = q.raw();
        float x = qc[0] + rnd.nextInt(61) - 30 + (rnd.nextBoolean() ? 0 : rnd.nextInt(2) / 2f);
        float y = qc[1] + rnd.nextInt(61) - 30 + (rnd.nextBoolean() ? 0 : rnd.nextFloat());
        float w = rnd.nextInt(4) == 0 ? 1 : 1 + rnd.nextInt(20) + (rnd.nextBoolean() ? 0 : rnd.nextFloat());
        return new Rect(x, y, w, 1 + rnd.nextInt(20));
    }

    /**
     * A box against a convex polygon goes the exact way (the faces of their Minkowski
     * difference, {@code ConvexPolygonSweep.rectTimeOfImpact}), judged by {@link #judge}.
     */
    @Test
    void boxIntoConvexPolygon_keepsThePromiseAndMostlyMatchesByPieces() {
        Random rnd = new Random(33);
        int[] tally = new int[3];
        for (int i = 0; i < 5_000; i++) {
            Polygon q = convex(rnd);
            Rect p = boxNear(rnd, q);
            float vx = rnd.nextInt(81) - 40 + (rnd.nextBoolean() ? rnd.nextFloat() : 0);
            float vy = rnd.nextInt(81) - 40 + (rnd.nextBoolean() ? rnd.nextFloat() : 0);
            if (vx == 0 && vy == 0) {
                continue;
            }
            assertTrue(ConvexPolygonSweep.rectAgainstConvex(p, q), "the exact way");
            tally(tally, judge(p, vx, vy, q, p.x(), p.y(), t -> meets(q.raw(), p.x() + t * vx, p.y() + t * vy, p.w(), p.h())));
        }
        assertMostlyTheSame(tally, 500);
    }

    /**
     * Found by the test above: 32,800 px out, where a float step of x is 1/256 px, the box's
     * float positions overlap the polygon's slanted edge 4,013 float times before the t that
     * conservative advancement gave (0.96621096): its look-back gave up. The exact faces'
     * walk starts at the slack entry and finds the first of them.
     */
    @Test
    void boxIntoConvexPolygon_farOut_stopsAtTheFirstOverlappingFloatPosition() {
        Polygon q = Polygon.of(32823.88f, 77.3822f, 32821.652f, 78.92552f, 32808.0f, 67.0f, 32805.945f, 59.52176f,
                32832.336f, 37.9208f);
        float x = 32834.38f, y = 47.382202f;
        Hit hit = Sweep.timeOfImpact(new Rect(x, y, 6, 16), -10, 27, q);
        float t = hit.t();
        assertTrue(!meets(q.raw(), x + t * -10, y + t * 27, 6, 16), "clear at t: " + hit);
        float up = Math.nextUp(t);
        assertTrue(meets(q.raw(), x + up * -10, y + up * 27, 6, 16), "overlapping after: " + hit);
        assertTrue(t < 0.96621096f, "" + hit);
    }

    /**
     * The promise itself, on whole numbers, where the exact reference decides each position:
     * the box moved to t does not overlap the polygon, and moved to the next float up it does
     * (at t = 0, touching and moving in: moved a little, it does); no hit, and no position
     * sampled every 1/64 overlaps.
     */
    @Test
    void boxIntoConvexPolygon_keepsThePromiseOfTheExactReference() {
        Random rnd = new Random(34);
        int hits = 0, total = 4_000;
        for (int i = 0; i < total; i++) {
            int n = 3 + rnd.nextInt(4);
            float[] xy = new float[2 * n];
            for (int k = 0; k < n; k++) {
                double a = 2 * Math.PI * (k + rnd.nextDouble() * 0.8) / n;
                xy[2 * k] = 20 + Math.round(8 * Math.cos(a));
                xy[2 * k + 1] = 20 + Math.round(8 * Math.sin(a));
            }
            Polygon q;
            try {
                q = Polygon.of(xy);
            } catch (IllegalArgumentException notAPolygon) {
                continue;
            }
            if (!q.isConvex()) {
                continue;
            }
            float x = rnd.nextInt(40), y = rnd.nextInt(40), w = 1 + rnd.nextInt(8), h = 1 + rnd.nextInt(8);
            float vx = rnd.nextInt(33) - 16, vy = rnd.nextInt(33) - 16;
            if (meets(xy, x, y, w, h) || vx == 0 && vy == 0) {
                continue;
            }
            Hit hit = Sweep.timeOfImpact(new Rect(x, y, w, h), vx, vy, q);
            String where = new Rect(x, y, w, h) + " by (" + vx + ", " + vy + ") into " + q + ": " + hit;
            if (hit == null) {
                for (int k = 0; k <= 64; k++) {
                    float t = k / 64f;
                    assertTrue(!meets(xy, x + t * vx, y + t * vy, w, h),
                            "no hit, yet it overlaps at " + t + ": " + where);
                }
                continue;
            }
            float t = hit.t();
            assertTrue(!meets(xy, x + t * vx, y + t * vy, w, h),
                    "clear at t: " + where);
            float up = t == 0 ? moved(x, vx, y, vy) : Math.nextUp(t);  // t = 0: touching at the start, moving in
            assertTrue(meets(xy, x + up * vx, y + up * vy, w, h),
                    "overlapping just after: " + where);
            hits++;
        }
        assertTrue(hits > 400, hits + " hits");
    }

    /** A t from 1/1024 up at which each moving coordinate of (x + t vx, y + t vy) has moved from t = 0. */
    private static float moved(float x, float vx, float y, float vy) {
        float t = 1 / 1024f;
        while (t < 1 && (vx != 0 && x + t * vx == x || vy != 0 && y + t * vy == y)) {
            t *= 2;
        }
        return t;
    }

    /** The exact reference: the polygon and the box (x, y, w, h), its far sides summed exactly, overlap. */
    private static boolean meets(float[] polygon, float x, float y, float w, float h) {
        return ExactReference.polygonsMeet(ExactReference.toQ(polygon), ExactReference.rectQ(x, y, w, h));
    }

    /** Resting flush on a slope: sliding along it is no hit, pressing into it is a hit at 0. */
    @Test
    void boxFlushOnASlope_slidesAlongAndStopsPressingIn() {
        // The slope from (0, 40) up to (40, 0) and the ground under it; the box's corner on it at (20, 20).
        Polygon slope = Polygon.of(0, 40, 40, 0, 40, 40);
        Rect box = new Rect(10, 10, 10, 10);
        assertEquals(null, Sweep.timeOfImpact(box, -4, 4, slope), "along the slope, down");
        assertEquals(null, Sweep.timeOfImpact(box, 4, -4, slope), "along the slope, up");
        assertEquals(null, Sweep.timeOfImpact(box, -3, -3, slope), "away from it");
        Hit in = Sweep.timeOfImpact(box, 0, 5, slope);
        assertEquals(0, in.t(), "pressing in: " + in);
        assertEquals(Math.sqrt(0.5), in.nx(), 1e-6);
        assertEquals(Math.sqrt(0.5), in.ny(), 1e-6);
        // A gap of 4 closed at half the move: clear at t (still touching), overlapping just after.
        Hit ahead = Sweep.timeOfImpact(new Rect(10, 6, 10, 10), 0, 8, slope);
        float t = ahead.t();
        assertEquals(0.5, t, 1e-6, "" + ahead);
        assertTrue(!meets(slope.raw(), 10, 6 + t * 8, 10, 10), "clear at t: " + ahead);
        assertTrue(meets(slope.raw(), 10, 6 + Math.nextUp(t) * 8, 10, 10), "overlapping after: " + ahead);
    }

    /**
     * A circle against a convex polygon goes the exact way too (the capsules round the edges,
     * {@code ConvexPolygonSweep.circleTimeOfImpact}), judged by {@link #judge}.
     */
    @Test
    void circleIntoConvexPolygon_keepsThePromiseAndMostlyMatchesByPieces() {
        Random rnd = new Random(35);
        int[] tally = new int[3];
        for (int i = 0; i < 5_000; i++) {
            Polygon q = convex(rnd);
            float[] qc = q.raw();
            float cx = qc[0] + rnd.nextInt(61) - 30 + (rnd.nextBoolean() ? 0 : rnd.nextInt(2) / 2f);
            float cy = qc[1] + rnd.nextInt(61) - 30 + (rnd.nextBoolean() ? 0 : rnd.nextFloat());
            float r = rnd.nextInt(4) == 0 ? 1 : 1 + rnd.nextInt(15) + (rnd.nextBoolean() ? 0 : rnd.nextFloat());
            float vx = rnd.nextInt(81) - 40 + (rnd.nextBoolean() ? rnd.nextFloat() : 0);
            float vy = rnd.nextInt(81) - 40 + (rnd.nextBoolean() ? rnd.nextFloat() : 0);
            if (vx == 0 && vy == 0) {
                continue;
            }
            Circle c = new Circle(cx, cy, r);
            assertTrue(ConvexPolygonSweep.circleAgainstPolygon(c, q), "the exact way");
            tally(tally, judge(c, vx, vy, q, cx, cy, t -> ExactReference.polygonCircle(qc, cx + t * vx, cy + t * vy, r)));
        }
        assertMostlyTheSame(tally, 500);
    }

    /** A ball resting on a slope's face rolls along it (no hit), and pressing into it stops at 0. */
    @Test
    void circleOnASlope_slidesAlongAndStopsPressingIn() {
        // The slope's face from (0, 30) to (40, 0): a 3-4-5 line, so a centre 5 off it is a whole number.
        Polygon slope = Polygon.of(0, 30, 40, 0, 40, 30);
        Circle ball = new Circle(17, 11, 5);  // 3*17 + 4*11 = 95 = 120 - 5*5: touching the face
        assertEquals(null, Sweep.timeOfImpact(ball, 8, -6, slope), "up along the face");
        assertEquals(null, Sweep.timeOfImpact(ball, -8, 6, slope), "down along the face");
        assertEquals(null, Sweep.timeOfImpact(ball, -3, -4, slope), "away from it");
        Hit in = Sweep.timeOfImpact(ball, 3, 4, slope);
        assertEquals(0, in.t(), "pressing in: " + in);
        assertEquals(0.6, in.nx(), 1e-6);
        assertEquals(0.8, in.ny(), 1e-6);
    }

    /**
     * The circle's exact way takes a concave polygon too (the capsules round its edges),
     * judged by {@link #judge} against conservative advancement over the polygon's triangles.
     */
    @Test
    void circleIntoConcavePolygon_keepsThePromiseAndMostlyMatchesByPieces() {
        java.util.SplittableRandom rnd = new java.util.SplittableRandom(36);
        int[] tally = new int[3];
        int concave = 0, total = 3_000;
        for (int i = 0; i < total; i++) {
            Polygon q = TestShapes.starRing(rnd, 5 + rnd.nextInt(6), 60, 60, rnd.nextBoolean());
            concave += q.isConvex() ? 0 : 1;
            float[] qc = q.raw();
            float cx = 60 + rnd.nextInt(121) - 60 + (rnd.nextBoolean() ? 0 : (float) rnd.nextDouble());
            float cy = 60 + rnd.nextInt(121) - 60 + (rnd.nextBoolean() ? 0 : rnd.nextInt(2) / 2f);
            float r = 1 + rnd.nextInt(10) + (rnd.nextBoolean() ? 0 : (float) rnd.nextDouble());
            float vx = rnd.nextInt(121) - 60 + (rnd.nextBoolean() ? (float) rnd.nextDouble() : 0);
            float vy = rnd.nextInt(121) - 60;
            if (vx == 0 && vy == 0) {
                continue;
            }
            Circle c = new Circle(cx, cy, r);
            assertTrue(ConvexPolygonSweep.circleAgainstPolygon(c, q), "the exact way");
            tally(tally, judge(c, vx, vy, q, cx, cy, t -> ExactReference.polygonCircle(qc, cx + t * vx, cy + t * vy, r)));
        }
        assertTrue(concave > total / 2, concave + " concave");
        assertMostlyTheSame(tally, 300);
    }

    /** Does the mover, moved by t times its motion in float as a sketch moves it, overlap the obstacle (the exact reference)? */
    private interface MovedMeets {
        boolean at(float t);
    }

    /**
     * One sweep into a polygon, judged by the exact reference: the mover moved to t does not
     * overlap, moved to the next float up it does (at t = 0, touching and moving in: once its
     * float position has moved a little, it does); conservative advancement over the pieces,
     * which knows nothing of faces or capsules, finds a hit too, never at an earlier t (it may
     * walk past float positions that rounding put inside far from the origin, see
     * {@link #boxIntoConvexPolygon_farOut_stopsAtTheFirstOverlappingFloatPosition}); the
     * normal is unit and points from the mover into the face it moves into. (x, y) is the
     * mover's first coordinate. Returns -1 if it overlaps at the start, 0 for no hit, 1 for a
     * hit at by pieces' t, 2 for one before it.
     */
    private static int judge(Shape mover, float vx, float vy, Polygon q, float x, float y, MovedMeets meets) {
        Hit hit = Sweep.timeOfImpact(mover, vx, vy, q);
        if (hit != null && hit.alreadyOverlapping()) {
            return -1;
        }
        Hit pieces = ConvexSweep.byPieces(mover, vx, vy, q);
        String where = mover + " by (" + vx + ", " + vy + ") into " + q + ": " + hit + ", by pieces " + pieces;
        assertEquals(pieces == null, hit == null, where);
        if (hit == null) {
            return 0;
        }
        float t = hit.t();
        assertTrue(!meets.at(t), "clear at t: " + where);
        if (t < 1) {
            assertTrue(meets.at(t == 0 ? moved(x, vx, y, vy) : Math.nextUp(t)), "overlapping after t: " + where);
        }
        assertTrue(t <= pieces.t(), where);
        assertEquals(1, Math.hypot(hit.nx(), hit.ny()), 1e-6, where);
        assertTrue(hit.nx() * vx + hit.ny() * vy > 0, "moving into the face it hit: " + where);
        return t == pieces.t() ? 1 : 2;
    }

    /** Counts {@link #judge}'s answer: hits at by pieces' t, hits before it, and all hits. */
    private static void tally(int[] tally, int judged) {
        if (judged > 0) {
            tally[judged - 1]++;
            tally[2]++;
        }
    }

    /** Enough hits, and nearly all (99%) at the t conservative advancement gives. */
    private static void assertMostlyTheSame(int[] tally, int leastHits) {
        assertTrue(tally[2] > leastHits, tally[2] + " hits");
        assertTrue(tally[0] > tally[2] * 99 / 100, tally[0] + " of " + tally[2] + " the same as by pieces");
    }
}
