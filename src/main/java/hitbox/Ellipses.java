package hitbox;

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
 */
final class Ellipses {
    private Ellipses() {
    }

    /** 4 units in the last place, bound on the rounding of a sum of three rounded squares. */
    private static final double SUM_ERROR = 8 * 0x1p-53;

    /**
     * The exact sign of {@code ((qx - cx) b)^2 + ((qy - cy) a)^2 - (a b)^2}: negative inside
     * the ellipse (centre cx, cy, radii a, b), 0 on its outline, positive outside.
     */
    static int side(double qx, double qy, double cx, double cy, double a, double b) {
        double u = (qx - cx) * b, v = (qy - cy) * a, w = a * b;
        double s = u * u + v * v - w * w;
        double bound = SUM_ERROR * (u * u + v * v + w * w);
        if (!(bound < Double.POSITIVE_INFINITY) || s != s) {
            return s < 0 ? -1 : 1; // infinite values or overflow: compared as they come, NaN is outside
        }
        if (s > bound) {
            return 1;
        }
        if (-s > bound) {
            return -1;
        }
        BigDecimal bu = new BigDecimal(qx).subtract(new BigDecimal(cx)).multiply(new BigDecimal(b));
        BigDecimal bv = new BigDecimal(qy).subtract(new BigDecimal(cy)).multiply(new BigDecimal(a));
        BigDecimal bw = new BigDecimal(a).multiply(new BigDecimal(b));
        return bu.multiply(bu).add(bv.multiply(bv)).subtract(bw.multiply(bw)).signum();
    }

    /** Is the point strictly inside the ellipse? A flat ellipse has no inside. */
    static boolean point(float x, float y, float a, float b, float px, float py) {
        return a > 0 && b > 0 && side(px, py, x, y, a, b) < 0;
    }

    /** The ellipse's box, as a flat rectangle when a radius is 0 (left, top, width, height in float). */
    static float[] box(float x, float y, float a, float b) {
        return new float[] {x - a, y - b, 2 * a, 2 * b};
    }

    /** Ellipse and rectangle, both real (radii and sizes > 0 for the ellipse; any size for the rectangle). */
    static boolean rect(float x, float y, float a, float b, float rx, float ry, float rw, float rh) {
        double qx = Collide.clamp(x, rx, (double) rx + rw);
        double qy = Collide.clamp(y, ry, (double) ry + rh);
        // The rectangle's point nearest the centre, in the scaled plane as in this one.
        return side(qx, qy, x, y, a, b) < 0;
    }

    /**
     * A closed segment and a real ellipse: in the plane scaled by (b, a) about the centre, is
     * the segment closer to the centre than a b (or, if {@code closed}, at most that far)?
     */
    static boolean segment(float x, float y, float a, float b, float x1, float y1, float x2, float y2, boolean closed) {
        double px = ((double) x1 - x) * b, py = ((double) y1 - y) * a;
        double qx = ((double) x2 - x) * b, qy = ((double) y2 - y) * a;
        double reach = (double) a * b;
        return Capsules.nearOrigin(px, py, qx, qy, reach, closed);
    }

