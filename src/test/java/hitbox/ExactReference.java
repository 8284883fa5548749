package hitbox;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.TreeSet;

/**
 * The slow, exact reference of the tests: each question written the most obvious way, in
 * exact arithmetic, and differently from the library on purpose, so that a test can say "the
 * library agrees with the maths" and not "the library agrees with itself".
 *
 * <p>Every float is a dyadic rational, and is taken without rounding: {@link #exact} as a
 * {@link BigDecimal} (sums, differences and products of which are exact), {@link Q#of(float)}
 * as a fraction of {@link BigInteger}s where a question needs division (crossing points).
 * So every answer here is the true answer for the given floats, by the <a
 * href="package-summary.html#touching">touching rule</a>: shapes with area are open, a
 * zero-size shape has no inside and collides only by reaching into the inside of a shape that
 * has one; segments and points are closed.
 *
 * <p>Written differently from the library: crossing points are computed (the library mostly
 * compares orientations), point in polygon is a winding number (the library counts crossings
 * even-odd), and two open polygons are compared by sampling one point in every cell of the
 * arrangement of their edge lines (the library reasons about edges and corners). Nothing here
 * is tuned for speed or shares code with the library. All arguments must be finite; sizes 0
 * or more.
 */
final class ExactReference {
    private ExactReference() {
    }

    /**
     * Whole-number offsets of up to 1e6, by which a test moves every shape of a case: the
     * library promises the same answer, touching cases included, after any of them.
     */
    static final float[][] WHOLE_OFFSETS = {
            {1_000_000, 1_000_000}, {-1_000_000, -1_000_000}, {1_000_000, -1_000_000},
            {-999_999, 654_321}, {0, 1_000_000}, {-1_000_000, 0},
    };

    // ------------------------------------------------------------ the tutorial's shapes

    /** The value exactly ({@code new BigDecimal(double)} is exact, and a float widens exactly). */
    static BigDecimal exact(double v) {
        return new BigDecimal(v);
    }

    /** The exact square of the distance between two points. */
    private static BigDecimal distanceSquared(float x1, float y1, float x2, float y2) {
        BigDecimal dx = exact(x2).subtract(exact(x1));
        BigDecimal dy = exact(y2).subtract(exact(y1));
        return dx.multiply(dx).add(dy.multiply(dy));
    }

    /** {@code (r1 + r2)^2 - d^2} for two circles: positive when they overlap, 0 when they touch. */
    static BigDecimal circleCircleMargin(float x1, float y1, float r1, float x2, float y2, float r2) {
        BigDecimal reach = exact(r1).add(exact(r2));
        return reach.multiply(reach).subtract(distanceSquared(x1, y1, x2, y2));
    }

    /**
     * Do the circles overlap: are the centres closer than the sum of the radii? With one radius
     * 0 this is the other circle containing a point; with both 0 it is never true.
     */
    static boolean circleCircle(float x1, float y1, float r1, float x2, float y2, float r2) {
        return circleCircleMargin(x1, y1, r1, x2, y2, r2).signum() > 0;
    }

    /** Is the point strictly inside the circle: closer to the centre than the radius? */
    static boolean circlePoint(float cx, float cy, float r, float px, float py) {
        return circleCircle(cx, cy, r, px, py, 0);
    }

    /**
     * Do the rectangles overlap? A rectangle with area is open; one of width or height 0 is a
     * segment (without its ends) or a point that must reach into the other's inside. Two of
     * them meet only when they cross like a plus sign, as the tutorial's comparisons say.
     */
    static boolean rectRect(float x1, float y1, float w1, float h1,
                            float x2, float y2, float w2, float h2) {
        // Boxes meet when they meet along each axis. An open interval (a, b) and a closed one
        // [c, d] share a point when c < b and a < d; two open ones, likewise.
        return openMeetsClosed(x1, w1, x2, w2) && openMeetsClosed(y1, h1, y2, h2);
    }

    /** Is the point strictly between the left and right edges, and the top and bottom edges? */
    static boolean rectPoint(float rx, float ry, float rw, float rh, float px, float py) {
        return rectRect(rx, ry, rw, rh, px, py, 0, 0);
    }

