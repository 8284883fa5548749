package hitbox;

import java.math.BigInteger;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.TreeSet;

/**
 * Slow, exact answers for the property tests, in rational arithmetic ({@link BigInteger}), and
 * written differently from the library on purpose: crossing points are computed (the library
 * never computes them), point in polygon is a winding number (the library counts crossings
 * even-odd), and open shapes are compared by sampling one point in every cell of the
 * arrangement of their edge lines (the library reasons about edges and corners).
 *
 * <p>Coordinates are whole numbers (small ones: the point is exactness, not speed).
 */
final class GeometryReference {
    private GeometryReference() {
    }

    /** A rational number, always reduced, with a positive denominator. */
    record Q(BigInteger num, BigInteger den) implements Comparable<Q> {
        static final Q ZERO = of(0);
        static final Q ONE = of(1);

        Q {
            if (den.signum() == 0) {
                throw new ArithmeticException("zero denominator");
            }
            if (den.signum() < 0) {
                num = num.negate();
                den = den.negate();
            }
            BigInteger g = num.gcd(den);
            if (!g.equals(BigInteger.ONE) && g.signum() != 0) {
                num = num.divide(g);
                den = den.divide(g);
            }
        }

        static Q of(long n) {
            return new Q(BigInteger.valueOf(n), BigInteger.ONE);
        }

        static Q of(long n, long d) {
            return new Q(BigInteger.valueOf(n), BigInteger.valueOf(d));
        }

        /** The exact value of a float (a float is a dyadic rational). */
        static Q of(float f) {
            java.math.BigDecimal b = new java.math.BigDecimal(f);
            return b.scale() <= 0 ? new Q(b.toBigIntegerExact(), BigInteger.ONE)
                    : new Q(b.unscaledValue(), BigInteger.TEN.pow(b.scale()));
        }

        Q plus(Q o) {
            return new Q(num.multiply(o.den).add(o.num.multiply(den)), den.multiply(o.den));
        }

        Q minus(Q o) {
            return new Q(num.multiply(o.den).subtract(o.num.multiply(den)), den.multiply(o.den));
        }

        Q times(Q o) {
            return new Q(num.multiply(o.num), den.multiply(o.den));
        }

        Q div(Q o) {
            return new Q(num.multiply(o.den), den.multiply(o.num));
        }

        Q mid(Q o) {
            return plus(o).div(of(2));
        }

        int signum() {
            return num.signum();
        }

        @Override
        public int compareTo(Q o) {
            return num.multiply(o.den).compareTo(o.num.multiply(den));
        }
    }

    enum Where { INSIDE, ON, OUTSIDE }

    static Q cross(Q ax, Q ay, Q bx, Q by) {
        return ax.times(by).minus(ay.times(bx));
    }

    /** (b - a) x (p - a): positive, negative or zero, exactly. */
    static int orient(Q ax, Q ay, Q bx, Q by, Q px, Q py) {
        return cross(bx.minus(ax), by.minus(ay), px.minus(ax), py.minus(ay)).signum();
    }

    /** Is p on the closed segment ab? Collinear, and the projection parameter in [0, 1]. */
    static boolean onSegment(Q ax, Q ay, Q bx, Q by, Q px, Q py) {
        if (orient(ax, ay, bx, by, px, py) != 0) {
            return false;
        }
        Q dx = bx.minus(ax);
        Q dy = by.minus(ay);
        Q t = px.minus(ax).times(dx).plus(py.minus(ay).times(dy));
        Q len2 = dx.times(dx).plus(dy.times(dy));
        if (len2.signum() == 0) {
            return px.compareTo(ax) == 0 && py.compareTo(ay) == 0;
        }
        return t.signum() >= 0 && t.compareTo(len2) <= 0;
    }

    static Q[] toQ(float[] xy) {
        Q[] q = new Q[xy.length];
        for (int i = 0; i < xy.length; i++) {
            q[i] = Q.of(xy[i]);
        }
        return q;
    }

