package hitbox.internal;

import hitbox.*;

/**
 * The maths of turned ellipses (an {@link Ellipse} with an angle), apart from the
 * axis-aligned maths in {@link Ellipses} that it reuses: the other shape is taken into the
 * turned ellipse's own frame in double, where the aligned tests apply. Decided to double
 * precision, so a pair within about 1e-12 of its size from touching may go either way (the
 * {@link Ellipse} doc says so); an ellipse whose radii are equal, or whose angle is 0, is
 * handed to the exact aligned code instead.
 */
public final class TurnedEllipses {
    private TurnedEllipses() {
    }

    /**
     * Is the ellipse decided as axis-aligned: angle 0, or equal radii (a circle, or a point),
     * where the angle changes nothing?
     */
    public static boolean aligned(Ellipse e) {
        return e.angle() == 0 || e.rx() == e.ry();
    }

    /** Half the width of the ellipse's box: exact when aligned, else widened past the rounding. */
    public static double halfWidth(Ellipse e) {
        if (aligned(e)) {
            return e.rx();
        }
        double c = StrictMath.cos(e.angle()), s = StrictMath.sin(e.angle());
        return widen(Math.hypot(e.rx() * c, e.ry() * s));
    }

    /** Half the height of the ellipse's box: exact when aligned, else widened past the rounding. */
    public static double halfHeight(Ellipse e) {
        if (aligned(e)) {
            return e.ry();
        }
        double c = StrictMath.cos(e.angle()), s = StrictMath.sin(e.angle());
        return widen(Math.hypot(e.rx() * s, e.ry() * c));
    }

    /** A few double roundings more (cos, sin, products, hypot), so the box holds the ellipse. */
    private static double widen(double h) {
        return h * (1 + Tolerance.TURNED_BOX_WIDEN);
    }

    /** Is the point strictly inside the turned ellipse (taken into its frame in double)? */
    public static boolean turnedPoint(Ellipse e, double px, double py) {
        if (e.rx() == 0 || e.ry() == 0) {
            return false;
        }
        Frame f = new Frame(e);
        return Ellipses.side(f.u(px, py), f.v(px, py), 0, 0, e.rx(), e.ry()) < 0;
    }

    /**
     * A turned ellipse's own frame: centre at the origin, its rx along u and ry along v. A
     * point goes in by {@code u = dx cos + dy sin, v = -dx sin + dy cos} (the turn undone).
     */
    public record Frame(double x, double y, double c, double s) {
        public Frame(Ellipse e) {
            this(e.x(), e.y(), StrictMath.cos(e.angle()), StrictMath.sin(e.angle()));
        }

        public double u(double px, double py) {
            return TurnedEllipses.u(x, y, c, s, px, py);
        }

        public double v(double px, double py) {
            return TurnedEllipses.v(x, y, c, s, px, py);
        }
    }

    /** The flat turned ellipse's segment (one radius 0, not aligned): ends rounded to float. */
    public static Segment flatSegment(Ellipse e) {
        double[] xy = flatEnds(e, new double[4]);
        return new Segment((float) xy[0], (float) xy[1], (float) xy[2], (float) xy[3]);
    }

    /**
     * {@link #flatSegment}'s ends, the floats it holds, into {@code out} (x1, y1, x2, y2),
     * for a caller that makes no segment.
     */
    public static double[] flatEnds(Ellipse e, double[] out) {
        double c = StrictMath.cos(e.angle()), s = StrictMath.sin(e.angle());
        double hx = e.rx() * c - e.ry() * s, hy = e.rx() * s + e.ry() * c; // one term is 0
        out[0] = (float) (e.x() - hx);
        out[1] = (float) (e.y() - hy);
        out[2] = (float) (e.x() + hx);
        out[3] = (float) (e.y() + hy);
        return out;
    }

