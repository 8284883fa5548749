package hitbox.internal;

import hitbox.*;
import java.util.ArrayList;
import java.util.List;

/**
 * The kernel behind {@link Contact#manifold}: the contact of {@link Contacts#between} with its
 * one or two contact points.
 *
 * <p>Each shape is read, through {@link ShapeKind}, as round (a circle, an ellipse, or a
 * shape of no extent: a capsule of one point, a rectangle of size 0) or as straight pieces:
 * convex polygons (a rectangle, a convex polygon, a concave polygon's convex pieces) and
 * rounded segments (a capsule: its segment and radius; a flat rectangle: its segment and
 * radius 0). A pair with a round shape has one point. Straight pieces are clipped as Box2D
 * and dyn4j clip: with the contact's one normal, the reference face is the face most nearly
 * along it, the incident edge the other piece's face most nearly against the reference face,
 * and that edge is clipped (Sutherland-Hodgman, one half-plane at a time) to the reference
 * piece and its face's side lines; the ends that lie behind the reference face are the
 * points. A rounded segment as reference is its rectangle (segment and radius on both
 * sides); as incident, its segment moved by its radius towards the reference face.
 *
 * <p>A point's depth is {@code exit(a, p, n) + exit(b, p, -n)}: how far b must move along n
 * for p, as a point of b, to leave a, plus how far a must move against n for p, as a point
 * of a, to leave b. For a point on b's outline inside a (the usual incident point) the
 * second term is 0, and the first is Box2D's separation from the reference face when the
 * face is across the normal.
 *
 * <p>At about 830 lines this class is longer than most: the clipping, the depths, the
 * fallbacks and the one-point rule all read the same pieces, and only make sense together.
 *
 * <p>Reference: E. Catto, Box2D's {@code b2ClipPolygons} and {@code b2ClipSegments}; W.
 * Bittle, dyn4j's {@code ClippingManifoldSolver}; C. Ericson, <i>Real-Time Collision
 * Detection</i> (2005), 8.3.4 (Sutherland-Hodgman clipping).
 */
public final class Manifolds {
    private Manifolds() {
    }

    /** Relative size (of the pair's scale) below which two points are one, and a depth none. */
    private static final double SAME = 1e-9;

    /** Below this cosine a side is nearly along a ray (about 0.06 degrees off). */
    private static final double ALONG = 1e-3;

    /**
     * The manifold of two shapes with area, normal from a to b, or null when they do not
     * overlap. Segments are refused as by {@link Contacts#between}.
     */
    public static Manifold between(Shape a, Shape b) {
        Contact c = Contacts.between(a, b);
        if (c == null) {
            return null;
        }
        // The points are worked out with the pair in one order, whichever came first, as the
        // pair tables do: so both orders give the same points, to the last bit, wherever the
        // contact is the same one flipped.
        if (later(a, b)) {
            return points(b, a, c.flipped()).flipped();
        }
        return points(a, b, c);
    }

    /** Does a come after b in the order the points are worked out in: by kind, then by place? */
    private static boolean later(Shape a, Shape b) {
        int ka = ShapeKind.of(a).ordinal(), kb = ShapeKind.of(b).ordinal();
        if (ka != kb) {
            return ka > kb;
        }
        double[] p = {a.minX(), a.minY(), a.maxX(), a.maxY()}, q = {b.minX(), b.minY(), b.maxX(), b.maxY()};
        for (int i = 0; i < 4; i++) {
            if (p[i] != q[i]) {
                return p[i] > q[i];
            }
        }
        return a.toString().compareTo(b.toString()) > 0;
    }

    /** The manifold of overlapping a and b with their contact c. */
    private static Manifold points(Shape a, Shape b, Contact c) {
        double nx = c.nx(), ny = c.ny();
        double scale = scale(a, b);
        List<Piece> pa = pieces(a), pb = pieces(b);
        if (pa == null || pb == null) {
            return onePoint(a, pa, b, pb, c, scale);
        }
        List<double[]> points = new ArrayList<>();
        for (Piece p : pa) {
            for (Piece q : pb) {
                if (boxesMeet(p, q, scale)) {
                    clip(p, q, nx, ny, pa, pb, scale, points);
                }
            }
        }
        if (points.isEmpty()) {
            // Crossing deeply: no incident edge lies in the reference piece. The overlap's
            // corners, piece by piece, and the deepest of them.
            for (Piece p : pa) {
                for (Piece q : pb) {
                    if (boxesMeet(p, q, scale)) {
                        overlapCorners(p, q, nx, ny, pa, pb, scale, points);
                    }
                }
            }
            if (points.isEmpty()) {
                return onePoint(a, pa, b, pb, c, scale);
            }
            keepDeepest(points, scale);
        }
        return reduce(points, c, scale);
    }