    /** Where the point is, by winding number (Sunday's algorithm) with exact on-edge detection. */
    static Where locate(float[] polygon, Q px, Q py) {
        return locate(toQ(polygon), px, py);
    }

    static Where locate(Q[] p, Q px, Q py) {
        int n = p.length / 2;
        int winding = 0;
        for (int i = 0; i < n; i++) {
            int k = (i + 1) % n;
            Q ax = p[2 * i], ay = p[2 * i + 1], bx = p[2 * k], by = p[2 * k + 1];
            if (onSegment(ax, ay, bx, by, px, py)) {
                return Where.ON;
            }
            if (ay.compareTo(py) <= 0) {
                if (by.compareTo(py) > 0 && orient(ax, ay, bx, by, px, py) > 0) {
                    winding++;
                }
            } else if (by.compareTo(py) <= 0 && orient(ax, ay, bx, by, px, py) < 0) {
                winding--;
            }
        }
        return winding != 0 ? Where.INSIDE : Where.OUTSIDE;
    }

    static boolean polygonPoint(float[] polygon, float px, float py) {
        return locate(polygon, Q.of(px), Q.of(py)) == Where.INSIDE;
    }

    /** Closed segments meet: solve for the crossing parameters; parallel cases by projection. */
    static boolean segmentsMeet(float x1, float y1, float x2, float y2, float x3, float y3, float x4, float y4) {
        Q ax = Q.of(x1), ay = Q.of(y1), bx = Q.of(x2), by = Q.of(y2);
        Q cx = Q.of(x3), cy = Q.of(y3), dx = Q.of(x4), dy = Q.of(y4);
        Q ux = bx.minus(ax), uy = by.minus(ay), vx = dx.minus(cx), vy = dy.minus(cy);
        Q fx = cx.minus(ax), fy = cy.minus(ay);
        boolean uZero = ux.signum() == 0 && uy.signum() == 0;
        boolean vZero = vx.signum() == 0 && vy.signum() == 0;
        if (uZero && vZero) {
            return ax.compareTo(cx) == 0 && ay.compareTo(cy) == 0;
        }
        if (uZero) {
            return onSegment(cx, cy, dx, dy, ax, ay);
        }
        if (vZero) {
            return onSegment(ax, ay, bx, by, cx, cy);
        }
        Q den = cross(ux, uy, vx, vy);
        if (den.signum() != 0) {
            Q t = cross(fx, fy, vx, vy).div(den);
            Q s = cross(fx, fy, ux, uy).div(den);
            return t.signum() >= 0 && t.compareTo(Q.ONE) <= 0 && s.signum() >= 0 && s.compareTo(Q.ONE) <= 0;
        }
        if (cross(fx, fy, ux, uy).signum() != 0) {
            return false; // parallel, on different lines
        }
        // Collinear: project both ends of the second onto the first, as parameters.
        Q len2 = ux.times(ux).plus(uy.times(uy));
        Q t3 = fx.times(ux).plus(fy.times(uy)).div(len2);
        Q t4 = dx.minus(ax).times(ux).plus(dy.minus(ay).times(uy)).div(len2);
        Q lo = t3.compareTo(t4) <= 0 ? t3 : t4;
        Q hi = t3.compareTo(t4) <= 0 ? t4 : t3;
        return lo.compareTo(Q.ONE) <= 0 && hi.signum() >= 0;
    }

    /** Squared distance from c to the closed segment ab, by the clamped projection. */
    static Q distanceSquared(Q ax, Q ay, Q bx, Q by, Q cx, Q cy) {
        Q dx = bx.minus(ax), dy = by.minus(ay);
        Q len2 = dx.times(dx).plus(dy.times(dy));
        Q t = Q.ZERO;
        if (len2.signum() != 0) {
            t = cx.minus(ax).times(dx).plus(cy.minus(ay).times(dy)).div(len2);
            t = t.signum() < 0 ? Q.ZERO : (t.compareTo(Q.ONE) > 0 ? Q.ONE : t);
        }
        Q ex = ax.plus(t.times(dx)).minus(cx);
        Q ey = ay.plus(t.times(dy)).minus(cy);
        return ex.times(ex).plus(ey.times(ey));
    }

