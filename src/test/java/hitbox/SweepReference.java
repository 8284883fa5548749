package hitbox;

import java.math.BigDecimal;
import java.math.MathContext;

/**
 * Slow, exact answers to "does the moving shape's inside overlap the obstacle's at some time
 * t in [0, 1]?", in BigDecimal, written from the geometry (closest distance between the
 * path and the obstacle) rather than from the library's slab and quadratic code where that
 * is possible. Used by the property tests as the reference.
 */
final class SweepReference {
    private SweepReference() {
    }

    static BigDecimal d(double v) {
        return new BigDecimal(v);
    }

    /** A fraction n / d with d > 0. */
    record Q(BigDecimal n, BigDecimal d) implements Comparable<Q> {
        static Q of(BigDecimal n, BigDecimal d) {
            return d.signum() < 0 ? new Q(n.negate(), d.negate()) : new Q(n, d);
        }

        static final Q ZERO = new Q(BigDecimal.ZERO, BigDecimal.ONE);
        static final Q ONE = new Q(BigDecimal.ONE, BigDecimal.ONE);

        @Override
        public int compareTo(Q o) {
            return n.multiply(o.d).compareTo(o.n.multiply(d));
        }

        double value() {
            return n.divide(d, MathContext.DECIMAL128).doubleValue();
        }
    }

    /**
     * Exact time of impact of box against box (the time the open intervals first overlap on
     * both axes), or null for no hit within [0, 1).
     */
    static Q rectRect(double x, double y, double w, double h, double vx, double vy,
                      double ox, double oy, double ow, double oh) {
        BigDecimal[] lo = {d(ox).subtract(d(x)).subtract(d(w)), d(oy).subtract(d(y)).subtract(d(h))};
        BigDecimal[] hi = {d(ox).add(d(ow)).subtract(d(x)), d(oy).add(d(oh)).subtract(d(y))};
        BigDecimal[] v = {d(vx), d(vy)};
        Q enter = null, exit = null;  // null: unbounded
        for (int a = 0; a < 2; a++) {
            if (v[a].signum() == 0) {
                if (!(lo[a].signum() < 0 && hi[a].signum() > 0)) {
                    return null;
                }
                continue;
            }
            Q in = Q.of(v[a].signum() > 0 ? lo[a] : hi[a], v[a]);
            Q out = Q.of(v[a].signum() > 0 ? hi[a] : lo[a], v[a]);
            enter = enter == null || in.compareTo(enter) > 0 ? in : enter;
            exit = exit == null || out.compareTo(exit) < 0 ? out : exit;
        }
        if (enter == null) {
            return Q.ZERO;  // standing still, overlapping
        }
        if (enter.compareTo(exit) < 0 && exit.compareTo(Q.ZERO) > 0 && enter.compareTo(Q.ONE) < 0) {
            return enter.compareTo(Q.ZERO) > 0 ? enter : Q.ZERO;
        }
        return null;
    }

    /** Squared distance from the point to the segment a + u v, u in [0, 1], compared to r2: is it less? */
    static boolean segmentPointCloser(BigDecimal ax, BigDecimal ay, BigDecimal vx, BigDecimal vy,
                                      BigDecimal px, BigDecimal py, BigDecimal r2) {
        BigDecimal dx = px.subtract(ax), dy = py.subtract(ay);
        BigDecimal vv = vx.multiply(vx).add(vy.multiply(vy));
        BigDecimal dv = dx.multiply(vx).add(dy.multiply(vy));
        if (vv.signum() == 0 || dv.signum() <= 0) {
            return dx.multiply(dx).add(dy.multiply(dy)).compareTo(r2) < 0;
        }
        if (dv.compareTo(vv) >= 0) {
            BigDecimal ex = dx.subtract(vx), ey = dy.subtract(vy);
            return ex.multiply(ex).add(ey.multiply(ey)).compareTo(r2) < 0;
        }
        // |d|^2 - (d.v)^2 / |v|^2 < r2, times |v|^2.
        BigDecimal cross = dx.multiply(vy).subtract(dy.multiply(vx));
        return cross.multiply(cross).compareTo(r2.multiply(vv)) < 0;
    }

    /** Does a moving circle's inside meet the standing circle's at some t in [0, 1]? */
    static boolean circleCircleHits(double x, double y, double r, double vx, double vy,
                                    double ox, double oy, double or) {
        BigDecimal reach = d(r).add(d(or));
        if (reach.signum() <= 0) {
            return false;
        }
        return segmentPointCloser(d(x), d(y), d(vx), d(vy), d(ox), d(oy), reach.multiply(reach));
    }

