package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The cheap first answers of the curved pairs (the discs and closest-point rounds in front of
 * {@code Ellipse.overlaps(Capsule)} and its kin) never disagree with the long way they stand in front of:
 * random, whole and half-pixel (touching-heavy) and far-apart cases.
 */
class CurvedQuickPathTest {

    private static float pick(SplittableRandom rnd, int kind, float lo, float hi) {
        float v = lo + (float) rnd.nextDouble() * (hi - lo);
        return kind == 0 ? v : kind == 1 ? Math.round(v) : Math.round(2 * v) / 2f;
    }

    @Test
    void ellipseCapsuleQuickAgreesWithTheLongWay() {
        SplittableRandom rnd = new SplittableRandom(12);
        int decided = 0;
        for (int i = 0; i < 200_000; i++) {
            int kind = i % 3;
            float span = i % 7 == 0 ? 1e5f : 12;
            float x = pick(rnd, kind, -span, span), y = pick(rnd, kind, -span, span);
            float a = pick(rnd, kind, 0.5f, 6), b = pick(rnd, kind, 0.5f, 6);
            float x1 = pick(rnd, kind, -12, 12), y1 = pick(rnd, kind, -12, 12);
            float x2 = pick(rnd, kind, -12, 12), y2 = pick(rnd, kind, -12, 12);
            float r = pick(rnd, kind, 0.5f, 4);
            if (i % 5 == 0) { // the capsule near the ellipse, as after a broad phase
                x1 += x;
                y1 += y;
                x2 += x;
                y2 += y;
            }
            if (!(a > 0 && b > 0 && r > 0)) {
                continue;
            }
            boolean slow = Ellipses.segmentWithin(x, y, a, b, x1, y1, x2, y2, r);
            int quick = Ellipses.capsuleQuick(a, b, (double) x1 - x, (double) y1 - y, (double) x2 - x, (double) y2 - y, r);
            if (quick != 0) {
                decided++;
                String what = "case " + i + ": " + x + ", " + y + ", " + a + ", " + b + " / "
                        + x1 + ", " + y1 + ", " + x2 + ", " + y2 + ", " + r;
                assertEquals(slow, quick > 0, what);
            }
            // An ellipse with equal radii is a circle, which the shapes answer exactly: there the
            // truth is the exact distance to the segment, which the long way rounds at touching.
            assertEquals(a == b ? exactlyCloser(x, y, x1, y1, x2, y2, (double) a + r) : slow,
                    new Ellipse(x, y, a, b).overlaps(new Capsule(x1, y1, x2, y2, r)));
        }
        // The point of the quick path: it decides most cases.
        org.junit.jupiter.api.Assertions.assertTrue(decided > 150_000, "decided " + decided);
    }

    @Test
    void ellipseCircleAndEllipseQuickAgreeWithTheLongWay() {
        SplittableRandom rnd = new SplittableRandom(13);
        int decided = 0;
        for (int i = 0; i < 200_000; i++) {
            int kind = i % 3;
            float x = pick(rnd, kind, -12, 12), y = pick(rnd, kind, -12, 12);
            float a = pick(rnd, kind, 0.5f, 6), b = pick(rnd, kind, 0.5f, 6);
            float x2 = pick(rnd, kind, -12, 12), y2 = pick(rnd, kind, -12, 12);
            float a2 = pick(rnd, kind, 0.5f, 6), b2 = pick(rnd, kind, 0.5f, 6);
            if (!(a > 0 && b > 0 && a2 > 0 && b2 > 0)) {
                continue;
            }
            // The circle: the long way is the outline's distance from its centre.
            double qx = (double) x2 - x, qy = (double) y2 - y;
            boolean slowCircle = Ellipses.side(x2, y2, x, y, a, b) <= 0 || Ellipses.distance(a, b, qx, qy, null) < a2;
            int quick = Ellipses.capsuleQuick(a, b, qx, qy, qx, qy, a2);
            String what = "case " + i + ": " + x + ", " + y + ", " + a + ", " + b + " / " + x2 + ", " + y2 + ", " + a2 + ", " + b2;
            if (quick != 0) {
                decided++;
                assertEquals(slowCircle, quick > 0, what);
            }
            // Equal radii: a circle, answered exactly (see ellipseCapsuleQuickAgreesWithTheLongWay).
            assertEquals(a == b ? exactlyCloser(x, y, x2, y2, x2, y2, (double) a + a2) : slowCircle,
                    new Ellipse(x, y, a, b).overlaps(new Circle(x2, y2, a2)), what);
            // The ellipse pair, in the first's scaled frame, as Ellipses.ellipse takes it.
            double cx = qx * b, cy = qy * a, ea = (double) a2 * b, eb = (double) b2 * a, reach = (double) a * b;
            boolean slowEllipse = Ellipses.side(0, 0, cx, cy, ea, eb) <= 0 || Ellipses.distance(ea, eb, -cx, -cy, null) < reach;
            int quickE = Ellipses.capsuleQuick(ea, eb, -cx, -cy, -cx, -cy, reach);
            if (quickE != 0) {
                assertEquals(slowEllipse, quickE > 0, what);
            }
            assertEquals(slowEllipse, Ellipses.ellipse(x, y, a, b, x2, y2, a2, b2), what);
        }
        org.junit.jupiter.api.Assertions.assertTrue(decided > 150_000, "decided " + decided);
    }