    /** A closed segment reaches the open disk: its closest point is nearer than r. */
    static boolean segmentCircle(float x1, float y1, float x2, float y2, float cx, float cy, float r) {
        Q rr = Q.of(r);
        return r > 0 && distanceSquared(Q.of(x1), Q.of(y1), Q.of(x2), Q.of(y2), Q.of(cx), Q.of(cy))
                .compareTo(rr.times(rr)) < 0;
    }

    /** The open polygon meets the open disk (or, for radius 0, contains its centre). */
    static boolean polygonCircle(float[] polygon, float cx, float cy, float r) {
        Q[] p = toQ(polygon);
        Q x = Q.of(cx), y = Q.of(cy);
        Where w = locate(p, x, y);
        if (r == 0 || w != Where.OUTSIDE) {
            return w == Where.INSIDE || (r > 0 && w == Where.ON);
        }
        Q rr = Q.of(r).times(Q.of(r));
        int n = p.length / 2;
        for (int i = 0; i < n; i++) {
            int k = (i + 1) % n;
            if (distanceSquared(p[2 * i], p[2 * i + 1], p[2 * k], p[2 * k + 1], x, y).compareTo(rr) < 0) {
                return true;
            }
        }
        return false;
    }

    /** The four corners of a rectangle, as a polygon. */
    static float[] rectPolygon(float x, float y, float w, float h) {
        return new float[] {x, y, x + w, y, x + w, y + h, x, y + h};
    }

    /**
     * A closed segment meets the open polygon: cut the segment wherever it crosses an edge's
     * line or passes a vertex; between two cuts nothing changes, so testing every cut and
     * every midpoint between cuts is a complete search.
     */
    static boolean segmentPolygon(float[] polygon, float x1, float y1, float x2, float y2) {
        Q[] p = toQ(polygon);
        Q ax = Q.of(x1), ay = Q.of(y1), dx = Q.of(x2).minus(ax), dy = Q.of(y2).minus(ay);
        if (dx.signum() == 0 && dy.signum() == 0) {
            return locate(p, ax, ay) == Where.INSIDE;
        }
        TreeSet<Q> cuts = new TreeSet<>(List.of(Q.ZERO, Q.ONE));
        int n = p.length / 2;
        Q len2 = dx.times(dx).plus(dy.times(dy));
        for (int i = 0; i < n; i++) {
            int k = (i + 1) % n;
            Q ex = p[2 * k].minus(p[2 * i]), ey = p[2 * k + 1].minus(p[2 * i + 1]);
            Q fx = p[2 * i].minus(ax), fy = p[2 * i + 1].minus(ay);
            Q den = cross(dx, dy, ex, ey);
            if (den.signum() != 0) {
                addCut(cuts, cross(fx, fy, ex, ey).div(den));
            }
            if (cross(dx, dy, fx, fy).signum() == 0) {
                addCut(cuts, fx.times(dx).plus(fy.times(dy)).div(len2)); // vertex on the line
            }
        }
        List<Q> ts = new ArrayList<>(cuts);
        for (int i = 0; i < ts.size(); i++) {
            if (at(p, ax, ay, dx, dy, ts.get(i)) == Where.INSIDE) {
                return true;
            }
            if (i + 1 < ts.size() && at(p, ax, ay, dx, dy, ts.get(i).mid(ts.get(i + 1))) == Where.INSIDE) {
                return true;
            }
        }
        return false;
    }

    private static void addCut(TreeSet<Q> cuts, Q t) {
        if (t.signum() > 0 && t.compareTo(Q.ONE) < 0) {
            cuts.add(t);
        }
    }

    private static Where at(Q[] p, Q ax, Q ay, Q dx, Q dy, Q t) {
        return locate(p, ax.plus(t.times(dx)), ay.plus(t.times(dy)));
    }