    /**
     * A turned ellipse (not {@link #aligned}) against any shape, or an aligned one against a
     * turned ellipse: the other shape taken into the turned one's frame in double, where the
     * axis-aligned maths applies.
     */
    public static boolean turned(Ellipse e, Shape other) {
        if (aligned(e)) {
            return turned((Ellipse) other, e); // other is the turned one
        }
        if (e.rx() == 0 || e.ry() == 0) {
            return flat(flatSegment(e), other);
        }
        float ex = e.x(), ey = e.y(), a = e.rx(), b = e.ry(), angle = e.angle();
        return switch (ShapeKind.of(other)) {
            case ELLIPSE -> {
                Ellipse f = (Ellipse) other;
                if (f.rx() > 0 && f.ry() > 0) {
                    yield realPair(ex, ey, a, b, angle, f.x(), f.y(), f.rx(), f.ry(), f.angle());
                }
                if (!aligned(f) && (f.rx() > 0 || f.ry() > 0)) {
                    yield turned(e, flatSegment(f)); // a flat turned ellipse: its open segment
                }
                // An aligned flat ellipse is its flat box, as a rectangle below; both radii 0 is a point.
                yield turned(e, new Rect(f.x() - f.rx(), f.y() - f.ry(), 2 * f.rx(), 2 * f.ry()));
            }
            case CAPSULE -> {
                Capsule k = (Capsule) other;
                yield capsule(ex, ey, a, b, angle, k.x1(), k.y1(), k.x2(), k.y2(), k.r());
            }
            case CIRCLE -> {
                Circle c = (Circle) other;
                yield circle(ex, ey, a, b, angle, c.x(), c.y(), c.r());
            }
            case RECT -> {
                Rect r = (Rect) other;
                yield rect(ex, ey, a, b, angle, r.x(), r.y(), r.w(), r.h());
            }
            case SEGMENT -> {
                Segment g = (Segment) other;
                yield segment(ex, ey, a, b, angle, g.x1(), g.y1(), g.x2(), g.y2());
            }
            case POLYGON -> polygon(ex, ey, a, b, angle, HiddenParts.raw((Polygon) other));
        };
    }

    // The turned real ellipse (x, y, rx, ry, angle: both radii above 0, not aligned) against
    // one kind each, on plain numbers: turned's cases, and a world's pair tests on a body's
    // placed numbers (Placement), which make no shape.

    /** The turned real ellipse against the capsule round (x1, y1)-(x2, y2) of radius r. */
    public static boolean capsule(float x, float y, float rx, float ry, float angle,
                                  float x1, float y1, float x2, float y2, float r) {
        double c = StrictMath.cos(angle), s = StrictMath.sin(angle);
        if (segmentIn(x, y, c, s, rx, ry, x1, y1, x2, y2, r > 0)) {
            return true;
        }
        return r > 0 && Ellipses.segmentDistance(rx, ry, u(x, y, c, s, x1, y1), v(x, y, c, s, x1, y1),
                u(x, y, c, s, x2, y2), v(x, y, c, s, x2, y2)) < r;
    }

    /** The turned real ellipse against the circle (cx, cy, r). */
    public static boolean circle(float x, float y, float rx, float ry, float angle, float cx, float cy, float r) {
        double c = StrictMath.cos(angle), s = StrictMath.sin(angle);
        double u = u(x, y, c, s, cx, cy), v = v(x, y, c, s, cx, cy);
        if (Ellipses.side(u, v, 0, 0, rx, ry) < 0) {
            return true;
        }
        return r > 0 && (Ellipses.side(u, v, 0, 0, rx, ry) == 0 || Ellipses.distance(rx, ry, u, v, null) < r);
    }

    /** The turned real ellipse against the rectangle (rectX, rectY, w, h). */
    public static boolean rect(float x, float y, float rx, float ry, float angle,
                               float rectX, float rectY, float w, float h) {
        double c = StrictMath.cos(angle), s = StrictMath.sin(angle);
        double right = (double) rectX + w, bottom = (double) rectY + h;
        if (w == 0 || h == 0) {
            return segmentIn(x, y, c, s, rx, ry, rectX, rectY, right, bottom, false);
        }
        // Its outline's edges in outlineIn's order (from the last corner round), no array made.
        double left = rectX, top = rectY;
        return segmentIn(x, y, c, s, rx, ry, left, bottom, left, top, false)
                || segmentIn(x, y, c, s, rx, ry, left, top, right, top, false)
                || segmentIn(x, y, c, s, rx, ry, right, top, right, bottom, false)
                || segmentIn(x, y, c, s, rx, ry, right, bottom, left, bottom, false)
                || RawTests.rectPoint(rectX, rectY, w, h, x, y);
    }