    // ---------------------------------------------------------------- the shapes as pieces

    /**
     * A convex straight piece: a polygon (vertices turning as +1, {@code (ey, -ex)} outward),
     * or, when {@code seg}, a segment (two ends) with a radius.
     */
    private static final class Piece {
        final double[] xy;
        final double r;
        final boolean seg;
        /** Half-planes {@code ux * x + uy * y <= c}, three numbers each. */
        final double[] planes;
        /** Faces: outward unit normal and the two ends, six numbers each. */
        final double[] faces;
        final double minX, minY, maxX, maxY;

        Piece(double[] xy, double r, boolean seg) {
            this.xy = xy;
            this.r = r;
            this.seg = seg;
            double x0 = Double.POSITIVE_INFINITY, y0 = x0, x1 = -x0, y1 = -x0;
            for (int i = 0; i < xy.length; i += 2) {
                x0 = Math.min(x0, xy[i]);
                x1 = Math.max(x1, xy[i]);
                y0 = Math.min(y0, xy[i + 1]);
                y1 = Math.max(y1, xy[i + 1]);
            }
            minX = x0 - r;
            minY = y0 - r;
            maxX = x1 + r;
            maxY = y1 + r;
            if (seg) {
                double ex = xy[2] - xy[0], ey = xy[3] - xy[1], len = Math.hypot(ex, ey);
                double tx = ex / len, ty = ey / len, px = ty, py = -tx;
                planes = new double[] {
                    px, py, px * xy[0] + py * xy[1] + r,
                    -px, -py, -px * xy[0] - py * xy[1] + r,
                    tx, ty, tx * xy[2] + ty * xy[3],
                    -tx, -ty, -tx * xy[0] - ty * xy[1]};
                faces = new double[] {
                    px, py, xy[0] + r * px, xy[1] + r * py, xy[2] + r * px, xy[3] + r * py,
                    -px, -py, xy[2] - r * px, xy[3] - r * py, xy[0] - r * px, xy[1] - r * py};
            } else {
                int n = xy.length / 2, m = 0;
                double[] pl = new double[3 * n], fa = new double[6 * n];
                for (int i = 0; i < n; i++) {
                    int j = (i + 1) % n;
                    double ex = xy[2 * j] - xy[2 * i], ey = xy[2 * j + 1] - xy[2 * i + 1], len = Math.hypot(ex, ey);
                    if (len == 0) {
                        continue;
                    }
                    double ux = ey / len, uy = -ex / len;
                    pl[3 * m] = ux;
                    pl[3 * m + 1] = uy;
                    pl[3 * m + 2] = ux * xy[2 * i] + uy * xy[2 * i + 1];
                    fa[6 * m] = ux;
                    fa[6 * m + 1] = uy;
                    fa[6 * m + 2] = xy[2 * i];
                    fa[6 * m + 3] = xy[2 * i + 1];
                    fa[6 * m + 4] = xy[2 * j];
                    fa[6 * m + 5] = xy[2 * j + 1];
                    m++;
                }
                planes = java.util.Arrays.copyOf(pl, 3 * m);
                faces = java.util.Arrays.copyOf(fa, 6 * m);
            }
        }
    }