    /**
     * Two open polygons share a point: sample one point in every cell of the arrangement of
     * all edge lines (vertical decomposition: a vertical line between any two neighbouring
     * "event" x values, where no two lines cross, and on it a point between any two
     * neighbouring line crossings). Inside a cell nothing changes, so the search is complete.
     */
    static boolean polygonsMeet(float[] a, float[] b) {
        Q[] p = toQ(a);
        Q[] q = toQ(b);
        List<Q[]> lines = new ArrayList<>(); // {A, B, C}: A x + B y = C
        for (Q[] poly : List.of(p, q)) {
            int n = poly.length / 2;
            for (int i = 0; i < n; i++) {
                int k = (i + 1) % n;
                Q x1 = poly[2 * i], y1 = poly[2 * i + 1], x2 = poly[2 * k], y2 = poly[2 * k + 1];
                Q aa = y2.minus(y1), bb = x1.minus(x2);
                lines.add(new Q[] {aa, bb, aa.times(x1).plus(bb.times(y1))});
            }
        }
        // Both insides lie within both bounding boxes: only sample where those overlap.
        Q loX = max(min(p, 0), min(q, 0)), hiX = min(max(p, 0), max(q, 0));
        Q loY = max(min(p, 1), min(q, 1)), hiY = min(max(p, 1), max(q, 1));
        if (loX.compareTo(hiX) >= 0 || loY.compareTo(hiY) >= 0) {
            return false;
        }
        TreeSet<Q> xs = new TreeSet<>(List.of(loX, hiX));
        for (int i = 0; i < lines.size(); i++) {
            Q[] l = lines.get(i);
            if (l[1].signum() == 0) {
                addBetween(xs, l[2].div(l[0]), loX, hiX); // a vertical line
            }
            for (int j = i + 1; j < lines.size(); j++) {
                Q[] m = lines.get(j);
                Q det = l[0].times(m[1]).minus(m[0].times(l[1]));
                if (det.signum() != 0) {
                    addBetween(xs, l[2].times(m[1]).minus(m[2].times(l[1])).div(det), loX, hiX);
                }
            }
        }
        List<Q> xl = new ArrayList<>(xs);
        for (int i = 0; i + 1 < xl.size(); i++) {
            Q x = xl.get(i).mid(xl.get(i + 1));
            TreeSet<Q> ys = new TreeSet<>(List.of(loY, hiY));
            for (Q[] l : lines) {
                if (l[1].signum() != 0) {
                    addBetween(ys, l[2].minus(l[0].times(x)).div(l[1]), loY, hiY);
                }
            }
            List<Q> yl = new ArrayList<>(ys);
            for (int j = 0; j + 1 < yl.size(); j++) {
                Q y = yl.get(j).mid(yl.get(j + 1));
                if (locate(p, x, y) == Where.INSIDE && locate(q, x, y) == Where.INSIDE) {
                    return true;
                }
            }
        }
        return false;
    }

    private static void addBetween(TreeSet<Q> set, Q v, Q lo, Q hi) {
        if (v.compareTo(lo) > 0 && v.compareTo(hi) < 0) {
            set.add(v);
        }
    }

    private static Q min(Q[] p, int axis) {
        Q m = p[axis];
        for (int i = axis; i < p.length; i += 2) {
            m = p[i].compareTo(m) < 0 ? p[i] : m;
        }
        return m;
    }

    private static Q max(Q[] p, int axis) {
        Q m = p[axis];
        for (int i = axis; i < p.length; i += 2) {
            m = p[i].compareTo(m) > 0 ? p[i] : m;
        }
        return m;
    }

    private static Q max(Q a, Q b) {
        return a.compareTo(b) >= 0 ? a : b;
    }

    private static Q min(Q a, Q b) {
        return a.compareTo(b) <= 0 ? a : b;
    }