    /** The turned real ellipse against the segment (x1, y1)-(x2, y2). */
    public static boolean segment(float x, float y, float rx, float ry, float angle, float x1, float y1, float x2, float y2) {
        return segmentIn(x, y, StrictMath.cos(angle), StrictMath.sin(angle), rx, ry, x1, y1, x2, y2, false);
    }

    /** The turned real ellipse against the polygon of the vertices xy. */
    public static boolean polygon(float x, float y, float rx, float ry, float angle, float[] xy) {
        return outlineIn(x, y, StrictMath.cos(angle), StrictMath.sin(angle), rx, ry, xy) || Polygons.contains(xy, x, y);
    }

    /**
     * A point taken into the frame of a turned ellipse centred on (x, y), the turn's cosine c
     * and sine s: {@link Frame}'s maths on plain numbers, for the tests that make no shape
     * (nor rely on the compiler to take a frame object apart).
     */
    private static double u(double x, double y, double c, double s, double px, double py) {
        return (px - x) * c + (py - y) * s;
    }

    /** {@link #u}'s v. */
    private static double v(double x, double y, double c, double s, double px, double py) {
        return -(px - x) * s + (py - y) * c;
    }

    /**
     * Does the segment (world coordinates) reach into the turned real ellipse (or its closed
     * form), centred on (x, y) and turned by (c, s)?
     */
    private static boolean segmentIn(double x, double y, double c, double s, double a, double b,
                                     double x1, double y1, double x2, double y2, boolean closed) {
        return Capsules.nearOrigin(u(x, y, c, s, x1, y1) * b, v(x, y, c, s, x1, y1) * a,
                u(x, y, c, s, x2, y2) * b, v(x, y, c, s, x2, y2) * a, a * b, closed);
    }