    /** Does a moving circle's inside meet the standing rectangle's at some t in [0, 1]? */
    static boolean circleRectHits(double cx, double cy, double r, double vx, double vy,
                                  double rx, double ry, double rw, double rh) {
        if (r == 0) {
            return rectRect(cx, cy, 0, 0, vx, vy, rx, ry, rw, rh) != null;
        }
        // The centre's path comes closer than r to the closed rectangle.
        BigDecimal r2 = d(r).multiply(d(r));
        BigDecimal ax = d(cx), ay = d(cy), bx = ax.add(d(vx)), by = ay.add(d(vy));
        BigDecimal left = d(rx), top = d(ry), right = left.add(d(rw)), bottom = top.add(d(rh));
        if (segmentMeetsClosedBox(ax, ay, d(vx), d(vy), left, top, right, bottom)) {
            return true;
        }
        if (pointBox2(ax, ay, left, top, right, bottom).compareTo(r2) < 0
                || pointBox2(bx, by, left, top, right, bottom).compareTo(r2) < 0) {
            return true;
        }
        for (BigDecimal qx : new BigDecimal[] {left, right}) {
            for (BigDecimal qy : new BigDecimal[] {top, bottom}) {
                if (segmentPointCloser(ax, ay, d(vx), d(vy), qx, qy, r2)) {
                    return true;
                }
            }
        }
        return false;
    }

    private static BigDecimal pointBox2(BigDecimal px, BigDecimal py, BigDecimal l, BigDecimal t, BigDecimal r, BigDecimal b) {
        BigDecimal dx = px.compareTo(l) < 0 ? l.subtract(px) : px.compareTo(r) > 0 ? px.subtract(r) : BigDecimal.ZERO;
        BigDecimal dy = py.compareTo(t) < 0 ? t.subtract(py) : py.compareTo(b) > 0 ? py.subtract(b) : BigDecimal.ZERO;
        return dx.multiply(dx).add(dy.multiply(dy));
    }

    /** Does the closed segment a + u v, u in [0, 1], meet the closed box? Closed slabs. */
    private static boolean segmentMeetsClosedBox(BigDecimal ax, BigDecimal ay, BigDecimal vx, BigDecimal vy,
                                                 BigDecimal l, BigDecimal t, BigDecimal r, BigDecimal b) {
        Q enter = Q.ZERO, exit = Q.ONE;
        BigDecimal[] a = {ax, ay}, v = {vx, vy}, lo = {l, t}, hi = {r, b};
        for (int i = 0; i < 2; i++) {
            BigDecimal dl = lo[i].subtract(a[i]), dh = hi[i].subtract(a[i]);
            if (v[i].signum() == 0) {
                if (dl.signum() > 0 || dh.signum() < 0) {
                    return false;
                }
                continue;
            }
            Q in = Q.of(v[i].signum() > 0 ? dl : dh, v[i]);
            Q out = Q.of(v[i].signum() > 0 ? dh : dl, v[i]);
            enter = in.compareTo(enter) > 0 ? in : enter;
            exit = out.compareTo(exit) < 0 ? out : exit;
        }
        return enter.compareTo(exit) <= 0;
    }

    /**
     * Does the closed segment meet the open box at this moment? Computed in double: the
     * callers pass whole and half numbers and dyadic times, for which it is exact.
     */
    static boolean openBoxSegment(double x, double y, double w, double h,
                                  double x1, double y1, double x2, double y2) {
        double enter = Double.NEGATIVE_INFINITY, exit = Double.POSITIVE_INFINITY;
        double[] a = {x1, y1}, v = {x2 - x1, y2 - y1}, lo = {x, y}, hi = {x + w, y + h};
        for (int i = 0; i < 2; i++) {
            double dl = lo[i] - a[i], dh = hi[i] - a[i];
            if (v[i] == 0) {
                if (!(dl < 0 && dh > 0)) {
                    return false;
                }
                continue;
            }
            double in = (v[i] > 0 ? dl : dh) / v[i], out = (v[i] > 0 ? dh : dl) / v[i];
            enter = Math.max(enter, in);
            exit = Math.min(exit, out);
        }
        // (enter, exit) open, u in [0, 1] closed.
        return enter < exit && enter < 1 && exit > 0;
    }
}