    @Test
    void ellipseSideWithoutBigDecimalStillExact() {
        SplittableRandom rnd = new SplittableRandom(14);
        for (int i = 0; i < 300_000; i++) {
            int kind = i % 3;
            float span = i % 5 == 0 ? 3e4f : 20;
            float qx = pick(rnd, kind, -span, span), qy = pick(rnd, kind, -span, span);
            float cx = pick(rnd, kind, -span, span), cy = pick(rnd, kind, -span, span);
            float a = pick(rnd, kind, 0.5f, 30), b = pick(rnd, kind, 0.5f, 30);
            if (i % 2 == 0) { // on or near the outline: the ties
                qx = cx + (rnd.nextBoolean() ? a : -a) * (kind == 0 ? 1 : 0) + (kind == 0 ? 0 : Math.round(rnd.nextDouble() * 2) - 1);
                qy = kind == 0 ? cy : cy + (rnd.nextBoolean() ? b : -b);
            }
            java.math.BigDecimal u = new java.math.BigDecimal(qx).subtract(new java.math.BigDecimal(cx)).multiply(new java.math.BigDecimal(b));
            java.math.BigDecimal v = new java.math.BigDecimal(qy).subtract(new java.math.BigDecimal(cy)).multiply(new java.math.BigDecimal(a));
            java.math.BigDecimal w = new java.math.BigDecimal(a).multiply(new java.math.BigDecimal(b));
            int want = u.multiply(u).add(v.multiply(v)).subtract(w.multiply(w)).signum();
            int fi = i;
            float fqx = qx, fqy = qy;
            assertEquals(want, Ellipses.side(fqx, fqy, cx, cy, a, b),
                    () -> "case " + fi + ": " + fqx + ", " + fqy + " in " + cx + ", " + cy + ", " + a + ", " + b);
        }
    }

    /**
     * Is the point (px, py) closer than {@code reach} to the segment (x1, y1)-(x2, y2), in exact
     * rational arithmetic: the oracle for an ellipse with equal radii, which is a circle.
     */
    static boolean exactlyCloser(float px, float py, float x1, float y1, float x2, float y2, double reach) {
        java.math.BigDecimal ex = bd(x2).subtract(bd(x1)), ey = bd(y2).subtract(bd(y1));
        java.math.BigDecimal wx = bd(px).subtract(bd(x1)), wy = bd(py).subtract(bd(y1));
        java.math.BigDecimal r2 = new java.math.BigDecimal(reach).pow(2);
        java.math.BigDecimal len2 = ex.pow(2).add(ey.pow(2)), along = wx.multiply(ex).add(wy.multiply(ey));
        if (along.signum() <= 0 || len2.signum() == 0) {
            return wx.pow(2).add(wy.pow(2)).compareTo(r2) < 0;
        }
        if (along.compareTo(len2) >= 0) {
            java.math.BigDecimal vx = bd(px).subtract(bd(x2)), vy = bd(py).subtract(bd(y2));
            return vx.pow(2).add(vy.pow(2)).compareTo(r2) < 0;
        }
        java.math.BigDecimal cross = wx.multiply(ey).subtract(wy.multiply(ex));
        return cross.pow(2).compareTo(r2.multiply(len2)) < 0;
    }

    private static java.math.BigDecimal bd(float v) {
        return new java.math.BigDecimal(v);
    }
}