    /** A polygon's raw outline (at least 3 vertices, no NaN) and a real ellipse. */
    static boolean polygon(float[] xy, float x, float y, float a, float b) {
        int n = xy.length / 2;
        for (int i = 0, h = n - 1; i < n; h = i++) {
            if (segment(x, y, a, b, xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], false)) {
                return true;
            }
        }
        return Polygons.contains(xy, x, y);
    }

    /** A real ellipse and a circle of radius r > 0. */
    static boolean circle(float x, float y, float a, float b, float cx, float cy, float r) {
        int sure = discs((double) cx - x, (double) cy - y, a, b, r, r);
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
    static int discs(double dx, double dy, double a1, double b1, double a2, double b2) {
        double d2 = dx * dx + dy * dy;
        double inner = Math.min(a1, b1) + Math.min(a2, b2), outer = Math.max(a1, b1) + Math.max(a2, b2);
        if (d2 < inner * inner * (1 - 1e-9)) {
            return 1;
        }
        if (d2 > outer * outer * (1 + 1e-9)) {
            return -1;
        }
        return 0;
    }

    /** Does ellipse (x1, y1, a1, b1) come before ellipse (x2, y2, a2, b2) in a fixed order? Makes the pair's answer symmetric. */
    static boolean before(float x1, float y1, float a1, float b1, float x2, float y2, float a2, float b2) {
        int c = Float.compare(x1, x2);
        c = c != 0 ? c : Float.compare(y1, y2);
        c = c != 0 ? c : Float.compare(a1, a2);
        return (c != 0 ? c : Float.compare(b1, b2)) < 0;
    }

    /** Two real ellipses: the first scaled into a circle of radius a1 b1, the second stays an ellipse. */
    static boolean ellipse(float x1, float y1, float a1, float b1, float x2, float y2, float a2, float b2) {
        int sure = discs((double) x2 - x1, (double) y2 - y1, a1, b1, a2, b2);
        if (sure != 0) {
            return sure > 0;
        }
        double cx = ((double) x2 - x1) * b1, cy = ((double) y2 - y1) * a1;
        double a = (double) a2 * b1, b = (double) b2 * a1;
        double reach = (double) a1 * b1;
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
    static boolean segmentWithin(float x, float y, float a, float b, float x1, float y1, float x2, float y2, float r) {
        if (segment(x, y, a, b, x1, y1, x2, y2, true)) {
            return r > 0; // the segment meets the closed ellipse
        }
        return segmentDistance(a, b, (double) x1 - x, (double) y1 - y, (double) x2 - x, (double) y2 - y) < r;
    }

    /** The distance from a segment outside the ellipse (centre at the origin) to it. */
    static double segmentDistance(double a, double b, double px, double py, double qx, double qy) {
        double dx = qx - px, dy = qy - py;
        double[] near = new double[2];
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
    static double distance(double a, double b, double px, double py, double[] near) {
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

    // ---------------------------------------------------------------- turned ellipses

    /**
     * Is the ellipse decided as axis-aligned: angle 0, or equal radii (a circle, or a point),
     * where the angle changes nothing?
     */
    static boolean aligned(Ellipse e) {
        return e.angle() == 0 || e.rx() == e.ry();
    }

    /** Half the width of the ellipse's box: exact when aligned, else widened past the rounding. */
    static double halfWidth(Ellipse e) {
        if (aligned(e)) {
            return e.rx();
        }
        double c = Math.cos(e.angle()), s = Math.sin(e.angle());
        return widen(Math.hypot(e.rx() * c, e.ry() * s));
    }

    /** Half the height of the ellipse's box: exact when aligned, else widened past the rounding. */
    static double halfHeight(Ellipse e) {
        if (aligned(e)) {
            return e.ry();
        }
        double c = Math.cos(e.angle()), s = Math.sin(e.angle());
        return widen(Math.hypot(e.rx() * s, e.ry() * c));
    }

    /** A few double roundings more (cos, sin, products, hypot), so the box holds the ellipse. */
    private static double widen(double h) {
        return h * (1 + 0x1p-48);
    }

    /** Is the point strictly inside the turned ellipse (taken into its frame in double)? */
    static boolean turnedPoint(Ellipse e, double px, double py) {
        if (e.rx() == 0 || e.ry() == 0) {
            return false;
        }
        Frame f = new Frame(e);
        return side(f.u(px, py), f.v(px, py), 0, 0, e.rx(), e.ry()) < 0;
    }

    /**
     * A turned ellipse's own frame: centre at the origin, its rx along u and ry along v. A
     * point goes in by {@code u = dx cos + dy sin, v = -dx sin + dy cos} (the turn undone).
     */
    record Frame(double x, double y, double c, double s) {
        Frame(Ellipse e) {
            this(e.x(), e.y(), Math.cos(e.angle()), Math.sin(e.angle()));
        }

        double u(double px, double py) {
            return (px - x) * c + (py - y) * s;
        }

        double v(double px, double py) {
            return -(px - x) * s + (py - y) * c;
        }
    }

    /** The flat turned ellipse's segment (one radius 0, not aligned): ends rounded to float. */
    static Segment flatSegment(Ellipse e) {
        double c = Math.cos(e.angle()), s = Math.sin(e.angle());
        double hx = e.rx() * c - e.ry() * s, hy = e.rx() * s + e.ry() * c; // one term is 0
        return new Segment((float) (e.x() - hx), (float) (e.y() - hy), (float) (e.x() + hx), (float) (e.y() + hy));
    }

    /** Has the shape an inside (area)? */
    private static boolean hasArea(Shape s) {
        if (s instanceof Circle c) {
            return c.r() > 0;
        }
        if (s instanceof Rect r) {
            return r.w() > 0 && r.h() > 0;
        }
        if (s instanceof Ellipse e) {
            return e.rx() > 0 && e.ry() > 0;
        }
        if (s instanceof Capsule k) {
            return k.r() > 0;
        }
        return s instanceof Polygon;
    }

    /**
     * A turned ellipse (not {@link #aligned}) against any shape, or an aligned one against a
     * turned ellipse: the other shape taken into the turned one's frame in double, where the
     * axis-aligned maths applies.
     */
    static boolean turned(Ellipse e, Shape other) {
        if (aligned(e)) {
            return turned((Ellipse) other, e); // other is the turned one
        }
        if (e.rx() == 0 || e.ry() == 0) {
            return flat(flatSegment(e), other);
        }
        if (other instanceof Ellipse f && f.rx() > 0 && f.ry() > 0) {
            if (aligned(f) || before(f, e)) {
                return ellipses(f, e);
            }
            return ellipses(e, f);
        }
        if (other instanceof Ellipse f && !aligned(f) && (f.rx() > 0 || f.ry() > 0)) {
            return turned(e, flatSegment(f)); // a flat turned ellipse: its open segment
        }
        Frame fr = new Frame(e);
        double a = e.rx(), b = e.ry();
        if (other instanceof Circle c) {
            double u = fr.u(c.x(), c.y()), v = fr.v(c.x(), c.y());
            if (side(u, v, 0, 0, a, b) < 0) {
                return true;
            }
            return c.r() > 0 && (side(u, v, 0, 0, a, b) == 0 || distance(a, b, u, v, null) < c.r());
        }
        if (other instanceof Segment g) {
            return segmentIn(fr, a, b, g.x1(), g.y1(), g.x2(), g.y2(), false);
        }
        if (other instanceof Capsule k) {
            if (segmentIn(fr, a, b, k.x1(), k.y1(), k.x2(), k.y2(), k.r() > 0)) {
                return true;
            }
            return k.r() > 0 && segmentDistance(a, b, fr.u(k.x1(), k.y1()), fr.v(k.x1(), k.y1()),
                    fr.u(k.x2(), k.y2()), fr.v(k.x2(), k.y2())) < k.r();
        }
        if (other instanceof Ellipse f) {
            // An aligned flat ellipse is its flat box, as below; both radii 0 is a point.
            return turned(e, new Rect(f.x() - f.rx(), f.y() - f.ry(), 2 * f.rx(), 2 * f.ry()));
        }
        if (other instanceof Rect r) {
            double right = (double) r.x() + r.w(), bottom = (double) r.y() + r.h();
            if (r.w() == 0 || r.h() == 0) {
                return segmentIn(fr, a, b, r.x(), r.y(), right, bottom, false);
            }
            double[] xy = {r.x(), r.y(), right, r.y(), right, bottom, r.x(), bottom};
            return outlineIn(fr, a, b, xy) || Collide.rectPoint(r.x(), r.y(), r.w(), r.h(), e.x(), e.y());
        }
        float[] raw = ((Polygon) other).raw();
        double[] xy = new double[raw.length];
        for (int i = 0; i < raw.length; i++) {
            xy[i] = raw[i];
        }
        return outlineIn(fr, a, b, xy) || Polygons.contains(raw, e.x(), e.y());
    }

    /** Does the segment (world coordinates) reach into the turned real ellipse (or its closed form)? */
    private static boolean segmentIn(Frame f, double a, double b, double x1, double y1, double x2, double y2,
                                     boolean closed) {
        return Capsules.nearOrigin(f.u(x1, y1) * b, f.v(x1, y1) * a, f.u(x2, y2) * b, f.v(x2, y2) * a, a * b, closed);
    }

    /** Does any edge of the closed outline reach into the turned real ellipse? */
    private static boolean outlineIn(Frame f, double a, double b, double[] xy) {
        int n = xy.length / 2;
        for (int i = 0, h = n - 1; i < n; h = i++) {
            if (segmentIn(f, a, b, xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], false)) {
                return true;
            }
        }
        return false;
    }

    /**
     * A flat turned ellipse, the open segment s, against any shape: a shape with area is
     * reached as the closed segment reaches it (the same for an open shape); a shape without
     * area only by crossing it properly, like two flat rectangles in a plus sign.
     */
    private static boolean flat(Segment s, Shape other) {
        if (hasArea(other)) {
            return Overlaps.test(s, other);
        }
        Segment o;
        if (other instanceof Segment g) {
            o = g;
        } else if (other instanceof Rect r && (r.w() > 0 || r.h() > 0)) {
            o = new Segment(r.x(), r.y(), r.x() + r.w(), r.y() + r.h());
        } else if (other instanceof Ellipse f && (f.rx() > 0 || f.ry() > 0)) {
            o = aligned(f) ? new Segment(f.x() - f.rx(), f.y() - f.ry(), f.x() + f.rx(), f.y() + f.ry()) : flatSegment(f);
        } else {
            return false; // a point-like shape, or a capsule of radius 0: no inside, no crossing
        }
        return Lines.orient(s.x1(), s.y1(), s.x2(), s.y2(), o.x1(), o.y1())
                * Lines.orient(s.x1(), s.y1(), s.x2(), s.y2(), o.x2(), o.y2()) < 0
                && Lines.orient(o.x1(), o.y1(), o.x2(), o.y2(), s.x1(), s.y1())
                * Lines.orient(o.x1(), o.y1(), o.x2(), o.y2(), s.x2(), s.y2()) < 0;
    }

    /** A fixed order on ellipses, the angle included, so a pair is always worked from the same side. */
    private static boolean before(Ellipse p, Ellipse q) {
        if (p.x() != q.x() || p.y() != q.y() || p.rx() != q.rx() || p.ry() != q.ry()) {
            return before(p.x(), p.y(), p.rx(), p.ry(), q.x(), q.y(), q.rx(), q.ry());
        }
        return Float.compare(p.angle(), q.angle()) < 0;
    }

    /**
     * Two real ellipses, at least one turned: in p's frame, scaled by (ry, rx) so p is a
     * circle of radius rx ry, q is still an ellipse, whose axes are found from its shape
     * matrix M M^T (M = scale x turn x radii); then q's distance from the circle's centre is
     * compared with that radius, as for two aligned ellipses.
     */
    static boolean ellipses(Ellipse p, Ellipse q) {
        int sure = discs((double) q.x() - p.x(), (double) q.y() - p.y(), p.rx(), p.ry(), q.rx(), q.ry());
        if (sure != 0) {
            return sure > 0;
        }
        Frame f = new Frame(p);
        double a1 = p.rx(), b1 = p.ry();
        double cu = f.u(q.x(), q.y()) * b1, cv = f.v(q.x(), q.y()) * a1;
        double phi = (double) q.angle() - p.angle();
        double c = Math.cos(phi), s = Math.sin(phi);
        // M's columns: q's two half axes in the scaled frame.
        double m00 = b1 * c * q.rx(), m10 = a1 * s * q.rx();
        double m01 = -b1 * s * q.ry(), m11 = a1 * c * q.ry();
        double pp = m00 * m00 + m01 * m01, ss = m10 * m10 + m11 * m11, qq = m00 * m10 + m01 * m11;
        double det = m00 * m11 - m01 * m10;
        double big = (pp + ss) / 2 + Math.hypot((pp - ss) / 2, qq);
        double small = det * det / big; // the other eigenvalue, without the cancellation
        double psi = 0.5 * Math.atan2(2 * qq, pp - ss);
        double A = Math.sqrt(big), B = Math.sqrt(small);
        // The circle's centre (the origin) relative to q's centre, in q's own axes.
        double ox = -cu, oy = -cv;
        double cp = Math.cos(psi), sp = Math.sin(psi);
        double x = ox * cp + oy * sp, y = -ox * sp + oy * cp;
        if (side(x, y, 0, 0, A, B) <= 0) {
            return true;
        }
        return distance(A, B, x, y, null) < a1 * b1;
    }

    /** How far the (possibly turned) ellipse reaches along (nx, ny). */
    static double support(Ellipse e, double nx, double ny) {
        double base = e.x() * nx + e.y() * ny;
        if (e.angle() == 0) {
            return base + Math.hypot(e.rx() * nx, e.ry() * ny);
        }
        double c = Math.cos(e.angle()), s = Math.sin(e.angle());
        return base + Math.hypot(e.rx() * (nx * c + ny * s), e.ry() * (-nx * s + ny * c));
    }
}