    /**
     * Is the vertex list a simple polygon? At least 3 vertices, no vertex equal to the next,
     * not all on one line, edges that are not neighbours never meet, and neighbours meet only
     * at their shared vertex.
     */
    static boolean isSimple(float[] xy) {
        if (xy.length % 2 != 0 || xy.length < 6) {
            return false;
        }
        Q[] p = toQ(xy);
        int n = p.length / 2;
        boolean flat = true;
        for (int i = 0; i < n; i++) {
            int k = (i + 1) % n;
            if (p[2 * i].compareTo(p[2 * k]) == 0 && p[2 * i + 1].compareTo(p[2 * k + 1]) == 0) {
                return false;
            }
            flat &= orient(p[0], p[1], p[2], p[3], p[2 * i], p[2 * i + 1]) == 0;
        }
        if (flat) {
            return false;
        }
        for (int i = 0; i < n; i++) {
            int b = (i + 1) % n, c = (i + 2) % n;
            // Neighbours i and i + 1 share vertex b: neither far end may lie on the other edge.
            if (onSegment(p[2 * i], p[2 * i + 1], p[2 * b], p[2 * b + 1], p[2 * c], p[2 * c + 1])
                    || onSegment(p[2 * b], p[2 * b + 1], p[2 * c], p[2 * c + 1], p[2 * i], p[2 * i + 1])) {
                return false;
            }
            for (int j = 0; j < n; j++) {
                int d = (j + 1) % n;
                if (j == i || d == i || j == b) {
                    continue;
                }
                if (segmentsMeet(xy[2 * i], xy[2 * i + 1], xy[2 * b], xy[2 * b + 1],
                        xy[2 * j], xy[2 * j + 1], xy[2 * d], xy[2 * d + 1])) {
                    return false;
                }
            }
        }
        return true;
    }

    /** The vertices in reverse order (the other winding), starting from the same vertex. */
    static float[] reversed(float[] xy) {
        int n = xy.length / 2;
        float[] r = new float[xy.length];
        for (int i = 0; i < n; i++) {
            int k = (n - i) % n;
            r[2 * i] = xy[2 * k];
            r[2 * i + 1] = xy[2 * k + 1];
        }
        return r;
    }

    /** The same outline, listed from vertex {@code start}. */
    static float[] rotated(float[] xy, int start) {
        int n = xy.length / 2;
        float[] r = new float[xy.length];
        for (int i = 0; i < n; i++) {
            int k = (i + start) % n;
            r[2 * i] = xy[2 * k];
            r[2 * i + 1] = xy[2 * k + 1];
        }
        return r;
    }

    /** Every coordinate moved by (dx, dy). */
    static float[] translated(float[] xy, float dx, float dy) {
        float[] r = xy.clone();
        for (int i = 0; i < r.length; i += 2) {
            r[i] += dx;
            r[i + 1] += dy;
        }
        return r;
    }

    /**
     * A star-shaped vertex list from some points: sorted by angle around their mean, so it is
     * usually simple (often concave); callers keep only those {@link #isSimple} accepts.
     */
    static float[] starPolygon(List<int[]> points, boolean reverse) {
        List<int[]> distinct = new ArrayList<>();
        for (int[] pt : points) {
            if (distinct.stream().noneMatch(d -> Arrays.equals(d, pt))) {
                distinct.add(pt);
            }
        }
        double mx = distinct.stream().mapToInt(pt -> pt[0]).average().orElse(0) + 0.01;
        double my = distinct.stream().mapToInt(pt -> pt[1]).average().orElse(0) + 0.003;
        distinct.sort((u, v) -> Double.compare(Math.atan2(u[1] - my, u[0] - mx), Math.atan2(v[1] - my, v[0] - mx)));
        float[] xy = new float[2 * distinct.size()];
        for (int i = 0; i < distinct.size(); i++) {
            xy[2 * i] = distinct.get(i)[0];
            xy[2 * i + 1] = distinct.get(i)[1];
        }
        return reverse ? reversed(xy) : xy;
    }
}
