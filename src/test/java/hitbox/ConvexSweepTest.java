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
}