    /** The shape's straight pieces, or null for a round shape (one point). */
    private static List<Piece> pieces(Shape s) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE, CIRCLE -> null;
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                yield k.x1() == k.x2() && k.y1() == k.y2() ? null
                        : List.of(new Piece(new double[] {k.x1(), k.y1(), k.x2(), k.y2()}, k.r(), true));
            }
            case RECT -> straight(List.of(Polygons.corners((Rect) s, new double[8])));
            case POLYGON -> {
                Polygon p = (Polygon) s;
                yield straight(p.isConvex() ? List.of(HiddenParts.corners(p)) : Clearance.Parts.of(p).pieces());
            }
            case SEGMENT -> throw new IllegalArgumentException("a manifold needs two shapes with area, but a Segment has none");
        };
    }

    /**
     * Convex vertex lists as pieces: repeated vertices dropped, turned to winding +1; two
     * distinct vertices make a segment of radius 0, one a point (round: null).
     */
    private static List<Piece> straight(List<double[]> polygons) {
        List<Piece> out = new ArrayList<>();
        for (double[] xy : polygons) {
            double[] v = distinct(xy);
            int n = v.length / 2;
            if (n == 1) {
                return null;
            }
            if (n == 2) {
                out.add(new Piece(v, 0, true));
                continue;
            }
            if (Polygons.doubleSignedArea(v) < 0) {
                double[] w = new double[v.length];
                for (int i = 0; i < n; i++) {
                    w[2 * i] = v[2 * (n - 1 - i)];
                    w[2 * i + 1] = v[2 * (n - 1 - i) + 1];
                }
                v = w;
            }
            out.add(new Piece(v, 0, false));
        }
        return out;
    }

    private static double[] distinct(double[] xy) {
        int n = xy.length / 2;
        double[] out = new double[xy.length];
        int m = 0;
        for (int i = 0; i < n; i++) {
            double x = xy[2 * i], y = xy[2 * i + 1];
            boolean seen = false;
            for (int k = 0; k < m && !seen; k++) {
                seen = out[2 * k] == x && out[2 * k + 1] == y;
            }
            if (!seen) {
                out[2 * m] = x;
                out[2 * m + 1] = y;
                m++;
            }
        }
        return java.util.Arrays.copyOf(out, 2 * m);
    }

    private static boolean boxesMeet(Piece p, Piece q, double scale) {
        double slack = SAME * scale;
        return p.minX <= q.maxX + slack && q.minX <= p.maxX + slack && p.minY <= q.maxY + slack && q.minY <= p.maxY + slack;
    }

    /** The pair's size: their largest coordinate or extent, at least 1. */
    public static double scale(Shape a, Shape b) {
        double s = 1;
        for (Shape t : new Shape[] {a, b}) {
            s = Math.max(s, Math.max(Math.max(Math.abs(t.minX()), Math.abs(t.maxX())), Math.max(Math.abs(t.minY()), Math.abs(t.maxY()))));
            s = Math.max(s, Math.max(t.maxX() - t.minX(), t.maxY() - t.minY()));
        }
        return s;
    }

    // ---------------------------------------------------------------- clipping

    /** The clipped points of piece p (of a) against piece q (of b), normal (nx, ny) from a to b, into {@code out}. */
    private static void clip(Piece p, Piece q, double nx, double ny, List<Piece> pa, List<Piece> pb, double scale,
                             List<double[]> out) {
        int fa = bestFace(p, nx, ny), fb = bestFace(q, -nx, -ny);
        if (fa < 0 || fb < 0) {
            return;
        }
        double apart = offBy(p.faces[fa], p.faces[fa + 1], -q.faces[fb], -q.faces[fb + 1], nx, ny);
        boolean referenceA;
        if (Math.abs(apart) > rounding(p, fa, q, fb, scale)) {
            referenceA = apart < 0;
        } else {
            // Equally along the normal: the reference is the shape the preferred one of n and
            // -n points away from, whichever shape came first (n and -n are mirror images in
            // every key, so the keys are compared exactly: no tie tolerance).
            referenceA = Contacts.preferred(nx, ny, -nx, -ny, 0);
        }
        Piece ref = referenceA ? p : q, inc = referenceA ? q : p;
        int f = referenceA ? fa : fb;
        double ux = ref.faces[f], uy = ref.faces[f + 1];
        double fx1 = ref.faces[f + 2], fy1 = ref.faces[f + 3], fx2 = ref.faces[f + 4], fy2 = ref.faces[f + 5];
        // The incident edge: the face most nearly against the reference face; a segment's
        // own segment, moved by its radius towards the reference.
        double[] e;
        if (inc.seg) {
            e = new double[] {inc.xy[0] - inc.r * ux, inc.xy[1] - inc.r * uy, inc.xy[2] - inc.r * ux, inc.xy[3] - inc.r * uy};
        } else {
            e = incidentEdge(inc, ux, uy, scale);
        }
        // Clipped to the reference piece (all its half-planes but the face's own) and the
        // face's side lines.
        for (int k = 0; k < ref.planes.length && e != null; k += 3) {
            // Face i lies on half-plane i (a segment's two sides are its first two planes).
            if (k / 3 != f / 6) {
                e = clipTo(e, ref.planes[k], ref.planes[k + 1], ref.planes[k + 2]);
            }
        }
        double tx = fx2 - fx1, ty = fy2 - fy1;
        if (e != null && (tx != 0 || ty != 0)) {
            e = clipTo(e, -tx, -ty, -tx * fx1 - ty * fy1);
        }
        if (e != null && (tx != 0 || ty != 0)) {
            e = clipTo(e, tx, ty, tx * fx2 + ty * fy2);
        }
        if (e == null) {
            return;
        }
        // The ends behind the reference face (Box2D's separation <= 0); one in front is dropped,
        // not moved onto the face, so that a corner gives one point.
        double faceC = ux * fx1 + uy * fy1;
        for (int k = 0; k < 4; k += 2) {
            if (ux * e[k] + uy * e[k + 1] - faceC > SAME * scale) {
                continue;
            }
            double depth = depth(e[k], e[k + 1], nx, ny, pa, pb, scale);
            if (depth > SAME * scale) {
                out.add(new double[] {e[k], e[k + 1], depth});
            }
        }
    }

    /**
     * The incident edge of a polygon piece against the reference face's normal (ux, uy): its
     * face most nearly against it. Two faces as far against it (their angles to it the same,
     * to the {@link #rounding} of float corners) that meet at a corner turned straight at the
     * reference face give that corner alone, so that a shape placed symmetrically gives
     * symmetric points; two in line (to the same rounding) give their union. Both by angles,
     * not cosines: near straight against the face the cosines differ by about the angles'
     * squares, and a cosine slack of 1e-6 took the two faces of a corner of 179.93 degrees
     * for one line, or for a corner turned straight at the face.
     */
    private static double[] incidentEdge(Piece inc, double ux, double uy, double scale) {
        int g = bestFace(inc, -ux, -uy);
        double[] f = inc.faces;
        for (int k = 0; k < f.length; k += 6) {
            double slack = rounding(inc, g, inc, k, scale);
            if (k == g || offBy(f[k], f[k + 1], f[g], f[g + 1], -ux, -uy) > slack) {
                continue;
            }
            if (f[k] * f[g] + f[k + 1] * f[g + 1] > 0 && Math.abs(f[g] * f[k + 1] - f[g + 1] * f[k]) <= slack) {
                // In line: from the nearer end to the farther, along the first face.
                double tx = f[g + 4] - f[g + 2], ty = f[g + 5] - f[g + 3];
                double[] ends = {f[g + 2], f[g + 3], f[g + 4], f[g + 5], f[k + 2], f[k + 3], f[k + 4], f[k + 5]};
                int lo = 0, hi = 0;
                for (int i = 2; i < 8; i += 2) {
                    double t = ends[i] * tx + ends[i + 1] * ty;
                    lo = t < ends[lo] * tx + ends[lo + 1] * ty ? i : lo;
                    hi = t > ends[hi] * tx + ends[hi + 1] * ty ? i : hi;
                }
                return new double[] {ends[lo], ends[lo + 1], ends[hi], ends[hi + 1]};
            }
            if (f[g + 4] == f[k + 2] && f[g + 5] == f[k + 3]) {
                return new double[] {f[g + 4], f[g + 5], f[g + 4], f[g + 5]};
            }
            if (f[k + 4] == f[g + 2] && f[k + 5] == f[g + 3]) {
                return new double[] {f[g + 2], f[g + 3], f[g + 2], f[g + 3]};
            }
        }
        return new double[] {f[g + 2], f[g + 3], f[g + 4], f[g + 5]};
    }

    /**
     * How much farther unit (ax, ay) is turned from unit (ux, uy) than unit (bx, by) is, both
     * within a right angle of it: sin(angle a - angle b), the angles taken unsigned. Near
     * (ux, uy) this is about the angles' difference, where the cosines' is about the squares'.
     */
    private static double offBy(double ax, double ay, double bx, double by, double ux, double uy) {
        double xa = Math.abs(ax * uy - ay * ux), xb = Math.abs(bx * uy - by * ux);
        return xa * (bx * ux + by * uy) - (ax * ux + ay * uy) * xb;
    }

    /**
     * The turn (as a sine) that the rounding of float corners at the pair's scale can give
     * face f of p against face g of q: their angles within it are the same angle.
     */
    private static double rounding(Piece p, int f, Piece q, int g, double scale) {
        return AS_DEEP * scale / Math.min(faceLength(p, f), faceLength(q, g));
    }

    private static double faceLength(Piece p, int f) {
        return Math.hypot(p.faces[f + 4] - p.faces[f + 2], p.faces[f + 5] - p.faces[f + 3]);
    }

    /** The face of the piece most nearly along (ux, uy), as an index into its faces; -1 if none. */
    private static int bestFace(Piece p, double ux, double uy) {
        int best = -1;
        double most = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < p.faces.length; k += 6) {
            double s = p.faces[k] * ux + p.faces[k + 1] * uy;
            if (s > most) {
                most = s;
                best = k;
            }
        }
        return best;
    }

    /** Segment e (x1, y1, x2, y2) clipped to {@code px * x + py * y <= c}; null when nothing is left. */
    private static double[] clipTo(double[] e, double px, double py, double c) {
        double d1 = px * e[0] + py * e[1] - c, d2 = px * e[2] + py * e[3] - c;
        if (d1 <= 0 && d2 <= 0) {
            return e;
        }
        if (d1 > 0 && d2 > 0) {
            return null;
        }
        double t = d1 / (d1 - d2);
        double x = e[0] + t * (e[2] - e[0]), y = e[1] + t * (e[3] - e[1]);
        return d1 > 0 ? new double[] {x, y, e[2], e[3]} : new double[] {e[0], e[1], x, y};
    }

    /**
     * The overlap of two pieces (q clipped to p's half-planes, a rounded segment as its
     * inscribed polygon), its corners with their depths into {@code out}.
     */
    private static void overlapCorners(Piece p, Piece q, double nx, double ny, List<Piece> pa, List<Piece> pb,
                                       double scale, List<double[]> out) {
        double[] poly = outline(q);
        double[] planes = p.seg && p.r > 0 ? straight(List.of(outline(p))).get(0).planes : p.planes;
        for (int k = 0; k < planes.length && poly.length > 0; k += 3) {
            poly = clipPolygon(poly, planes[k], planes[k + 1], planes[k + 2]);
        }
        for (int i = 0; i + 1 < poly.length; i += 2) {
            double depth = depth(poly[i], poly[i + 1], nx, ny, pa, pb, scale);
            if (depth > SAME * scale) {
                out.add(new double[] {poly[i], poly[i + 1], depth});
            }
        }
    }

    /** A piece's outline as a polygon: its vertices, or a rounded segment's inscribed polygon. */
    private static double[] outline(Piece q) {
        if (!q.seg || q.r == 0) {
            return q.xy;
        }
        // Two half circles, each from one side's corner to the other's, the corners exact.
        int half = INSCRIBED / 2;
        double[] xy = new double[4 * (half + 1)];
        double dx = q.planes[6], dy = q.planes[7], px = q.planes[0], py = q.planes[1];
        int k = 0;
        for (int end = 2; end >= 0; end -= 2) {
            double sign = end == 2 ? 1 : -1;
            for (int i = 0; i <= half; i++) {
                double t = -Math.PI / 2 + Math.PI * i / half;
                double c = i == 0 || i == half ? 0 : StrictMath.cos(t), sn = i == 0 ? -1 : i == half ? 1 : StrictMath.sin(t);
                xy[k++] = q.xy[end] + sign * q.r * (c * dx + sn * px);
                xy[k++] = q.xy[end + 1] + sign * q.r * (c * dy + sn * py);
            }
        }
        return xy;
    }

    /** Sutherland-Hodgman: the polygon clipped to {@code px * x + py * y <= c}. */
    private static double[] clipPolygon(double[] poly, double px, double py, double c) {
        int n = poly.length / 2;
        double[] out = new double[4 * n];
        int m = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double xi = poly[2 * i], yi = poly[2 * i + 1], xj = poly[2 * j], yj = poly[2 * j + 1];
            double di = px * xi + py * yi - c, dj = px * xj + py * yj - c;
            if (di <= 0) {
                out[m++] = xi;
                out[m++] = yi;
            }
            if (di <= 0 != dj <= 0) {
                double t = di / (di - dj);
                out[m++] = xi + t * (xj - xi);
                out[m++] = yi + t * (yj - yi);
            }
        }
        return java.util.Arrays.copyOf(out, m);
    }

    // ---------------------------------------------------------------- depths

    /**
     * A point's depth: how far b moves along n before p leaves a, plus how far a moves
     * against n before p leaves b.
     */
    private static double depth(double px, double py, double nx, double ny, List<Piece> pa, List<Piece> pb, double scale) {
        return exit(pa, px, py, nx, ny, scale) + exit(pb, px, py, -nx, -ny, scale);
    }

    /**
     * How far from p along (ux, uy) the union of the pieces ends (0 if p is not in it): the
     * ray may pass from a piece into the next across a cut.
     */
    private static double exit(List<Piece> pieces, double px, double py, double ux, double uy, double scale) {
        double t = 0;
        double tol = SAME * scale;
        for (int round = 0; round <= pieces.size(); round++) {
            double far = t;
            for (Piece p : pieces) {
                double e = exit(p, px + t * ux, py + t * uy, ux, uy, tol);
                if (e > 0) {
                    far = Math.max(far, t + e);
                }
            }
            if (!(far > t + tol)) {
                break;
            }
            t = far;
        }
        return t;
    }

    /** How far from p along unit (ux, uy) the piece's closure ends; 0 when p is not in it. */
    private static double exit(Piece p, double px, double py, double ux, double uy, double tol) {
        double best = 0;
        double[] range = slab(p.planes, px, py, ux, uy, tol);
        if (range != null && range[0] <= tol) {
            best = Math.max(best, range[1]);
        }
        if (p.seg && p.r > 0) {
            for (int k = 0; k < 4; k += 2) {
                // The end caps: the larger root of |p + t u - s| = r, if p is in the disc.
                double ox = px - p.xy[k], oy = py - p.xy[k + 1];
                double b = ox * ux + oy * uy, c = ox * ox + oy * oy - p.r * p.r;
                if (c <= 2 * tol * p.r) {
                    double disc = Math.max(0, b * b - c);
                    best = Math.max(best, -b + Math.sqrt(disc));
                }
            }
        }
        return best;
    }

    /**
     * The ray's parameter range inside the half-planes (Liang-Barsky): {lo, hi}, or null when
     * it misses them.
     */
    private static double[] slab(double[] planes, double px, double py, double ux, double uy, double tol) {
        double reach = tol / SAME;
        double lo = Double.NEGATIVE_INFINITY, hi = Double.POSITIVE_INFINITY;
        for (int k = 0; k < planes.length; k += 3) {
            double along = planes[k] * ux + planes[k + 1] * uy;
            double gap = planes[k + 2] - (planes[k] * px + planes[k + 1] * py);
            if (along > 0) {
                // A side the ray runs nearly along (a float polygon's upright edge, turned by
                // rounding) lets it go the way it would go along the side itself: the region
                // widened by a float's rounding there, so the side's rounding does not decide.
                hi = Math.min(hi, (along < ALONG ? gap + AS_DEEP * reach : gap) / along);
            } else if (along < 0) {
                // The same on the side the ray enters by: a point on such a side (an incident
                // edge's end clipped to a box's side line, the ray along the box's face normal)
                // would else be outside by its rounding divided by the tiny cosine.
                lo = Math.max(lo, (along > -ALONG ? gap + AS_DEEP * reach : gap) / along);
            } else if (gap < -tol) {
                return null;
            }
        }
        return lo <= hi + tol ? new double[] {lo, hi} : null;
    }

    // ---------------------------------------------------------------- choosing the points

    /**
     * How close (relative to the pair's scale) two depths are the same for the deepest
     * corners: a little above a float's rounding of the coordinates, so that a shape placed
     * symmetrically, whose float corners are symmetric only to rounding, keeps both.
     */
    private static final double AS_DEEP = 1e-6;

    /** Keeps the deepest of the overlap's corners (and those as deep, to the rounding of floats). */
    private static void keepDeepest(List<double[]> points, double scale) {
        double most = 0;
        for (double[] p : points) {
            most = Math.max(most, p[2]);
        }
        double cut = most - AS_DEEP * scale;
        points.removeIf(p -> p[2] < cut);
    }

    /**
     * One or two of the points: the two farthest apart along the surface (ties to the deeper,
     * then the smaller x, then y), in the order of x, then y.
     */
    private static Manifold reduce(List<double[]> points, Contact c, double scale) {
        double tx = -c.ny(), ty = c.nx();
        double[] lo = null, hi = null;
        for (double[] p : points) {
            if (lo == null || before(p, lo, tx, ty, scale)) {
                lo = p;
            }
            if (hi == null || before(p, hi, -tx, -ty, scale)) {
                hi = p;
            }
        }
        double apart = Math.hypot(hi[0] - lo[0], hi[1] - lo[1]);
        if (apart <= SAME * scale) {
            double[] deepest = lo[2] >= hi[2] ? lo : hi;
            return one(c, deepest[0], deepest[1], deepest[2]);
        }
        double[] first = lo, second = hi;
        float x1 = (float) lo[0], y1 = (float) lo[1], x2 = (float) hi[0], y2 = (float) hi[1];
        if (x2 < x1 || x2 == x1 && y2 < y1) {
            first = hi;
            second = lo;
        }
        if ((float) first[0] == (float) second[0] && (float) first[1] == (float) second[1]) {
            return one(c, first[0], first[1], Math.max(first[2], second[2]));
        }
        return new Manifold(c, 2, (float) first[0], (float) first[1], depthOf(first[2], c),
                (float) second[0], (float) second[1], depthOf(second[2], c));
    }

    /**
     * Is p before q along (tx, ty): less far along it, or as far (to the rounding of floats)
     * and deeper (to the same rounding), or then by y and x? (By y first, so that points placed symmetrically about a
     * vertical line are chosen symmetrically.)
     */
    private static boolean before(double[] p, double[] q, double tx, double ty, double scale) {
        double dp = p[0] * tx + p[1] * ty, dq = q[0] * tx + q[1] * ty;
        if (Math.abs(dp - dq) > AS_DEEP * scale) {
            return dp < dq;
        }
        if (Math.abs(p[2] - q[2]) > AS_DEEP * scale) {
            return p[2] > q[2];
        }
        return p[1] < q[1] || p[1] == q[1] && p[0] < q[0];
    }

    private static Manifold one(Contact c, double x, double y, double depth) {
        float d = depthOf(depth, c);
        return new Manifold(c, 1, (float) x, (float) y, d, (float) x, (float) y, d);
    }

    /** A depth as a float in (0, the contact's depth]. */
    private static float depthOf(double depth, Contact c) {
        return Math.min(c.depth(), Math.max(Float.MIN_VALUE, (float) depth));
    }

    // ---------------------------------------------------------------- one point

    /**
     * The one point of a pair with a round shape (or of straight pieces that left nothing to
     * clip): the round shape's deepest point into the other where that lies in the other,
     * else the other's deepest point into it; for two round shapes (or two straight ones),
     * the middle of the overlap when both deepest points lie in the other shape. Its depth is
     * the contact's.
     */
    private static Manifold onePoint(Shape a, List<Piece> piecesA, Shape b, List<Piece> piecesB, Contact c, double scale) {
        boolean roundA = piecesA == null, roundB = piecesB == null;
        double nx = c.nx(), ny = c.ny(), d = c.depth();
        double[] pa, pb;
        if (roundA && !roundB) {
            pa = support(a, nx, ny);
            pb = new double[] {pa[0] - d * nx, pa[1] - d * ny};
        } else if (roundB && !roundA) {
            pb = support(b, -nx, -ny);
            pa = new double[] {pb[0] + d * nx, pb[1] + d * ny};
        } else {
            pa = support(a, nx, ny);
            pb = support(b, -nx, -ny);
        }
        double tol = Manifold.TOLERANCE * scale;
        // In both: a witness worked out from the other's (pa = pb + d n) need not be on its own
        // shape's outline (a concave polygon's contact is not its hull's).
        boolean aInB = outside(b, pa[0], pa[1]) <= tol && outside(a, pa[0], pa[1]) <= tol;
        boolean bInA = outside(a, pb[0], pb[1]) <= tol && outside(b, pb[0], pb[1]) <= tol;
        double[] p;
        if (!aInB && !bInA) {
            // Neither deepest point lies in the other shape (a round shape in a concave
            // polygon's notch, say): the deepest corner of the overlap, a round shape taken
            // as its inscribed polygon.
            Manifold m = deepestCorner(piecesA != null ? piecesA : inscribed(a), piecesB != null ? piecesB : inscribed(b),
                    c, scale);
            if (m != null) {
                return m;
            }
        }
        if (roundA != roundB) {
            double[] round = roundA ? pa : pb, other = roundA ? pb : pa;
            boolean roundIn = roundA ? aInB : bInA, otherIn = roundA ? bInA : aInB;
            p = roundIn || !otherIn ? round : other;
        } else if (aInB == bInA) {
            p = new double[] {(pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2};
        } else {
            p = aInB ? pa : pb;
        }
        return one(c, p[0], p[1], d);
    }

    /** The deepest corners of the overlap of the two shapes' pieces, one or two; null if none. */
    private static Manifold deepestCorner(List<Piece> pa, List<Piece> pb, Contact c, double scale) {
        if (pa == null || pb == null) {
            return null;
        }
        List<double[]> points = new ArrayList<>();
        for (Piece p : pa) {
            for (Piece q : pb) {
                if (boxesMeet(p, q, scale)) {
                    overlapCorners(p, q, c.nx(), c.ny(), pa, pb, scale, points);
                }
            }
        }
        if (points.isEmpty()) {
            return null;
        }
        keepDeepest(points, scale);
        return reduce(points, c, scale);
    }

    /** The number of corners of a round shape's inscribed polygon. */
    private static final int INSCRIBED = 64;

    /** A round shape as its inscribed polygon, one piece; null for a shape of no extent. */
    private static List<Piece> inscribed(Shape s) {
        double[] xy = new double[2 * INSCRIBED];
        for (int i = 0; i < INSCRIBED; i++) {
            double t = 2 * Math.PI * i / INSCRIBED;
            double[] p = support(s, StrictMath.cos(t), StrictMath.sin(t));
            xy[2 * i] = p[0];
            xy[2 * i + 1] = p[1];
        }
        return straight(List.of(xy));
    }

    /** The shape's point farthest along unit (ux, uy); the middle of a flat side that is farthest. */
    public static double[] support(Shape s, double ux, double uy) {
        return switch (ShapeKind.of(s)) {
            case CIRCLE -> {
                Circle o = (Circle) s;
                yield new double[] {o.x() + o.r() * ux, o.y() + o.r() * uy};
            }
            case ELLIPSE -> {
                Ellipse e = (Ellipse) s;
                double cos = e.angle() == 0 ? 1 : StrictMath.cos(e.angle()), sin = e.angle() == 0 ? 0 : StrictMath.sin(e.angle());
                // In the ellipse's own axes: the point (a^2 u, b^2 v) / |(a u, b v)|.
                double u = ux * cos + uy * sin, v = -ux * sin + uy * cos;
                double au = (double) e.rx() * u, bv = (double) e.ry() * v, len = Math.hypot(au, bv);
                double lx = len == 0 ? 0 : e.rx() * au / len, ly = len == 0 ? 0 : e.ry() * bv / len;
                yield new double[] {e.x() + lx * cos - ly * sin, e.y() + lx * sin + ly * cos};
            }
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                double[] end = farthest(new double[] {k.x1(), k.y1(), k.x2(), k.y2()}, ux, uy);
                yield new double[] {end[0] + k.r() * ux, end[1] + k.r() * uy};
            }
            case RECT, POLYGON -> farthest(Polygons.corners(s), ux, uy);
            case SEGMENT -> {
                Segment g = (Segment) s;
                yield farthest(new double[] {g.x1(), g.y1(), g.x2(), g.y2()}, ux, uy);
            }
        };
    }

    /** The vertex farthest along (ux, uy); the middle of those as far, to rounding. */
    private static double[] farthest(double[] xy, double ux, double uy) {
        double most = Double.NEGATIVE_INFINITY, size = 0;
        for (int i = 0; i < xy.length; i += 2) {
            most = Math.max(most, xy[i] * ux + xy[i + 1] * uy);
            size = Math.max(size, Math.abs(xy[i]) + Math.abs(xy[i + 1]));
        }
        double sx = 0, sy = 0, minT = Double.POSITIVE_INFINITY, maxT = Double.NEGATIVE_INFINITY;
        double[] lo = null, hi = null;
        for (int i = 0; i < xy.length; i += 2) {
            if (xy[i] * ux + xy[i + 1] * uy >= most - SAME * Math.max(1, size)) {
                double t = -xy[i] * uy + xy[i + 1] * ux;
                if (t < minT) {
                    minT = t;
                    lo = new double[] {xy[i], xy[i + 1]};
                }
                if (t > maxT) {
                    maxT = t;
                    hi = new double[] {xy[i], xy[i + 1]};
                }
            }
        }
        return new double[] {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2};
    }

    /** How far the point lies outside the shape (0 or less: in its closure), roughly a distance. */
    public static double outside(Shape s, double px, double py) {
        return switch (ShapeKind.of(s)) {
            case CIRCLE -> {
                Circle o = (Circle) s;
                yield Math.hypot(px - o.x(), py - o.y()) - o.r();
            }
            case ELLIPSE -> {
                Ellipse e = (Ellipse) s;
                double cos = e.angle() == 0 ? 1 : StrictMath.cos(e.angle()), sin = e.angle() == 0 ? 0 : StrictMath.sin(e.angle());
                double dx = px - e.x(), dy = py - e.y();
                double lx = dx * cos + dy * sin, ly = -dx * sin + dy * cos;
                double a = e.rx(), b = e.ry();
                if (Math.min(a, b) == 0) {
                    yield Math.max(Math.abs(lx) - a, Math.abs(ly) - b);
                }
                // The implicit value turned into a distance: exact on the outline, a lower
                // bound near it (the gradient is at least 1 / max(a, b) in that scale).
                yield (Math.hypot(lx / a, ly / b) - 1) * Math.min(a, b);
            }
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                yield segmentDistance(px, py, k.x1(), k.y1(), k.x2(), k.y2()) - k.r();
            }
            case RECT -> {
                Rect r = (Rect) s;
                yield Math.max(Math.max(r.x() - px, px - ((double) r.x() + r.w())),
                        Math.max(r.y() - py, py - ((double) r.y() + r.h())));
            }
            case POLYGON -> {
                double best = Double.POSITIVE_INFINITY;
                for (Piece p : pieces(s)) {
                    double worst = Double.NEGATIVE_INFINITY;
                    for (int k = 0; k < p.planes.length; k += 3) {
                        worst = Math.max(worst, p.planes[k] * px + p.planes[k + 1] * py - p.planes[k + 2]);
                    }
                    best = Math.min(best, worst);
                }
                yield best;
            }
            case SEGMENT -> {
                Segment g = (Segment) s;
                yield segmentDistance(px, py, g.x1(), g.y1(), g.x2(), g.y2());
            }
        };
    }

    private static double segmentDistance(double px, double py, double x1, double y1, double x2, double y2) {
        double ex = x2 - x1, ey = y2 - y1, len2 = ex * ex + ey * ey;
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((px - x1) * ex + (py - y1) * ey) / len2));
        return Math.hypot(px - (x1 + t * ex), py - (y1 + t * ey));
    }
}
