package hitbox.internal;

import hitbox.*;

import java.math.BigDecimal;

/**
 * The ellipse maths behind {@link Collide}'s {@code ellipse...} methods and {@link Ellipse}:
 * valid values only (finite, radii at least 0; {@code Collide} screens NaN and negative sizes
 * first).
 *
 * <p>How each pair is decided, and how exactly:
 * <ul>
 *   <li>A point, and a rectangle (through its point nearest the centre, which an axis-aligned
 *       scaling keeps nearest): the sign of {@code (dx ry)^2 + (dy rx)^2 - (rx ry)^2},
 *       exact (double with an error filter, then {@link BigDecimal}).</li>
 *   <li>A segment and a polygon: the plane scaled by ry along x and rx along y turns the
 *       ellipse into a circle of radius rx ry, and segments stay segments; then the segment's
 *       distance is compared with that radius as {@link Collide#lineCircle} compares it
 *       (exact signs of double products: exact for whole numbers up to about 2^12).</li>
 *   <li>A circle and another ellipse: the distance from a point to an ellipse's outline by
 *       D. Eberly's robust bisection ("Distance from a Point to an Ellipse, an Ellipsoid, or a
 *       Hyperellipsoid", Geometric Tools, 2013), to double precision; an ellipse against an
 *       ellipse is first scaled so the first is a circle (products of floats, exact in
 *       double). The answer can be wrong only when the shapes are within about 1e-12 of
 *       their own size of touching; touching on an axis of the ellipse (its top, bottom, left
 *       or right point) is exact.</li>
 *   <li>A flat ellipse (a radius 0) is its box, a flat rectangle: a segment without its
 *       ends, as the package's zero-size rule says.</li>
 * </ul>
 * A turned ellipse is taken into its own frame by {@link TurnedEllipses}, which calls these.
 */
public final class Ellipses {
    private Ellipses() {
    }

    /** 4 units in the last place, bound on the rounding of a sum of three rounded squares. */
    private static final double SUM_ERROR = 8 * 0x1p-53;

    /**
     * The exact sign of {@code ((qx - cx) b)^2 + ((qy - cy) a)^2 - (a b)^2}: negative inside
     * the ellipse (centre cx, cy, radii a, b), 0 on its outline, positive outside.
     */
    public static int side(double qx, double qy, double cx, double cy, double a, double b) {
        double u = (qx - cx) * b, v = (qy - cy) * a, w = a * b;
        double s = u * u + v * v - w * w;
        double bound = SUM_ERROR * (u * u + v * v + w * w);
        // The usual answers first: clear of the rounding error either way (NaN fails both, and
        // an infinite bound is never exceeded).
        if (s > bound) {
            return 1;
        }
        if (-s > bound) {
            return -1;
        }
        if (!(bound < Double.POSITIVE_INFINITY) || s != s) {
            return s < 0 ? -1 : 1; // infinite values or overflow: compared as they come, NaN is outside
        }
        if (exact(qx, qy, cx, cy, a, b, s)) {
            return s < 0 ? -1 : s > 0 ? 1 : 0;
        }
        BigDecimal bu = new BigDecimal(qx).subtract(new BigDecimal(cx)).multiply(new BigDecimal(b));
        BigDecimal bv = new BigDecimal(qy).subtract(new BigDecimal(cy)).multiply(new BigDecimal(a));
        BigDecimal bw = new BigDecimal(a).multiply(new BigDecimal(b));
        return bu.multiply(bu).add(bv.multiply(bv)).subtract(bw.multiply(bw)).signum();
    }

    /**
     * Was {@code s} of {@link #side} computed without rounding? Each difference, product and
     * sum is checked with its error-free transformation (Knuth's two-sum, and a fused
     * multiply-add for products): the usual case for whole and half-pixel ties, which then
     * need no BigDecimal (nothing allocated).
     */
    private static boolean exact(double qx, double qy, double cx, double cy, double a, double b, double s) {
        double dx = qx - cx, dy = qy - cy;
        if (!exactSum(qx, -cx, dx) || !exactSum(qy, -cy, dy)) {
            return false;
        }
        double u = dx * b, v = dy * a, w = a * b;
        if (Math.fma(dx, b, -u) != 0 || Math.fma(dy, a, -v) != 0 || Math.fma(a, b, -w) != 0) {
            return false;
        }
        double uu = u * u, vv = v * v, ww = w * w;
        if (Math.fma(u, u, -uu) != 0 || Math.fma(v, v, -vv) != 0 || Math.fma(w, w, -ww) != 0) {
            return false;
        }
        double sum = uu + vv;
        return exactSum(uu, vv, sum) && exactSum(sum, -ww, s) && sum - ww == s;
    }

