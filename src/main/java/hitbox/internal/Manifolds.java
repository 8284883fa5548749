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
 * <p>A call makes nothing but its answer (the {@link Manifold}; the {@link Contact} is
 * {@link Contacts#between}'s): the pieces, the clipped edges and the candidate points live in
 * a thread's {@link Scratch}, fetched once per call and handed down, reset at each call.
 * (A concave polygon's convex pieces are still worked out per call, by {@link Clearance.Parts}.)
 *
 * <p>At about 1,000 lines this class is longer than most: the clipping, the depths, the
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
        Scratch sc = SCRATCH.get();
        sc.reset();
        // The points are worked out with the pair in one order, whichever came first, as the
        // pair tables do: so both orders give the same points, to the last bit, wherever the
        // contact is the same one flipped. The other order works with the flipped contact's
        // normal (as Contact.flipped makes it, -0 made 0) and hands back the points as found.
        if (later(a, b)) {
            points(b, a, -c.nx() + 0.0f, -c.ny() + 0.0f, c.depth(), sc);
        } else {
            points(a, b, c.nx(), c.ny(), c.depth(), sc);
        }
        return new Manifold(c, sc.count, sc.x1, sc.y1, sc.depth1, sc.x2, sc.y2, sc.depth2);
    }

    /** Does a come after b in the order the points are worked out in: by kind, then by place? */
    private static boolean later(Shape a, Shape b) {
        int ka = ShapeKind.of(a).ordinal(), kb = ShapeKind.of(b).ordinal();
        if (ka != kb) {
            return ka > kb;
        }
        if (Extents.minX(a) != Extents.minX(b)) {
            return Extents.minX(a) > Extents.minX(b);
        }
        if (Extents.minY(a) != Extents.minY(b)) {
            return Extents.minY(a) > Extents.minY(b);
        }
        if (Extents.maxX(a) != Extents.maxX(b)) {
            return Extents.maxX(a) > Extents.maxX(b);
        }
        if (Extents.maxY(a) != Extents.maxY(b)) {
            return Extents.maxY(a) > Extents.maxY(b);
        }
        // Equal shapes come in either order alike (their texts compare equal); only others
        // with the same box are told apart by their texts.
        return !a.equals(b) && a.toString().compareTo(b.toString()) > 0;
    }

    /**
     * The points of overlapping a and b, whose contact has normal (nx, ny) from a to b and the
     * given depth, into the scratch's answer.
     */
    private static void points(Shape a, Shape b, float nx, float ny, float depth, Scratch sc) {
        sc.nx = nx;
        sc.ny = ny;
        sc.depth = depth;
        double scale = scale(a, b);
        List<Piece> pa = pieces(a, sc, sc.piecesA), pb = pieces(b, sc, sc.piecesB);
        if (pa == null || pb == null) {
            onePoint(a, pa, b, pb, scale, sc);
            return;
        }
        Points points = sc.points.clear();
        for (int i = 0; i < pa.size(); i++) {
            for (int j = 0; j < pb.size(); j++) {
                Piece p = pa.get(i), q = pb.get(j);
                if (boxesMeet(p, q, scale)) {
                    clip(p, q, nx, ny, pa, pb, scale, sc);
                }
            }
        }
        if (points.n == 0) {
            // Crossing deeply: no incident edge lies in the reference piece. The overlap's
            // corners, piece by piece, and the deepest of them.
            for (int i = 0; i < pa.size(); i++) {
                for (int j = 0; j < pb.size(); j++) {
                    Piece p = pa.get(i), q = pb.get(j);
                    if (boxesMeet(p, q, scale)) {
                        overlapCorners(p, q, nx, ny, pa, pb, scale, sc);
                    }
                }
            }
            if (points.n == 0) {
                onePoint(a, pa, b, pb, scale, sc);
                return;
            }
            keepDeepest(points, scale);
        }
        reduce(points, scale, sc);
    }

    // ---------------------------------------------------------------- a thread's scratch

    /** The candidate points, x, y and depth each, in the order found. */
    private static final class Points {
        double[] xyd = new double[48];
        /** How many points. */
        int n;

        Points clear() {
            n = 0;
            return this;
        }

        void add(double x, double y, double depth) {
            if (3 * n + 3 > xyd.length) {
                xyd = java.util.Arrays.copyOf(xyd, 2 * xyd.length);
            }
            xyd[3 * n] = x;
            xyd[3 * n + 1] = y;
            xyd[3 * n + 2] = depth;
            n++;
        }
    }

    /**
     * A thread's working objects: the pieces (taken from a pool that a call starts again
     * from), the lists they are handed in, the points, the edge being clipped, and the answer
     * being made. Every array is grown to the largest seen and kept.
     */
    private static final class Scratch {
        Piece[] pool = new Piece[8];
        /** How many of the pool's pieces this call has taken. */
        int used;
        final ArrayList<Piece> piecesA = new ArrayList<>(), piecesB = new ArrayList<>();
        final ArrayList<Piece> inscribedA = new ArrayList<>(), inscribedB = new ArrayList<>(), polygon = new ArrayList<>();
        final Points points = new Points();
        /** The incident edge as it is clipped, and the ends of two faces in line. */
        final double[] edge = new double[4], ends = new double[8];
        /** A rectangle's corners; a shape's outline as a polygon; the vertices without repeats. */
        final double[] corners = new double[8];
        double[] outlineP = new double[4 * (INSCRIBED / 2 + 1)], outlineQ = new double[4 * (INSCRIBED / 2 + 1)];
        double[] inscribed = new double[2 * INSCRIBED], distinct = new double[16];
        /** The polygon being clipped, in two buffers taken in turn. */
        double[] clipA = new double[64], clipB = new double[64];
        /** Deepest points of the one-point rule, and a support point. */
        final double[] deepA = new double[2], deepB = new double[2], support = new double[2];
        /** The contact's normal and depth the points are found with. */
        float nx, ny, depth;
        /** The answer: one or two points. */
        int count;
        float x1, y1, depth1, x2, y2, depth2;

        void reset() {
            used = 0;
        }

        /** A piece from the pool, for this call. */
        Piece piece() {
            if (used == pool.length) {
                pool = java.util.Arrays.copyOf(pool, 2 * pool.length);
            }
            if (pool[used] == null) {
                pool[used] = new Piece();
            }
            return pool[used++];
        }
    }

    private static final ThreadLocal<Scratch> SCRATCH = ThreadLocal.withInitial(Scratch::new);

    /** An array of at least n, a's own if it is large enough. */
    private static double[] atLeast(double[] a, int n) {
        return a.length >= n ? a : new double[Math.max(n, 2 * a.length)];
    }

    // ---------------------------------------------------------------- the shapes as pieces

    /**
     * A convex straight piece: a polygon (vertices turning as +1, {@code (ey, -ex)} outward),
     * or, when {@code seg}, a segment (two ends) with a radius.
     */
    private static final class Piece {
        /** The vertices, {@code n} numbers of them (the array may be longer). */
        double[] xy = new double[16];
        int n;
        double r;
        boolean seg;
        /** Half-planes {@code ux * x + uy * y <= c}, three numbers each, {@code np} numbers. */
        double[] planes = new double[24];
        int np;
        /** Faces: outward unit normal and the two ends, six numbers each, {@code nf} numbers. */
        double[] faces = new double[48];
        int nf;
        /**
         * Each face's length, by face ({@code lengths[k / 6]} for the face at k), worked out
         * once here: the rounding slack of {@link #rounding} reads them for every face pair.
         */
        double[] lengths = new double[8];
        double minX, minY, maxX, maxY;

        /**
         * Sets this piece to the first {@code n} numbers of {@code from} (read from the last
         * vertex back if {@code reversed}), with radius r; a segment if {@code seg}.
         */
        Piece set(double[] from, int count, boolean reversed, double r, boolean seg) {
            xy = atLeast(xy, count);
            int verts = count / 2;
            for (int i = 0; i < verts; i++) {
                int k = reversed ? verts - 1 - i : i;
                xy[2 * i] = from[2 * k];
                xy[2 * i + 1] = from[2 * k + 1];
            }
            this.n = count;
            this.r = r;
            this.seg = seg;
            double x0 = Double.POSITIVE_INFINITY, y0 = x0, x1 = -x0, y1 = -x0;
            for (int i = 0; i < count; i += 2) {
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
                put(planes, 0, px, py, px * xy[0] + py * xy[1] + r);
                put(planes, 3, -px, -py, -px * xy[0] - py * xy[1] + r);
                put(planes, 6, tx, ty, tx * xy[2] + ty * xy[3]);
                put(planes, 9, -tx, -ty, -tx * xy[0] - ty * xy[1]);
                np = 12;
                put(faces, 0, px, py, xy[0] + r * px);
                put(faces, 3, xy[1] + r * py, xy[2] + r * px, xy[3] + r * py);
                put(faces, 6, -px, -py, xy[2] - r * px);
                put(faces, 9, xy[3] - r * py, xy[0] - r * px, xy[1] - r * py);
                nf = 12;
                lengths[0] = Math.hypot(faces[4] - faces[2], faces[5] - faces[3]);
                lengths[1] = Math.hypot(faces[10] - faces[8], faces[11] - faces[9]);
            } else {
                int n = verts, m = 0;
                planes = atLeast(planes, 3 * n);
                faces = atLeast(faces, 6 * n);
                lengths = atLeast(lengths, n);
                double[] pl = planes, fa = faces;
                for (int i = 0; i < n; i++) {
                    int j = (i + 1) % n;
                    // Not Math.hypot, which costs several times as much: a difference of two of
                    // a shape's coordinates squares without overflow or underflow at any size a
                    // float holds, so the plain root is as accurate (within an ulp).
                    double ex = xy[2 * j] - xy[2 * i], ey = xy[2 * j + 1] - xy[2 * i + 1], len = Math.sqrt(ex * ex + ey * ey);
                    if (len == 0) {
                        continue;
                    }
                    double inverse = 1 / len, ux = ey * inverse, uy = -ex * inverse;
                    pl[3 * m] = ux;
                    pl[3 * m + 1] = uy;
                    pl[3 * m + 2] = ux * xy[2 * i] + uy * xy[2 * i + 1];
                    fa[6 * m] = ux;
                    fa[6 * m + 1] = uy;
                    fa[6 * m + 2] = xy[2 * i];
                    fa[6 * m + 3] = xy[2 * i + 1];
                    fa[6 * m + 4] = xy[2 * j];
                    fa[6 * m + 5] = xy[2 * j + 1];
                    // The same differences of the face's ends as faceLength would take.
                    lengths[m] = len;
                    m++;
                }
                np = 3 * m;
                nf = 6 * m;
            }
            return this;
        }

        private static void put(double[] a, int i, double x, double y, double z) {
            a[i] = x;
            a[i + 1] = y;
            a[i + 2] = z;
        }
    }

    /** The shape's straight pieces into {@code out} (cleared first), or null for a round shape (one point). */
    private static List<Piece> pieces(Shape s, Scratch sc, List<Piece> out) {
        out.clear();
        return switch (ShapeKind.of(s)) {
            case ELLIPSE, CIRCLE -> null;
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                if (k.x1() == k.x2() && k.y1() == k.y2()) {
                    yield null;
                }
                double[] ends = sc.edge;
                ends[0] = k.x1();
                ends[1] = k.y1();
                ends[2] = k.x2();
                ends[3] = k.y2();
                out.add(sc.piece().set(ends, 4, false, k.r(), true));
                yield out;
            }
            case RECT -> straight(Polygons.corners((Rect) s, sc.corners), sc, out);
            case POLYGON -> {
                Polygon p = (Polygon) s;
                if (p.isConvex()) {
                    // A polygon's outline is simple, so its corners never repeat.
                    double[] corners = HiddenParts.corners(p);
                    yield straight(corners, corners.length, sc, out);
                }
                List<double[]> parts = Clearance.Parts.of(p).pieces();
                for (int i = 0; i < parts.size(); i++) {
                    if (straight(parts.get(i), sc, out) == null) {
                        yield null;
                    }
                }
                yield out;
            }
            case SEGMENT -> throw new IllegalArgumentException("a manifold needs two shapes with area, but a Segment has none");
        };
    }

    /**
     * A convex vertex list added to {@code out} as a piece: repeated vertices dropped, turned
     * to winding +1; two distinct vertices make a segment of radius 0, one a point (round:
     * null, and the shape is round).
     */
    private static List<Piece> straight(double[] xy, Scratch sc, List<Piece> out) {
        int len = distinct(xy, xy.length, sc);
        return straight(sc.distinct, len, sc, out);
    }

    /** {@link #straight(double[], Scratch, List)} of the first len numbers of v, vertices known not to repeat. */
    private static List<Piece> straight(double[] v, int len, Scratch sc, List<Piece> out) {
        int n = len / 2;
        if (n == 1) {
            return null;
        }
        if (n == 2) {
            out.add(sc.piece().set(v, len, false, 0, true));
            return out;
        }
        out.add(sc.piece().set(v, len, Polygons.doubleSignedArea(v, n) < 0, 0, false));
        return out;
    }

    /** The first len numbers of xy without repeated vertices, into the scratch's {@code distinct}; returns how many numbers. */
    private static int distinct(double[] xy, int len, Scratch sc) {
        int n = len / 2;
        double[] out = sc.distinct = atLeast(sc.distinct, len);
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
        return 2 * m;
    }

    private static boolean boxesMeet(Piece p, Piece q, double scale) {
        double slack = SAME * scale;
        return p.minX <= q.maxX + slack && q.minX <= p.maxX + slack && p.minY <= q.maxY + slack && q.minY <= p.maxY + slack;
    }

    /** The pair's size: their largest coordinate or extent, at least 1. */
    public static double scale(Shape a, Shape b) {
        return scale(scale(1, a), b);
    }

    /** The larger of s and the shape's largest coordinate or extent. */
    private static double scale(double s, Shape t) {
        double minX = Extents.minX(t), minY = Extents.minY(t), maxX = Extents.maxX(t), maxY = Extents.maxY(t);
        s = Math.max(s, Math.max(Math.max(Math.abs(minX), Math.abs(maxX)), Math.max(Math.abs(minY), Math.abs(maxY))));
        return Math.max(s, Math.max(maxX - minX, maxY - minY));
    }

    // ---------------------------------------------------------------- clipping

    /** The clipped points of piece p (of a) against piece q (of b), normal (nx, ny) from a to b, into {@code out}. */
    private static void clip(Piece p, Piece q, double nx, double ny, List<Piece> pa, List<Piece> pb, double scale,
                             Scratch sc) {
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
        double[] e = sc.edge;
        if (inc.seg) {
            e[0] = inc.xy[0] - inc.r * ux;
            e[1] = inc.xy[1] - inc.r * uy;
            e[2] = inc.xy[2] - inc.r * ux;
            e[3] = inc.xy[3] - inc.r * uy;
        } else {
            incidentEdge(inc, ux, uy, scale, e, sc.ends);
        }
        // Clipped to the reference piece (all its half-planes but the face's own) and the
        // face's side lines.
        boolean left = true;
        for (int k = 0; k < ref.np && left; k += 3) {
            // Face i lies on half-plane i (a segment's two sides are its first two planes).
            if (k / 3 != f / 6) {
                left = clipTo(e, ref.planes[k], ref.planes[k + 1], ref.planes[k + 2]);
            }
        }
        double tx = fx2 - fx1, ty = fy2 - fy1;
        if (left && (tx != 0 || ty != 0)) {
            left = clipTo(e, -tx, -ty, -tx * fx1 - ty * fy1);
        }
        if (left && (tx != 0 || ty != 0)) {
            left = clipTo(e, tx, ty, tx * fx2 + ty * fy2);
        }
        if (!left) {
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
                sc.points.add(e[k], e[k + 1], depth);
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
    private static void incidentEdge(Piece inc, double ux, double uy, double scale, double[] e, double[] ends) {
        int g = bestFace(inc, -ux, -uy);
        double[] f = inc.faces;
        for (int k = 0; k < inc.nf; k += 6) {
            if (k == g) {
                continue;
            }
            double slack = rounding(inc, g, inc, k, scale);
            if (offBy(f[k], f[k + 1], f[g], f[g + 1], -ux, -uy) > slack) {
                continue;
            }
            if (f[k] * f[g] + f[k + 1] * f[g + 1] > 0 && Math.abs(f[g] * f[k + 1] - f[g + 1] * f[k]) <= slack) {
                // In line: from the nearer end to the farther, along the first face.
                double tx = f[g + 4] - f[g + 2], ty = f[g + 5] - f[g + 3];
                System.arraycopy(f, g + 2, ends, 0, 4);
                System.arraycopy(f, k + 2, ends, 4, 4);
                int lo = 0, hi = 0;
                for (int i = 2; i < 8; i += 2) {
                    double t = ends[i] * tx + ends[i + 1] * ty;
                    lo = t < ends[lo] * tx + ends[lo + 1] * ty ? i : lo;
                    hi = t > ends[hi] * tx + ends[hi + 1] * ty ? i : hi;
                }
                edge(e, ends[lo], ends[lo + 1], ends[hi], ends[hi + 1]);
                return;
            }
            if (f[g + 4] == f[k + 2] && f[g + 5] == f[k + 3]) {
                edge(e, f[g + 4], f[g + 5], f[g + 4], f[g + 5]);
                return;
            }
            if (f[k + 4] == f[g + 2] && f[k + 5] == f[g + 3]) {
                edge(e, f[g + 2], f[g + 3], f[g + 2], f[g + 3]);
                return;
            }
        }
        edge(e, f[g + 2], f[g + 3], f[g + 4], f[g + 5]);
    }

    private static void edge(double[] e, double x1, double y1, double x2, double y2) {
        e[0] = x1;
        e[1] = y1;
        e[2] = x2;
        e[3] = y2;
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

    /** The length of the face at f: the distance between its two ends. */
    private static double faceLength(Piece p, int f) {
        return p.lengths[f / 6];
    }

    /** The face of the piece most nearly along (ux, uy), as an index into its faces; -1 if none. */
    private static int bestFace(Piece p, double ux, double uy) {
        int best = -1;
        double most = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < p.nf; k += 6) {
            double s = p.faces[k] * ux + p.faces[k + 1] * uy;
            if (s > most) {
                most = s;
                best = k;
            }
        }
        return best;
    }

    /** Segment e (x1, y1, x2, y2) clipped to {@code px * x + py * y <= c}, in place; false when nothing is left. */
    private static boolean clipTo(double[] e, double px, double py, double c) {
        double d1 = px * e[0] + py * e[1] - c, d2 = px * e[2] + py * e[3] - c;
        if (d1 <= 0 && d2 <= 0) {
            return true;
        }
        if (d1 > 0 && d2 > 0) {
            return false;
        }
        double t = d1 / (d1 - d2);
        double x = e[0] + t * (e[2] - e[0]), y = e[1] + t * (e[3] - e[1]);
        int end = d1 > 0 ? 0 : 2;
        e[end] = x;
        e[end + 1] = y;
        return true;
    }

    /**
     * The overlap of two pieces (q clipped to p's half-planes, a rounded segment as its
     * inscribed polygon), its corners with their depths into {@code out}.
     */
    private static void overlapCorners(Piece p, Piece q, double nx, double ny, List<Piece> pa, List<Piece> pb,
                                       double scale, Scratch sc) {
        double[] poly = outline(q, sc.outlineQ);
        int len = outlineLength(q);
        Piece clipper = p;
        if (p.seg && p.r > 0) {
            sc.polygon.clear();
            clipper = straight(outline(p, sc.outlineP), sc, sc.polygon).get(0);
        }
        double[] planes = clipper.planes;
        for (int k = 0; k < clipper.np && len > 0; k += 3) {
            // From the outline into one buffer, then from buffer to buffer in turn.
            double[] to = poly == sc.clipA ? (sc.clipB = atLeast(sc.clipB, 2 * len)) : (sc.clipA = atLeast(sc.clipA, 2 * len));
            len = clipPolygon(poly, len, planes[k], planes[k + 1], planes[k + 2], to);
            poly = to;
        }
        for (int i = 0; i + 1 < len; i += 2) {
            double depth = depth(poly[i], poly[i + 1], nx, ny, pa, pb, scale);
            if (depth > SAME * scale) {
                sc.points.add(poly[i], poly[i + 1], depth);
            }
        }
    }

    /** How many numbers {@link #outline} gives for the piece. */
    private static int outlineLength(Piece q) {
        return !q.seg || q.r == 0 ? q.n : 4 * (INSCRIBED / 2 + 1);
    }

    /**
     * A piece's outline as a polygon, {@link #outlineLength} numbers: its vertices, or a
     * rounded segment's inscribed polygon written into {@code xy}.
     */
    private static double[] outline(Piece q, double[] xy) {
        if (!q.seg || q.r == 0) {
            return q.xy;
        }
        // Two half circles, each from one side's corner to the other's, the corners exact.
        int half = INSCRIBED / 2;
        double dx = q.planes[6], dy = q.planes[7], px = q.planes[0], py = q.planes[1];
        int k = 0;
        for (int end = 2; end >= 0; end -= 2) {
            double sign = end == 2 ? 1 : -1;
            for (int i = 0; i <= half; i++) {
                double c = HALF_COS[i], sn = HALF_SIN[i];
                xy[k++] = q.xy[end] + sign * q.r * (c * dx + sn * px);
                xy[k++] = q.xy[end + 1] + sign * q.r * (c * dy + sn * py);
            }
        }
        return xy;
    }

    /**
     * Sutherland-Hodgman: the polygon of the first len numbers of poly clipped to
     * {@code px * x + py * y <= c}, into {@code out} (room for twice len); returns how many numbers.
     */
    private static int clipPolygon(double[] poly, int len, double px, double py, double c, double[] out) {
        int n = len / 2;
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
        return m;
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
        if (pieces.size() == 1 && !pieces.get(0).seg) {
            // One convex polygon: the loop below would stop after its second round, which
            // starts where the ray left the piece and finds no farther exit than rounding
            // (the region's widened sides move with the ray). Its answer, without that round.
            double e = exit(pieces.get(0), px, py, ux, uy, tol);
            return e > tol ? e : 0;
        }
        for (int round = 0; round <= pieces.size(); round++) {
            double far = t;
            for (int i = 0; i < pieces.size(); i++) {
                double e = exit(pieces.get(i), px + t * ux, py + t * uy, ux, uy, tol);
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
        double best = Math.max(0, slabExit(p.planes, p.np, px, py, ux, uy, tol));
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
     * Where the ray leaves the half-planes (the first np numbers of {@code planes}), by its
     * parameter range inside them (Liang-Barsky) from lo to hi: hi when the range starts at p
     * or before (lo within tol), else 0 (as when it misses them).
     */
    private static double slabExit(double[] planes, int np, double px, double py, double ux, double uy, double tol) {
        double reach = tol / SAME;
        double lo = Double.NEGATIVE_INFINITY, hi = Double.POSITIVE_INFINITY;
        for (int k = 0; k < np; k += 3) {
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
                return 0;
            }
        }
        return lo <= hi + tol && lo <= tol ? hi : 0;
    }

    // ---------------------------------------------------------------- choosing the points

    /**
     * How close (relative to the pair's scale) two depths are the same for the deepest
     * corners: a little above a float's rounding of the coordinates, so that a shape placed
     * symmetrically, whose float corners are symmetric only to rounding, keeps both.
     */
    private static final double AS_DEEP = 1e-6;

    /** Keeps the deepest of the overlap's corners (and those as deep, to the rounding of floats). */
    private static void keepDeepest(Points points, double scale) {
        double[] p = points.xyd;
        double most = 0;
        for (int i = 0; i < points.n; i++) {
            most = Math.max(most, p[3 * i + 2]);
        }
        double cut = most - AS_DEEP * scale;
        int kept = 0;
        for (int i = 0; i < points.n; i++) {
            if (!(p[3 * i + 2] < cut)) {
                System.arraycopy(p, 3 * i, p, 3 * kept++, 3);
            }
        }
        points.n = kept;
    }

    /**
     * One or two of the points: the two farthest apart along the surface (ties to the deeper,
     * then the smaller x, then y), in the order of x, then y.
     */
    private static void reduce(Points points, double scale, Scratch sc) {
        double tx = -(double) sc.ny, ty = sc.nx;
        double[] p = points.xyd;
        int lo = -1, hi = -1;
        for (int i = 0; i < points.n; i++) {
            if (lo < 0 || before(p, 3 * i, 3 * lo, tx, ty, scale)) {
                lo = i;
            }
            if (hi < 0 || before(p, 3 * i, 3 * hi, -tx, -ty, scale)) {
                hi = i;
            }
        }
        int l = 3 * lo, h = 3 * hi;
        double apart = Math.hypot(p[h] - p[l], p[h + 1] - p[l + 1]);
        if (apart <= SAME * scale) {
            int deepest = p[l + 2] >= p[h + 2] ? l : h;
            one(p[deepest], p[deepest + 1], p[deepest + 2], sc);
            return;
        }
        int first = l, second = h;
        float x1 = (float) p[l], y1 = (float) p[l + 1], x2 = (float) p[h], y2 = (float) p[h + 1];
        if (x2 < x1 || x2 == x1 && y2 < y1) {
            first = h;
            second = l;
        }
        if ((float) p[first] == (float) p[second] && (float) p[first + 1] == (float) p[second + 1]) {
            one(p[first], p[first + 1], Math.max(p[first + 2], p[second + 2]), sc);
            return;
        }
        sc.count = 2;
        sc.x1 = (float) p[first];
        sc.y1 = (float) p[first + 1];
        sc.depth1 = depthOf(p[first + 2], sc);
        sc.x2 = (float) p[second];
        sc.y2 = (float) p[second + 1];
        sc.depth2 = depthOf(p[second + 2], sc);
    }

    /**
     * Is the point at p[i] before the one at p[j] along (tx, ty): less far along it, or as
     * far (to the rounding of floats) and deeper (to the same rounding), or then by y and x?
     * (By y first, so that points placed symmetrically about a vertical line are chosen
     * symmetrically.)
     */
    private static boolean before(double[] p, int i, int j, double tx, double ty, double scale) {
        double dp = p[i] * tx + p[i + 1] * ty, dq = p[j] * tx + p[j + 1] * ty;
        if (Math.abs(dp - dq) > AS_DEEP * scale) {
            return dp < dq;
        }
        if (Math.abs(p[i + 2] - p[j + 2]) > AS_DEEP * scale) {
            return p[i + 2] > p[j + 2];
        }
        return p[i + 1] < p[j + 1] || p[i + 1] == p[j + 1] && p[i] < p[j];
    }

    /** The answer of one point. */
    private static void one(double x, double y, double depth, Scratch sc) {
        float d = depthOf(depth, sc);
        sc.count = 1;
        sc.x1 = sc.x2 = (float) x;
        sc.y1 = sc.y2 = (float) y;
        sc.depth1 = sc.depth2 = d;
    }

    /** A depth as a float in (0, the contact's depth]. */
    private static float depthOf(double depth, Scratch sc) {
        return Math.min(sc.depth, Math.max(Float.MIN_VALUE, (float) depth));
    }

    // ---------------------------------------------------------------- one point

    /**
     * The one point of a pair with a round shape (or of straight pieces that left nothing to
     * clip): the round shape's deepest point into the other where that lies in the other,
     * else the other's deepest point into it; for two round shapes (or two straight ones),
     * the middle of the overlap when both deepest points lie in the other shape. Its depth is
     * the contact's.
     */
    private static void onePoint(Shape a, List<Piece> piecesA, Shape b, List<Piece> piecesB, double scale, Scratch sc) {
        boolean roundA = piecesA == null, roundB = piecesB == null;
        double nx = sc.nx, ny = sc.ny, d = sc.depth;
        double[] pa = sc.deepA, pb = sc.deepB;
        if (roundA && !roundB) {
            support(a, nx, ny, pa, sc);
            pb[0] = pa[0] - d * nx;
            pb[1] = pa[1] - d * ny;
        } else if (roundB && !roundA) {
            support(b, -nx, -ny, pb, sc);
            pa[0] = pb[0] + d * nx;
            pa[1] = pb[1] + d * ny;
        } else {
            support(a, nx, ny, pa, sc);
            support(b, -nx, -ny, pb, sc);
        }
        double tol = Manifold.TOLERANCE * scale;
        // In both: a witness worked out from the other's (pa = pb + d n) need not be on its own
        // shape's outline (a concave polygon's contact is not its hull's).
        boolean aInB = outside(b, pa[0], pa[1], sc) <= tol && outside(a, pa[0], pa[1], sc) <= tol;
        boolean bInA = outside(a, pb[0], pb[1], sc) <= tol && outside(b, pb[0], pb[1], sc) <= tol;
        if (!aInB && !bInA) {
            // Neither deepest point lies in the other shape (a round shape in a concave
            // polygon's notch, say): the deepest corner of the overlap, a round shape taken
            // as its inscribed polygon.
            if (deepestCorner(piecesA != null ? piecesA : inscribed(a, sc, sc.inscribedA),
                    piecesB != null ? piecesB : inscribed(b, sc, sc.inscribedB), scale, sc)) {
                return;
            }
        }
        if (roundA != roundB) {
            double[] round = roundA ? pa : pb, other = roundA ? pb : pa;
            boolean roundIn = roundA ? aInB : bInA, otherIn = roundA ? bInA : aInB;
            double[] p = roundIn || !otherIn ? round : other;
            one(p[0], p[1], d, sc);
        } else if (aInB == bInA) {
            one((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, d, sc);
        } else {
            double[] p = aInB ? pa : pb;
            one(p[0], p[1], d, sc);
        }
    }

    /** The deepest corners of the overlap of the two shapes' pieces, one or two, as the answer; false if none. */
    private static boolean deepestCorner(List<Piece> pa, List<Piece> pb, double scale, Scratch sc) {
        if (pa == null || pb == null) {
            return false;
        }
        Points points = sc.points.clear();
        for (int i = 0; i < pa.size(); i++) {
            for (int j = 0; j < pb.size(); j++) {
                Piece p = pa.get(i), q = pb.get(j);
                if (boxesMeet(p, q, scale)) {
                    overlapCorners(p, q, sc.nx, sc.ny, pa, pb, scale, sc);
                }
            }
        }
        if (points.n == 0) {
            return false;
        }
        keepDeepest(points, scale);
        reduce(points, scale, sc);
        return true;
    }

    /** The number of corners of a round shape's inscribed polygon. */
    private static final int INSCRIBED = 64;

    /**
     * The directions of the inscribed polygon's corners, {@code 2 pi i / INSCRIBED}: the same
     * angles on every call, so their cosines and sines are worked out once (by StrictMath, the
     * same bits on every platform) instead of 64 times a call.
     */
    private static final double[] ROUND_COS = new double[INSCRIBED], ROUND_SIN = new double[INSCRIBED];

    /**
     * A rounded segment's half circle, from {@code -pi / 2} to {@code pi / 2} in
     * {@code INSCRIBED / 2} steps, its two ends exact (0 and -1, 0 and 1).
     */
    private static final double[] HALF_COS = new double[INSCRIBED / 2 + 1], HALF_SIN = new double[INSCRIBED / 2 + 1];

    static {
        for (int i = 0; i < INSCRIBED; i++) {
            double t = 2 * Math.PI * i / INSCRIBED;
            ROUND_COS[i] = StrictMath.cos(t);
            ROUND_SIN[i] = StrictMath.sin(t);
        }
        int half = INSCRIBED / 2;
        for (int i = 0; i <= half; i++) {
            double t = -Math.PI / 2 + Math.PI * i / half;
            HALF_COS[i] = i == 0 || i == half ? 0 : StrictMath.cos(t);
            HALF_SIN[i] = i == 0 ? -1 : i == half ? 1 : StrictMath.sin(t);
        }
    }

    /** A round shape as its inscribed polygon, one piece in {@code out}; null for a shape of no extent. */
    private static List<Piece> inscribed(Shape s, Scratch sc, List<Piece> out) {
        double[] xy = sc.inscribed, p = sc.support;
        for (int i = 0; i < INSCRIBED; i++) {
            support(s, ROUND_COS[i], ROUND_SIN[i], p, sc);
            xy[2 * i] = p[0];
            xy[2 * i + 1] = p[1];
        }
        out.clear();
        return straight(xy, sc, out);
    }

    /** The shape's point farthest along unit (ux, uy) into {@code out}; the middle of a flat side that is farthest. */
    private static void support(Shape s, double ux, double uy, double[] out, Scratch sc) {
        switch (ShapeKind.of(s)) {
            case CIRCLE -> {
                Circle o = (Circle) s;
                out[0] = o.x() + o.r() * ux;
                out[1] = o.y() + o.r() * uy;
            }
            case ELLIPSE -> {
                Ellipse e = (Ellipse) s;
                double cos = e.angle() == 0 ? 1 : StrictMath.cos(e.angle()), sin = e.angle() == 0 ? 0 : StrictMath.sin(e.angle());
                // In the ellipse's own axes: the point (a^2 u, b^2 v) / |(a u, b v)|.
                double u = ux * cos + uy * sin, v = -ux * sin + uy * cos;
                double au = (double) e.rx() * u, bv = (double) e.ry() * v, len = Math.hypot(au, bv);
                double lx = len == 0 ? 0 : e.rx() * au / len, ly = len == 0 ? 0 : e.ry() * bv / len;
                out[0] = e.x() + lx * cos - ly * sin;
                out[1] = e.y() + lx * sin + ly * cos;
            }
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                farthest(ends(sc.edge, k.x1(), k.y1(), k.x2(), k.y2()), 4, ux, uy, out);
                out[0] += k.r() * ux;
                out[1] += k.r() * uy;
            }
            case RECT -> farthest(Polygons.corners((Rect) s, sc.corners), 8, ux, uy, out);
            case POLYGON -> {
                double[] c = HiddenParts.corners((Polygon) s);
                farthest(c, c.length, ux, uy, out);
            }
            case SEGMENT -> {
                Segment g = (Segment) s;
                farthest(ends(sc.edge, g.x1(), g.y1(), g.x2(), g.y2()), 4, ux, uy, out);
            }
        }
    }

    private static double[] ends(double[] e, double x1, double y1, double x2, double y2) {
        edge(e, x1, y1, x2, y2);
        return e;
    }

    /** The vertex of the first len numbers of xy farthest along (ux, uy) into {@code out}; the middle of those as far, to rounding. */
    private static void farthest(double[] xy, int len, double ux, double uy, double[] out) {
        double most = Double.NEGATIVE_INFINITY, size = 0;
        for (int i = 0; i < len; i += 2) {
            most = Math.max(most, xy[i] * ux + xy[i + 1] * uy);
            size = Math.max(size, Math.abs(xy[i]) + Math.abs(xy[i + 1]));
        }
        double minT = Double.POSITIVE_INFINITY, maxT = Double.NEGATIVE_INFINITY;
        int lo = -1, hi = -1;
        for (int i = 0; i < len; i += 2) {
            if (xy[i] * ux + xy[i + 1] * uy >= most - SAME * Math.max(1, size)) {
                double t = -xy[i] * uy + xy[i + 1] * ux;
                if (t < minT) {
                    minT = t;
                    lo = i;
                }
                if (t > maxT) {
                    maxT = t;
                    hi = i;
                }
            }
        }
        out[0] = (xy[lo] + xy[hi]) / 2;
        out[1] = (xy[lo + 1] + xy[hi + 1]) / 2;
    }

    /** How far the point lies outside the shape (0 or less: in its closure), roughly a distance. */
    private static double outside(Shape s, double px, double py, Scratch sc) {
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
                List<Piece> pieces = pieces(s, sc, sc.polygon);
                for (int i = 0; i < pieces.size(); i++) {
                    Piece p = pieces.get(i);
                    double worst = Double.NEGATIVE_INFINITY;
                    for (int k = 0; k < p.np; k += 3) {
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