    /**
     * {@code r^2} minus the squared distance from the circle's centre to the closed rectangle
     * (its nearest point: the centre clamped into it): positive when the open disk reaches
     * into the rectangle, 0 when the outline touches it.
     */
    static BigDecimal circleRectMargin(float cx, float cy, float r, float rx, float ry, float rw, float rh) {
        BigDecimal nearestX = exact(cx).max(exact(rx)).min(exact(rx).add(exact(rw)));
        BigDecimal nearestY = exact(cy).max(exact(ry)).min(exact(ry).add(exact(rh)));
        BigDecimal dx = exact(cx).subtract(nearestX);
        BigDecimal dy = exact(cy).subtract(nearestY);
        BigDecimal radius = exact(r);
        return radius.multiply(radius).subtract(dx.multiply(dx).add(dy.multiply(dy)));
    }

    /**
     * Does the circle overlap the rectangle? A circle of radius 0 is a point, which must be
     * strictly inside; otherwise the open disk must reach the closed rectangle.
     */
    static boolean circleRect(float cx, float cy, float r, float rx, float ry, float rw, float rh) {
        return r == 0 ? rectPoint(rx, ry, rw, rh, cx, cy) : circleRectMargin(cx, cy, r, rx, ry, rw, rh).signum() > 0;
    }

    /** Do [s1, s1 + l1] and [s2, s2 + l2] share a point, with at least one of them open? */
    private static boolean openMeetsClosed(float s1, float l1, float s2, float l2) {
        return exact(s2).compareTo(exact(s1).add(exact(l1))) < 0 && exact(s1).compareTo(exact(s2).add(exact(l2))) < 0;
    }

    // ------------------------------------------------------- polygons, segments, rays

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
            // f = m 2^e with a whole m of 24 bits at most: its bits, read as they are.
            if (f == 0) {
                return ZERO;
            }
            int e = Math.getExponent(f) - 23;
            long m = (long) Math.scalb(f, -e); // exact: f has 24 significant bits
            return e >= 0 ? new Q(BigInteger.valueOf(m).shiftLeft(e), BigInteger.ONE)
                    : new Q(BigInteger.valueOf(m), BigInteger.ONE.shiftLeft(-e));
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

        /** The nearest double, near enough: correct to 34 digits before the last rounding. */
        double toDouble() {
            return new BigDecimal(num).divide(new BigDecimal(den), MathContext.DECIMAL128).doubleValue();
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
    static Q segmentDistanceSquared(Q ax, Q ay, Q bx, Q by, Q cx, Q cy) {
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
        return r > 0 && segmentDistanceSquared(Q.of(x1), Q.of(y1), Q.of(x2), Q.of(y2), Q.of(cx), Q.of(cy))
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
            if (segmentDistanceSquared(p[2 * i], p[2 * i + 1], p[2 * k], p[2 * k + 1], x, y).compareTo(rr) < 0) {
                return true;
            }
        }
        return false;
    }

    /**
     * Where the ray {@code o + s d} ({@code s} from 0, up to {@code reach}, or without end when
     * {@code reach} is null) is inside the open polygon (convex or not), exactly: the stretches
     * {@code {in, out}} of s, in order. The ray is cut wherever it meets the outline (crossing an
     * edge, passing a vertex, or running along an edge, whose ends are cuts); between two cuts
     * nothing changes, so the winding number at each piece's middle tells the whole story.
     * Pieces inside on both sides of a cut (a ray that grazes a reflex corner from inside) are
     * one stretch. A bounded polygon is behind the ray's last cut.
     */
    static List<Q[]> rayInside(float[] polygon, float ox, float oy, float dx, float dy, Q reach) {
        return rayInside(toQ(polygon), Q.of(ox), Q.of(oy), Q.of(dx), Q.of(dy), reach);
    }