    /** Is {@code sum} the exact value of x + y (Knuth's two-sum error is 0)? */
    private static boolean exactSum(double x, double y, double sum) {
        double yv = sum - x;
        double err = (x - (sum - yv)) + (y - yv);
        return err == 0 && sum - x - y == 0 && !Double.isInfinite(sum);
    }

    /** Is the point strictly inside the ellipse? A flat ellipse has no inside. */
    public static boolean point(float x, float y, float a, float b, float px, float py) {
        return a > 0 && b > 0 && side(px, py, x, y, a, b) < 0;
    }

    /** Ellipse and rectangle, both real (radii and sizes > 0 for the ellipse; any size for the rectangle). */
    public static boolean rect(float x, float y, float a, float b, float rx, float ry, float rw, float rh) {
        double qx = Lines.clamp(x, rx, (double) rx + rw);
        double qy = Lines.clamp(y, ry, (double) ry + rh);
        // The rectangle's point nearest the centre, in the scaled plane as in this one.
        return side(qx, qy, x, y, a, b) < 0;
    }

    /**
     * A closed segment and a real ellipse: in the plane scaled by (b, a) about the centre, is
     * the segment closer to the centre than a b (or, if {@code closed}, at most that far)?
     */
    public static boolean segment(float x, float y, float a, float b, float x1, float y1, float x2, float y2, boolean closed) {
        double px = ((double) x1 - x) * b, py = ((double) y1 - y) * a;
        double qx = ((double) x2 - x) * b, qy = ((double) y2 - y) * a;
        double reach = (double) a * b;
        return Capsules.nearOrigin(px, py, qx, qy, reach, closed);
    }