    /**
     * Does any edge of the closed outline reach into the turned real ellipse? The float
     * vertices widen to double exactly, so no double copy of them is needed (a turned body's
     * polygon is placed anew each frame, and this test was what asked it for one).
     */
    private static boolean outlineIn(double x, double y, double c, double s, double a, double b, float[] xy) {
        int n = xy.length / 2;
        for (int i = 0, h = n - 1; i < n; h = i++) {
            if (segmentIn(x, y, c, s, a, b, xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], false)) {
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
        if (ShapeKind.hasInside(other)) {
            return Overlaps.test(s, other);
        }
        Segment o = switch (ShapeKind.of(other)) {
            case SEGMENT -> (Segment) other;
            case RECT -> {
                Rect r = (Rect) other;
                yield r.w() > 0 || r.h() > 0 ? new Segment(r.x(), r.y(), r.x() + r.w(), r.y() + r.h()) : null;
            }
            case ELLIPSE -> {
                Ellipse f = (Ellipse) other;
                if (!(f.rx() > 0 || f.ry() > 0)) {
                    yield null;
                }
                yield aligned(f) ? new Segment(f.x() - f.rx(), f.y() - f.ry(), f.x() + f.rx(), f.y() + f.ry()) : flatSegment(f);
            }
            // a point-like shape, or a capsule of radius 0: no inside, no crossing (shapes
            // with area were answered above)
            case CIRCLE, CAPSULE, POLYGON -> null;
        };
        if (o == null) {
            return false;
        }
        return Lines.orient(s.x1(), s.y1(), s.x2(), s.y2(), o.x1(), o.y1())
                * Lines.orient(s.x1(), s.y1(), s.x2(), s.y2(), o.x2(), o.y2()) < 0
                && Lines.orient(o.x1(), o.y1(), o.x2(), o.y2(), s.x1(), s.y1())
                * Lines.orient(o.x1(), o.y1(), o.x2(), o.y2(), s.x2(), s.y2()) < 0;
    }

    /** A fixed order on ellipses, the angle included, so a pair is always worked from the same side. */
    private static boolean before(float px, float py, float prx, float pry, float pa,
                                  float qx, float qy, float qrx, float qry, float qa) {
        if (px != qx || py != qy || prx != qrx || pry != qry) {
            return Ellipses.before(px, py, prx, pry, qx, qy, qrx, qry);
        }
        return Float.compare(pa, qa) < 0;
    }

    /**
     * Two real ellipses (both radii above 0), at least one turned, on plain numbers: worked
     * from an aligned one's side, or the earlier one's in a fixed order, so the answer does not
     * depend on the order they come in ({@link #turned}'s pair of ellipses, and a world's).
     */
    public static boolean realPair(float px, float py, float prx, float pry, float pa,
                                   float qx, float qy, float qrx, float qry, float qa) {
        boolean pAligned = pa == 0 || prx == pry, qAligned = qa == 0 || qrx == qry;
        if (!pAligned && (qAligned || before(qx, qy, qrx, qry, qa, px, py, prx, pry, pa))) {
            return ellipses(qx, qy, qrx, qry, qa, px, py, prx, pry, pa);
        }
        return ellipses(px, py, prx, pry, pa, qx, qy, qrx, qry, qa);
    }

    /**
     * Two real ellipses, at least one turned: in p's frame, scaled by (ry, rx) so p is a
     * circle of radius rx ry, q is still an ellipse, whose axes are found from its shape
     * matrix M M^T (M = scale x turn x radii); then q's distance from the circle's centre is
     * compared with that radius, as for two aligned ellipses.
     */
    private static boolean ellipses(float px, float py, float prx, float pry, float pa,
                                    float qx, float qy, float qrx, float qry, float qa) {
        int sure = Ellipses.discs((double) qx - px, (double) qy - py, prx, pry, qrx, qry);
        if (sure != 0) {
            return sure > 0;
        }
        double fc = StrictMath.cos(pa), fs = StrictMath.sin(pa);
        double a1 = prx, b1 = pry;
        double cu = u(px, py, fc, fs, qx, qy) * b1, cv = v(px, py, fc, fs, qx, qy) * a1;
        double phi = (double) qa - pa;
        double c = StrictMath.cos(phi), s = StrictMath.sin(phi);
        // M's columns: q's two half axes in the scaled frame.
        double m00 = b1 * c * qrx, m10 = a1 * s * qrx;
        double m01 = -b1 * s * qry, m11 = a1 * c * qry;
        double pp = m00 * m00 + m01 * m01, ss = m10 * m10 + m11 * m11, qq = m00 * m10 + m01 * m11;
        double det = m00 * m11 - m01 * m10;
        double big = (pp + ss) / 2 + Math.hypot((pp - ss) / 2, qq);
        double small = det * det / big; // the other eigenvalue, without the cancellation
        double psi = 0.5 * Math.atan2(2 * qq, pp - ss);
        double A = Math.sqrt(big), B = Math.sqrt(small);
        // The circle's centre (the origin) relative to q's centre, in q's own axes.
        double ox = -cu, oy = -cv;
        double cp = StrictMath.cos(psi), sp = StrictMath.sin(psi);
        double x = ox * cp + oy * sp, y = -ox * sp + oy * cp;
        if (Ellipses.side(x, y, 0, 0, A, B) <= 0) {
            return true;
        }
        return Ellipses.distance(A, B, x, y, null) < a1 * b1;
    }

    /** How far the (possibly turned) ellipse reaches along (nx, ny). */
    public static double support(Ellipse e, double nx, double ny) {
        double base = e.x() * nx + e.y() * ny;
        if (e.angle() == 0) {
            return base + Math.hypot(e.rx() * nx, e.ry() * ny);
        }
        double c = StrictMath.cos(e.angle()), s = StrictMath.sin(e.angle());
        return base + Math.hypot(e.rx() * (nx * c + ny * s), e.ry() * (-nx * s + ny * c));
    }
}