    private static List<Q[]> rayInside(Q[] p, Q x, Q y, Q vx, Q vy, Q reach) {
        Q vv = vx.times(vx).plus(vy.times(vy));
        TreeSet<Q> cuts = new TreeSet<>(List.of(Q.ZERO));
        int n = p.length / 2;
        for (int i = 0; i < n; i++) {
            int k = (i + 1) % n;
            Q ex = p[2 * k].minus(p[2 * i]), ey = p[2 * k + 1].minus(p[2 * i + 1]);
            Q fx = p[2 * i].minus(x), fy = p[2 * i + 1].minus(y);
            Q den = cross(vx, vy, ex, ey);
            if (den.signum() != 0) {
                // o + s d = a + u e: s = (f x e) / (d x e), u = (f x d) / (d x e).
                Q at = cross(fx, fy, ex, ey).div(den), u = cross(fx, fy, vx, vy).div(den);
                if (at.signum() >= 0 && u.signum() >= 0 && u.compareTo(Q.ONE) <= 0) {
                    cuts.add(at);
                }
            } else if (cross(fx, fy, vx, vy).signum() == 0) {
                // Along the edge's line: both ends are cuts.
                Q gx = p[2 * k].minus(x), gy = p[2 * k + 1].minus(y);
                for (Q at : List.of(fx.times(vx).plus(fy.times(vy)).div(vv), gx.times(vx).plus(gy.times(vy)).div(vv))) {
                    if (at.signum() >= 0) {
                        cuts.add(at);
                    }
                }
            }
        }
        if (reach != null) {
            cuts.removeIf(c -> c.compareTo(reach) > 0);
            cuts.add(reach);
        } else {
            cuts.add(cuts.last().plus(Q.ONE));
        }
        List<Q> cs = new ArrayList<>(cuts);
        List<Q[]> inside = new ArrayList<>();
        if (locate(p, x, y) == Where.INSIDE) {
            inside.add(new Q[] {Q.ZERO, Q.ZERO});
        }
        for (int i = 0; i + 1 < cs.size(); i++) {
            Q m = cs.get(i).mid(cs.get(i + 1));
            if (locate(p, x.plus(m.times(vx)), y.plus(m.times(vy))) != Where.INSIDE) {
                continue;
            }
            Q[] last = inside.isEmpty() ? null : inside.get(inside.size() - 1);
            if (last != null && last[1].compareTo(cs.get(i)) == 0) {
                last[1] = cs.get(i + 1);
            } else {
                inside.add(new Q[] {cs.get(i), cs.get(i + 1)});
            }
        }
        return inside;
    }