    /** A polygon's raw outline (at least 3 vertices, no NaN) and a real ellipse. */
    public static boolean polygon(float[] xy, float x, float y, float a, float b) {
        int n = xy.length / 2;
        for (int i = 0, h = n - 1; i < n; h = i++) {
            if (segment(x, y, a, b, xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], false)) {
                return true;
            }
        }
        return Polygons.contains(xy, x, y);
    }

    /** A real ellipse and a circle of radius r > 0. */
    public static boolean circle(float x, float y, float a, float b, float cx, float cy, float r) {
        int sure = discs((double) cx - x, (double) cy - y, a, b, r, r);
        if (sure == 0) {
            // The closest-point rounds, the circle a capsule with a segment of one point.
            double qx = (double) cx - x, qy = (double) cy - y;
            sure = capsuleQuick(a, b, qx, qy, qx, qy, r);
        }
        if (sure != 0) {
            return sure > 0;
        }
        if (side(cx, cy, x, y, a, b) <= 0) {
            return true;
        }
        return distance(a, b, (double) cx - x, (double) cy - y, null) < r;
    }

    /**
     * The cheap answer first, for real ellipses (radii a1, b1 and a2, b2; a circle has equal
     * radii) whose centres are (dx, dy) apart: 1 if they surely overlap (the centres closer
     * than the sum of the smaller radii: the discs inside both meet), -1 if they surely do
     * not (farther than the sum of the larger radii: the discs around both miss), 0 to decide
     * it the long way. A margin of 1e-9 keeps the double rounding of the squares out of it,
     * so it never answers a case the exact tests would answer otherwise.
     */
    public static int discs(double dx, double dy, double a1, double b1, double a2, double b2) {
        double d2 = dx * dx + dy * dy;
        double inner = Math.min(a1, b1) + Math.min(a2, b2), outer = Math.max(a1, b1) + Math.max(a2, b2);
        if (d2 < inner * inner * (1 - Tolerance.NEAR_TIE)) {
            return 1;
        }
        if (d2 > outer * outer * (1 + Tolerance.NEAR_TIE)) {
            return -1;
        }
        return 0;
    }

    /** Does ellipse (x1, y1, a1, b1) come before ellipse (x2, y2, a2, b2) in a fixed order? Makes the pair's answer symmetric. */
    public static boolean before(float x1, float y1, float a1, float b1, float x2, float y2, float a2, float b2) {
        int c = Float.compare(x1, x2);
        c = c != 0 ? c : Float.compare(y1, y2);
        c = c != 0 ? c : Float.compare(a1, a2);
        return (c != 0 ? c : Float.compare(b1, b2)) < 0;
    }

    /** Two real ellipses: the first scaled into a circle of radius a1 b1, the second stays an ellipse. */
    public static boolean ellipse(float x1, float y1, float a1, float b1, float x2, float y2, float a2, float b2) {
        int sure = discs((double) x2 - x1, (double) y2 - y1, a1, b1, a2, b2);
        if (sure != 0) {
            return sure > 0;
        }
        double cx = ((double) x2 - x1) * b1, cy = ((double) y2 - y1) * a1;
        double a = (double) a2 * b1, b = (double) b2 * a1;
        double reach = (double) a1 * b1;
        // The closest-point rounds, the circle a capsule with a segment of one point.
        sure = capsuleQuick(a, b, -cx, -cy, -cx, -cy, reach);
        if (sure != 0) {
            return sure > 0;
        }
        // The first's centre (the origin) in the closed second: they overlap.
        if (side(0, 0, cx, cy, a, b) <= 0) {
            return true;
        }
        return distance(a, b, -cx, -cy, null) < reach;
    }

    /**
     * A closed segment and a real ellipse, the capsule's question: is the segment closer to the
     * ellipse than r? The distance from a point to a convex set is a convex function along
     * the segment, so its least value is found by bisection on the sign of its slope.
     */
    public static boolean segmentWithin(float x, float y, float a, float b, float x1, float y1, float x2, float y2, float r) {
        if (segment(x, y, a, b, x1, y1, x2, y2, true)) {
            return r > 0; // the segment meets the closed ellipse
        }
        return segmentDistance(a, b, (double) x1 - x, (double) y1 - y, (double) x2 - x, (double) y2 - y) < r;
    }

    /**
     * The cheap answer first for a real ellipse (centre at the origin, radii a, b) and a
     * capsule (segment PQ, radius r > 0): 1 if they surely overlap, -1 if they surely do not,
     * 0 to decide it the long way. First the discs inside and around the ellipse against the
     * segment's distance from the centre; then a few rounds of the closest-points iteration
     * (the ellipse's support point along n, the segment's point nearest it, n from one to
     * the other): a direction along which the capsule lies beyond the ellipse proves a miss,
     * and a point of the ellipse's outline closer than r to the segment proves an overlap.
     * Each proof must hold by a margin of 1e-10 of the sizes, far above the double rounding
     * of these sums, so this never answers a case the long way would answer otherwise.
     * Allocates nothing.
     */
    public static int capsuleQuick(double a, double b, double px, double py, double qx, double qy, double r) {
        double scale = a + b + r + Math.abs(px) + Math.abs(py) + Math.abs(qx) + Math.abs(qy);
        if (!(scale < Double.POSITIVE_INFINITY)) {
            return 0;
        }
        double margin = Tolerance.QUICK_MARGIN * scale;
        double ex = qx - px, ey = qy - py, len2 = ex * ex + ey * ey;
        double sx = 0, sy = 0; // the point of the ellipse the segment is measured from: first its centre
        for (int round = 0; round < 6; round++) {
            // The segment's point nearest (sx, sy).
            double t = len2 > 0 ? ((sx - px) * ex + (sy - py) * ey) / len2 : 0;
            t = t < 0 ? 0 : t > 1 ? 1 : t;
            double dx = px + t * ex - sx, dy = py + t * ey - sy;
            double d = Math.hypot(dx, dy);
            if (round == 0) {
                if (d < Math.min(a, b) + r - margin) {
                    return 1; // the disc inside the ellipse meets the capsule
                }
                if (d > Math.max(a, b) + r + margin) {
                    return -1; // the disc around the ellipse misses it
                }
            } else if (d < r - margin) {
                return 1; // a point of the outline inside the capsule
            }
            if (!(d > 0)) {
                return 0;
            }
            double nx = dx / d, ny = dy / d;
            double w = Math.sqrt(a * a * nx * nx + b * b * ny * ny);
            double sep = Math.min(px * nx + py * ny, qx * nx + qy * ny) - r - w;
            if (sep > margin) {
                return -1; // along n the capsule starts beyond the ellipse's reach
            }
            if (!(w > 0)) {
                return 0;
            }
            sx = a * a * nx / w;
            sy = b * b * ny / w;
        }
        return 0;
    }

    /**
     * segmentDistance's place for the outline's nearest point, one per thread (as Contacts'
     * scratch corners): the rare cases that need the distance then allocate nothing either.
     * Nothing called while it is in use calls segmentDistance again.
     */
    private static final ThreadLocal<double[]> NEAR = ThreadLocal.withInitial(() -> new double[2]);

    /** The distance from a segment outside the ellipse (centre at the origin) to it. */
    public static double segmentDistance(double a, double b, double px, double py, double qx, double qy) {
        double dx = qx - px, dy = qy - py;
        double[] near = NEAR.get();
        double lo = 0, hi = 1;
        if (slope(a, b, px, py, dx, dy, near) >= 0) {
            return distance(a, b, px, py, null);
        }
        if (slope(a, b, qx, qy, dx, dy, near) <= 0) {
            return distance(a, b, qx, qy, null);
        }
        for (int i = 0; i < 80; i++) {
            double t = (lo + hi) / 2;
            if (t == lo || t == hi) {
                break;
            }
            double m = slope(a, b, px + t * dx, py + t * dy, dx, dy, near);
            if (m == 0) {
                return distance(a, b, px + t * dx, py + t * dy, null); // the least, found exactly
            }
            if (m < 0) {
                lo = t;
            } else {
                hi = t;
            }
        }
        double t = (lo + hi) / 2;
        return distance(a, b, px + t * dx, py + t * dy, null);
    }

    /** The sign of the distance's slope along (dx, dy) at point (px, py), outside the ellipse. */
    private static double slope(double a, double b, double px, double py, double dx, double dy, double[] near) {
        distance(a, b, px, py, near);
        return (px - near[0]) * dx + (py - near[1]) * dy;
    }

    /**
     * The distance from (px, py) to the outline of the ellipse centred at the origin with
     * radii a, b > 0, and (if {@code near} is not null) the outline's nearest point. Eberly's
     * method: the point is reflected into the first quadrant, the larger radius laid along x,
     * and the root of his function G found by bisection.
     */
    public static double distance(double a, double b, double px, double py, double[] near) {
        boolean swap = a < b;
        double e0 = swap ? b : a, e1 = swap ? a : b;
        double y0 = Math.abs(swap ? py : px), y1 = Math.abs(swap ? px : py);
        double x0, x1, d;
        if (y1 > 0) {
            if (y0 > 0) {
                double z0 = y0 / e0, z1 = y1 / e1;
                double g = Math.hypot(z0, z1) - 1;
                if (g != 0) {
                    double r0 = (e0 / e1) * (e0 / e1);
                    double s = root(r0, z0, z1, g);
                    x0 = r0 * y0 / (s + r0);
                    x1 = y1 / (s + 1);
                    d = Math.hypot(x0 - y0, x1 - y1);
                } else {
                    x0 = y0;
                    x1 = y1;
                    d = 0;
                }
            } else {
                x0 = 0;
                x1 = e1;
                d = Math.abs(y1 - e1);
            }
        } else {
            double numer = e0 * y0, denom = (e0 - e1) * (e0 + e1);
            if (numer < denom) {
                double xd = numer / denom;
                x0 = e0 * xd;
                x1 = e1 * Math.sqrt(1 - xd * xd);
                d = Math.hypot(x0 - y0, x1);
            } else {
                x0 = e0;
                x1 = 0;
                d = Math.abs(y0 - e0);
            }
        }
        if (near != null) {
            double nx = Math.copySign(swap ? x1 : x0, px), ny = Math.copySign(swap ? x0 : x1, py);
            near[0] = nx;
            near[1] = ny;
        }
        return d;
    }

    /** Eberly's GetRoot: the root of G(s) = (r0 z0 / (s + r0))^2 + (z1 / (s + 1))^2 - 1 by bisection. */
    private static double root(double r0, double z0, double z1, double g) {
        double n0 = r0 * z0;
        double s0 = z1 - 1, s1 = g < 0 ? 0 : Math.hypot(n0, z1) - 1;
        double s = 0;
        for (int i = 0; i < 1100; i++) {
            s = (s0 + s1) / 2;
            if (s == s0 || s == s1) {
                break;
            }
            double ratio0 = n0 / (s + r0), ratio1 = z1 / (s + 1);
            double gs = ratio0 * ratio0 + ratio1 * ratio1 - 1;
            if (gs > 0) {
                s0 = s;
            } else if (gs < 0) {
                s1 = s;
            } else {
                break;
            }
        }
        return s;
    }
}