    /**
     * The outward normals (not of unit length) of the polygon's edges that hold the point
     * {@code o + s d} and face the ray (the ray runs against them): one edge, two at a
     * corner, none for a point off the outline.
     */
    static List<Q[]> facingNormalsAt(float[] polygon, float ox, float oy, float dx, float dy, Q s) {
        Q[] p = toQ(polygon);
        Q vx = Q.of(dx), vy = Q.of(dy);
        Q px = Q.of(ox).plus(s.times(vx)), py = Q.of(oy).plus(s.times(vy));
        int n = p.length / 2;
        Q area = Q.ZERO;
        for (int i = 0; i < n; i++) {
            int k = (i + 1) % n;
            area = area.plus(cross(p[2 * i], p[2 * i + 1], p[2 * k], p[2 * k + 1]));
        }
        Q turn = Q.of(area.signum());
        List<Q[]> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            int k = (i + 1) % n;
            // Outward: (e_y, -e_x) for a positive signed area (counter-clockwise with y up).
            Q nx = turn.times(p[2 * k + 1].minus(p[2 * i + 1])), ny = turn.times(p[2 * i].minus(p[2 * k]));
            if (onSegment(p[2 * i], p[2 * i + 1], p[2 * k], p[2 * k + 1], px, py)
                    && nx.times(vx).plus(ny.times(vy)).signum() < 0) {
                out.add(new Q[] {nx, ny});
            }
        }
        return out;
    }

    /**
     * The separating axis theorem written out for two convex vertex lists (either winding, or
     * flat: a segment's two ends, a point's one; in double, so that a rectangle's far side
     * {@code x + w} is exact): every edge normal m of both, every vertex
     * projected, exactly. Null when some axis separates them (their shadows on it overlap by 0
     * or less: open shapes that touch do not overlap); else every push of b out of a, both
     * ways along each axis, as {@code {mx, my, overlap}}: b moved by {@code m overlap / |m|^2}
     * just touches a, a move of length {@code overlap / |m|}. For convex shapes the shortest of
     * these is the minimum translation.
     */
    static List<BigDecimal[]> convexPushes(double[] a, double[] b) {
        List<BigDecimal[]> pushes = new ArrayList<>();
        for (double[] owner : List.of(a, b)) {
            int n = owner.length / 2;
            for (int i = 0; i < n; i++) {
                int k = (i + 1) % n;
                BigDecimal mx = exact(owner[2 * i + 1]).subtract(exact(owner[2 * k + 1]));
                BigDecimal my = exact(owner[2 * k]).subtract(exact(owner[2 * i]));
                if (mx.signum() == 0 && my.signum() == 0) {
                    continue;
                }
                BigDecimal[] sa = shadow(a, mx, my), sb = shadow(b, mx, my);
                BigDecimal forward = sa[1].subtract(sb[0]), back = sb[1].subtract(sa[0]);
                if (forward.signum() <= 0 || back.signum() <= 0) {
                    return null;
                }
                pushes.add(new BigDecimal[] {mx, my, forward});
                pushes.add(new BigDecimal[] {mx.negate(), my.negate(), back});
            }
        }
        return pushes;
    }

    /** The least and greatest of {@code p . m} over the vertices. */
    private static BigDecimal[] shadow(double[] p, BigDecimal mx, BigDecimal my) {
        BigDecimal lo = null, hi = null;
        for (int k = 0; k < p.length; k += 2) {
            BigDecimal v = exact(p[k]).multiply(mx).add(exact(p[k + 1]).multiply(my));
            lo = lo == null || v.compareTo(lo) < 0 ? v : lo;
            hi = hi == null || v.compareTo(hi) > 0 ? v : hi;
        }
        return new BigDecimal[] {lo, hi};
    }

    /** The four corners of a rectangle, as a polygon. */
    static float[] rectPolygon(float x, float y, float w, float h) {
        return new float[] {x, y, x + w, y, x + w, y + h, x, y + h};
    }

    /**
     * A closed segment meets the open polygon: some stretch of it is inside ({@link
     * #rayInside} up to its far end), or, for a segment of length 0, its one point is.
     */
    static boolean segmentPolygon(float[] polygon, float x1, float y1, float x2, float y2) {
        Q[] p = toQ(polygon);
        Q ax = Q.of(x1), ay = Q.of(y1), dx = Q.of(x2).minus(ax), dy = Q.of(y2).minus(ay);
        if (dx.signum() == 0 && dy.signum() == 0) {
            return locate(p, ax, ay) == Where.INSIDE;
        }
        return !rayInside(p, ax, ay, dx, dy, Q.ONE).isEmpty();
    }

    /**
     * Two open polygons share a point: sample one point in every cell of the arrangement of
     * all edge lines (vertical decomposition: a vertical line between any two neighbouring
     * "event" x values, where no two lines cross, and on it a point between any two
     * neighbouring line crossings). Inside a cell nothing changes, so the search is complete.
     */
    static boolean polygonsMeet(float[] a, float[] b) {
        return polygonsMeet(toQ(a), toQ(b));
    }

    /**
     * The rectangle (x, y, w, h) as a polygon with its corners summed exactly ({@code x + w}
     * as a real number, not rounded to float as {@link #rectPolygon} rounds it).
     */
    static Q[] rectQ(float x, float y, float w, float h) {
        Q l = Q.of(x), t = Q.of(y), r = l.plus(Q.of(w)), b = t.plus(Q.of(h));
        return new Q[] {l, t, r, t, r, b, l, b};
    }

    /** {@link #polygonsMeet(float[], float[])} for exact corners. */
    static boolean polygonsMeet(Q[] p, Q[] q) {
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

    // ------------------------------------------------------------------- vertex lists

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
