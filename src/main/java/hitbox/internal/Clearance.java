package hitbox.internal;

import hitbox.*;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The shortest move that clears a concave polygon: the contact for pairs where pushing out of
 * the nearest edge is not enough, because the pushed shape can land in another part of the
 * polygon.
 *
 * <p>The method works in "translation space": the set of moves v of b that leave b + v
 * overlapping a. The answer is the point nearest to the origin (no move) outside that set,
 * and it lies on the set's outline: on one of the outline's pieces, at the foot of the
 * perpendicular from the origin, at a corner of a piece, or where two pieces cross. So the
 * candidates are listed, the ones inside the set are thrown out, and the nearest one left
 * wins.
 *
 * <ul>
 *   <li>Polygons and rectangles: each is cut into convex pieces (a concave polygon into
 *       triangles by ear clipping, merged back where they stay convex). Two pieces overlap
 *       exactly when the move lies inside their Minkowski difference, a convex polygon; the
 *       set is the union of those. Its outline is found edge by edge: the parts of each
 *       region's edge not inside another region, and on each part the point nearest the
 *       origin (the ends of those parts are where two regions' edges cross).</li>
 *   <li>A circle against a polygon: the centre must end at least r from the polygon, so the
 *       pieces are the polygon's edges pushed out by r and circles of radius r around its
 *       corners.</li>
 * </ul>
 *
 * <p>A candidate on an outline is, in exact arithmetic, exactly on the edge of the set; so it
 * counts as inside only when it is inside by more than {@link #TOLERANCE} times the size of
 * the problem. The move found may therefore leave an overlap that small, and candidates
 * that close in length tie (and go by the tie rule of {@link Contact}).
 *
 * <p>The cutting into convex pieces is {@link Triangulation}'s.
 *
 * <p>The circle half of the search, whose pieces are round, is {@link CircleClearance}'s;
 * the tolerance and the small geometry here are shared by both. At about 560 lines this is
 * a little over the usual size: the polygon search's candidates, regions and lines of moves
 * only make sense together.
 *
 * <p>Reference: C. Ericson, <i>Real-Time Collision Detection</i>, 2005, section 3.11
 * (Minkowski sums and differences).
 */
public final class Clearance {
    private Clearance() {
    }

    /** Relative tolerance for "inside the overlap set", a fraction of the problem's size. */
    public static final double TOLERANCE = 1e-9;

    /**
     * A shape as convex pieces (x0, y0, x1, y1, ...), the cuts between them (each x0, y0, x1,
     * y1), and whether it is flat: a rectangle of width or height 0, one piece that is a
     * segment or a point.
     */
    public record Parts(List<double[]> pieces, List<double[]> cuts, boolean flat) {

        /** A rectangle's or polygon's parts. */
        public static Parts of(Shape s) {
            return switch (ShapeKind.of(s)) {
                case RECT -> {
                    Rect r = (Rect) s;
                    yield new Parts(List.of(Polygons.corners(r, new double[8])), List.of(), r.w() == 0 || r.h() == 0);
                }
                case POLYGON -> of((Polygon) s);
                case ELLIPSE, CAPSULE, CIRCLE, SEGMENT -> throw Polygons.notStraight(s);
            };
        }

        /** A polygon's parts: itself if convex, else its convex pieces and the cuts between them. */
        public static Parts of(Polygon s) {
            double[] xy = HiddenParts.corners(s).clone();
            if (s.isConvex()) {
                return new Parts(List.of(xy), List.of(), false);
            }
            List<int[]> cuts = new ArrayList<>();
            List<double[]> pieces = new ArrayList<>();
            for (int[] piece : Triangulation.convexPieces(xy, cuts)) {
                double[] c = new double[2 * piece.length];
                for (int k = 0; k < piece.length; k++) {
                    c[2 * k] = xy[2 * piece[k]];
                    c[2 * k + 1] = xy[2 * piece[k] + 1];
                }
                pieces.add(c);
            }
            List<double[]> segments = new ArrayList<>();
            for (int[] d : cuts) {
                segments.add(new double[] {xy[2 * d[0]], xy[2 * d[0] + 1], xy[2 * d[1]], xy[2 * d[1] + 1]});
            }
            return new Parts(pieces, segments, false);
        }
    }

    /**
     * A convex region of moves, counter-clockwise, with its edges' lengths and its bounding
     * box for quick misses.
     */
    private record Region(double[] m, double[] lengths, double minX, double minY, double maxX, double maxY) {

        public static Region of(double[] m) {
            int n = m.length / 2;
            double[] lengths = new double[n];
            double minX = m[0], minY = m[1], maxX = m[0], maxY = m[1];
            for (int i = 0; i < n; i++) {
                int j = (i + 1) % n;
                lengths[i] = length(m[2 * j] - m[2 * i], m[2 * j + 1] - m[2 * i + 1]);
                minX = Math.min(minX, m[2 * i]);
                maxX = Math.max(maxX, m[2 * i]);
                minY = Math.min(minY, m[2 * i + 1]);
                maxY = Math.max(maxY, m[2 * i + 1]);
            }
            return new Region(m, lengths, minX, minY, maxX, maxY);
        }

        /**
         * The open interval of parameters t in which the point e0 + t (e1 - e0) of segment e
         * (its first four values) is inside this region by more than tol, or null. Each edge
         * of the region gives one linear condition on t; for whole numbers the conditions at
         * t = 0 and t = 1 are decided exactly. The answer is {lo, hi, the region's edge that
         * set lo, the edge that set hi} (an edge -1 where none did).
         */
        public double[] span(double[] e, double tol) {
            if (Math.max(e[0], e[2]) <= minX || Math.min(e[0], e[2]) >= maxX
                    || Math.max(e[1], e[3]) <= minY || Math.min(e[1], e[3]) >= maxY) {
                return null;
            }
            double lo = Double.NEGATIVE_INFINITY, hi = Double.POSITIVE_INFINITY;
            int loEdge = -1, hiEdge = -1;
            int n = m.length / 2;
            for (int i = 0; i < n; i++) {
                int j = (i + 1) % n;
                double margin = tol * lengths[i];
                double s0 = Lines.orient(m[2 * i], m[2 * i + 1], m[2 * j], m[2 * j + 1], e[0], e[1]) - margin;
                double s1 = Lines.orient(m[2 * i], m[2 * i + 1], m[2 * j], m[2 * j + 1], e[2], e[3]) - margin;
                // Inside this edge's half-plane where s0 + t (s1 - s0) > 0.
                if (s0 > 0 && s1 > 0) {
                    continue;
                }
                if (s0 <= 0 && s1 <= 0) {
                    return null;
                }
                double t = s0 / (s0 - s1);
                if (s1 > s0) {
                    if (t > lo) {
                        lo = t;
                        loEdge = i;
                    }
                } else if (t < hi) {
                    hi = t;
                    hiEdge = i;
                }
            }
            return lo < hi && hi > 0 && lo < 1 ? new double[] {lo, hi, loEdge, hiEdge} : null;
        }
    }


    // ---------------------------------------------------------------- polygons and rectangles

    /**
     * The contact between a and b, each given as convex pieces, or null when they do not
     * overlap. Normal from a to b.
     */
    public static Contact polygons(Parts a, Parts b) {
        // The moves v of b that overlap piece p of a and piece q of b: inside hull(p - q).
        List<Region> regions = new ArrayList<>();
        for (double[] p : a.pieces()) {
            for (double[] q : b.pieces()) {
                double[] m = hull(differences(p, q));
                if (m.length >= 6) {
                    regions.add(Region.of(m));
                }
            }
        }
        // A flat rectangle lying exactly along a cut is inside the polygon but inside none of
        // its open pieces: those moves form a line, added here as a region of its own.
        List<double[]> lines = new ArrayList<>();
        if (a.flat()) {
            for (double[] d : b.cuts()) {
                addLine(lines, a.pieces().get(0), d);
            }
        }
        if (b.flat()) {
            for (double[] d : a.cuts()) {
                addLine(lines, d, b.pieces().get(0));
            }
        }
        if (!coversOrigin(regions, lines)) {
            return null;
        }
        double extent = 0;
        for (Region r : regions) {
            extent = Math.max(extent, Math.max(Math.max(-r.minX(), r.maxX()), Math.max(-r.minY(), r.maxY())));
        }
        double tol = TOLERANCE * (1 + extent);

        // Every edge of every region, nearest first: its distance from the origin is a lower
        // bound for any candidate on it, so the search stops at the first edge farther away
        // than the best found.
        List<double[]> edges = new ArrayList<>();
        for (int k = 0; k < regions.size(); k++) {
            double[] m = regions.get(k).m();
            int n = m.length / 2;
            for (int i = 0; i < n; i++) {
                int j = (i + 1) % n;
                edges.add(new double[] {m[2 * i], m[2 * i + 1], m[2 * j], m[2 * j + 1],
                        segmentDistance(m[2 * i], m[2 * i + 1], m[2 * j], m[2 * j + 1]), k});
            }
        }
        edges.sort((e, f) -> Double.compare(e[4], f[4]));
        Contacts.Shortest best = new Contacts.Shortest(2 * tol);
        List<double[]> inside = new ArrayList<>();
        for (double[] e : edges) {
            if (best.beyond(e[4])) {
                break;
            }
            // The parts of the edge inside other regions (or along a line), as open intervals
            // of the edge's parameter t, from 0 at its start to 1 at its end.
            inside.clear();
            boolean buried = false;
            for (int k = 0; k < regions.size() && !buried; k++) {
                if (k != (int) e[5]) {
                    double[] span = regions.get(k).span(e, tol);
                    if (span != null) {
                        inside.add(new double[] {span[0], span[1], span[2], span[3], k});
                        // Most edges lie wholly inside another region: nothing to find there.
                        buried = span[0] < 0 && span[1] > 1;
                    }
                }
            }
            if (buried) {
                continue;
            }
            for (double[] l : lines) {
                double[] span = lineSpan(l, e, tol);
                if (span != null) {
                    inside.add(span);
                }
            }
            inside.sort((u, w) -> Double.compare(u[0], w[0]));
            // The closed gaps between those intervals are on the outline; on each, offer the
            // point nearest the origin.
            double ex = e[2] - e[0], ey = e[3] - e[1];
            double foot = -(e[0] * ex + e[1] * ey) / (ex * ex + ey * ey);
            double from = 0;
            double[] fromSpan = null;
            for (double[] span : inside) {
                if (span[0] >= from) {
                    offerGap(best, e, from, Math.min(span[0], 1), foot, lines, tol,
                            crossingAt(regions, fromSpan, 1), span[0] <= 1 ? crossingAt(regions, span, 0) : null);
                }
                if (span[1] > from) {
                    from = span[1];
                    fromSpan = span;
                }
                if (from > 1) {
                    break;
                }
            }
            if (from <= 1) {
                offerGap(best, e, from, 1, foot, lines, tol, crossingAt(regions, fromSpan, 1), null);
            }
        }
        return best.contact();
    }

    /**
     * Offers the point of edge e with parameter between lo and hi (a part outside every
     * region) that is nearest the origin. At the foot of the perpendicular the edge's outward
     * normal is the direction: better conditioned than the point's own direction.
     *
     * <p>A point near a line of moves is not offered. Near a region's outline, "within tol"
     * means an overlap that small; but a line stands for a flat rectangle lying along a cut,
     * overlapping over its whole length. Next to such a line both sides are covered by the
     * regions of the two pieces the cut separates, so nothing nearer is lost.
     */
    private static void offerGap(Contacts.Shortest best, double[] e, double lo, double hi, double foot,
                                 List<double[]> lines, double tol, double[] loCrossing, double[] hiCrossing) {
        double ex = e[2] - e[0], ey = e[3] - e[1];
        double t = Math.max(lo, Math.min(hi, foot));
        if (!lines.isEmpty() && onLine(lines, e[0] + t * ex, e[1] + t * ey, tol)) {
            return;
        }
        if (t == foot && t > 0 && t < 1) {
            // Regions run counter-clockwise (positive turn): outward is to the right.
            double len = length(ex, ey);
            double side = Lines.orient(e[0], e[1], e[2], e[3], 0, 0) / len;
            if (side > 0) {
                best.offer(ey / len, -ex / len, side);
            } else if (side < 0) {
                best.offer(-ey / len, ex / len, -side);
            }
            return;
        }
        // The ends themselves, not e0 + 1 * (e1 - e0), so that corners stay exact.
        double px = t == 0 ? e[0] : t == 1 ? e[2] : e[0] + t * ex;
        double py = t == 0 ? e[1] : t == 1 ? e[3] : e[1] + t * ey;
        double d = length(px, py);
        // An end of the gap where another region's edge crosses this one: that crossing
        // was found on the region's edge moved in by the tolerance, so the point is off the
        // true corner of the outline by about tol, in a direction the tie rule would read as
        // a different normal (an exact fit's (-1, 0) came out as (-1, -3e-8), and moving
        // along it never cleared). Where the point can still win, the crossing of the two
        // edges themselves is worked out exactly and rounded once.
        double[] crossing = t == lo && t > 0 ? loCrossing : t == hi && t < 1 ? hiCrossing : null;
        if (crossing != null && !best.beyond(d)) {
            double[] c = crossing(e, crossing);
            if (c != null) {
                px = c[0];
                py = c[1];
                d = length(px, py);
            }
        }
        if (d > 0) {
            best.offer(px / d, py / d, d);
        }
    }

    /**
     * The region edge that ends a span on one side (0: its low end, 1: its high end), as the
     * edge's two ends, or null when no region edge does (a line's span, or none).
     */
    private static double[] crossingAt(List<Region> regions, double[] span, int end) {
        if (span == null || span.length < 5 || span[2 + end] < 0) {
            return null;
        }
        double[] m = regions.get((int) span[4]).m();
        int i = (int) span[2 + end], j = (i + 1) % (m.length / 2);
        return new double[] {m[2 * i], m[2 * i + 1], m[2 * j], m[2 * j + 1]};
    }

    /**
     * Where the line of segment e meets the line of segment f (first four values each),
     * exactly, rounded once to double; null when they are parallel. With s0 and s1 the
     * orientations of e's ends seen from f, the point is (s0 e1 - s1 e0) / (s0 - s1).
     */
    private static double[] crossing(double[] e, double[] f) {
        BigDecimal s0 = Lines.exactOrient(f[0], f[1], f[2], f[3], e[0], e[1]);
        BigDecimal s1 = Lines.exactOrient(f[0], f[1], f[2], f[3], e[2], e[3]);
        BigDecimal den = s0.subtract(s1);
        if (den.signum() == 0) {
            return null;
        }
        BigDecimal x = s0.multiply(new BigDecimal(e[2])).subtract(s1.multiply(new BigDecimal(e[0])));
        BigDecimal y = s0.multiply(new BigDecimal(e[3])).subtract(s1.multiply(new BigDecimal(e[1])));
        return new double[] {x.divide(den, MathContext.DECIMAL128).doubleValue(),
                y.divide(den, MathContext.DECIMAL128).doubleValue()};
    }

    /** Is (px, py) within 2 tol of a line of moves, away from the line's open ends? */
    private static boolean onLine(List<double[]> lines, double px, double py, double tol) {
        for (double[] l : lines) {
            double lx = l[2] - l[0], ly = l[3] - l[1];
            double len = length(lx, ly);
            double across = Math.abs(Lines.orient(l[0], l[1], l[2], l[3], px, py)) / len;
            double along = ((px - l[0]) * lx + (py - l[1]) * ly) / len;
            if (across <= 2 * tol && along > tol && along < len - tol) {
                return true;
            }
        }
        return false;
    }

    /**
     * Where segment e (its first four values) runs along line l (a segment of moves), within
     * tol: the open interval of e's parameter, or null when e does not run along l.
     */
    private static double[] lineSpan(double[] l, double[] e, double tol) {
        double lx = l[2] - l[0], ly = l[3] - l[1];
        double len = length(lx, ly);
        if (Math.abs(Lines.orient(l[0], l[1], l[2], l[3], e[0], e[1])) / len > tol
                || Math.abs(Lines.orient(l[0], l[1], l[2], l[3], e[2], e[3])) / len > tol) {
            return null;
        }
        double ex = e[2] - e[0], ey = e[3] - e[1];
        double elen2 = ex * ex + ey * ey;
        double a = ((l[0] - e[0]) * ex + (l[1] - e[1]) * ey) / elen2;
        double b = ((l[2] - e[0]) * ex + (l[3] - e[1]) * ey) / elen2;
        double margin = tol / Math.sqrt(elen2);
        double lo = Math.min(a, b) + margin, hi = Math.max(a, b) - margin;
        return lo < hi ? new double[] {lo, hi} : null;
    }

    /** Is the origin (no move) strictly inside a region or on a line? Exact, no tolerance. */
    private static boolean coversOrigin(List<Region> regions, List<double[]> lines) {
        for (Region r : regions) {
            if (insideConvex(r.m(), 0, 0, 0)) {
                return true;
            }
        }
        for (double[] l : lines) {
            double ex = l[2] - l[0], ey = l[3] - l[1];
            if (Lines.orient(l[0], l[1], l[2], l[3], 0, 0) == 0
                    && -l[0] * ex - l[1] * ey > 0 && l[2] * ex + l[3] * ey > 0) {
                return true;
            }
        }
        return false;
    }

    /** Is (px, py) inside the counter-clockwise convex polygon m by more than tol? */
    private static boolean insideConvex(double[] m, double px, double py, double tol) {
        int n = m.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double o = Lines.orient(m[2 * i], m[2 * i + 1], m[2 * j], m[2 * j + 1], px, py);
            if (!(o > tol * length(m[2 * j] - m[2 * i], m[2 * j + 1] - m[2 * i + 1]))) {
                return false;
            }
        }
        return true;
    }

    /**
     * Adds the moves that put flat piece s onto open diagonal d (or d onto s, the order of
     * the difference being u - w), when the two are parallel: a segment of moves.
     */
    private static void addLine(List<double[]> lines, double[] u, double[] w) {
        // A flat piece is the rectangle's four corners: its extreme corners are its ends.
        double[] su = ends(u), sw = ends(w);
        double ux = su[2] - su[0], uy = su[3] - su[1];
        double wx = sw[2] - sw[0], wy = sw[3] - sw[1];
        if (ux * wy - uy * wx != 0) {
            return;
        }
        // All four differences lie on one line; keep the two extremes.
        double dx = ux != 0 || uy != 0 ? ux : wx;
        double dy = ux != 0 || uy != 0 ? uy : wy;
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        double[] line = new double[4];
        for (int i = 0; i < 4; i += 2) {
            for (int j = 0; j < 4; j += 2) {
                double px = su[i] - sw[j], py = su[i + 1] - sw[j + 1];
                double t = px * dx + py * dy;
                if (t < lo) {
                    lo = t;
                    line[0] = px;
                    line[1] = py;
                }
                if (t > hi) {
                    hi = t;
                    line[2] = px;
                    line[3] = py;
                }
            }
        }
        if (lo < hi) {
            lines.add(line);
        }
    }

    /** The two ends of a diagonal (x0, y0, x1, y1) or of a flat rectangle's corners. */
    private static double[] ends(double[] p) {
        if (p.length == 4) {
            return p;
        }
        // Corners x, y, right, y, right, bottom, x, bottom: the ends are corners 0 and 2.
        return new double[] {p[0], p[1], p[4], p[5]};
    }

    /** All pairwise differences p_i - q_j. */
    private static double[] differences(double[] p, double[] q) {
        double[] d = new double[p.length * q.length / 2];
        int k = 0;
        for (int i = 0; i < p.length; i += 2) {
            for (int j = 0; j < q.length; j += 2) {
                d[k++] = p[i] - q[j];
                d[k++] = p[i + 1] - q[j + 1];
            }
        }
        return d;
    }

    /**
     * The convex hull, counter-clockwise (positive turn), without repeated or collinear
     * points. Reference: A. M. Andrew, "Another efficient algorithm for convex hulls in two
     * dimensions", 1979 (the monotone chain).
     */
    public static double[] hull(double[] xy) {
        int n = xy.length / 2;
        // By x, then y; insertion sort, as the point sets are small (pieces times pieces).
        int[] order = new int[n];
        for (int i = 0; i < n; i++) {
            int k = i;
            while (k > 0 && before(xy, i, order[k - 1])) {
                order[k] = order[k - 1];
                k--;
            }
            order[k] = i;
        }
        double[] h = new double[4 * n + 4];
        int k = 0;
        for (int pass = 0; pass < 2; pass++) {
            int start = k;
            for (int s = 0; s < n; s++) {
                int i = pass == 0 ? order[s] : order[n - 1 - s];
                double x = xy[2 * i], y = xy[2 * i + 1];
                while (k - start >= 2 && Lines.orient(h[2 * k - 4], h[2 * k - 3], h[2 * k - 2], h[2 * k - 1], x, y) <= 0) {
                    k--;
                }
                h[2 * k] = x;
                h[2 * k + 1] = y;
                k++;
            }
            k--; // the last point of each chain starts the other one
        }
        if (k < 3) {
            return new double[0];
        }
        return Arrays.copyOf(h, 2 * k);
    }

    private static boolean before(double[] xy, int i, int j) {
        return xy[2 * i] < xy[2 * j] || (xy[2 * i] == xy[2 * j] && xy[2 * i + 1] < xy[2 * j + 1]);
    }

    /**
     * The length of (x, y). Not {@code Math.hypot}, which guards against overflow at a high
     * price: every value here comes from floats, whose squares fit a double easily.
     */
    public static double length(double x, double y) {
        return Math.sqrt(x * x + y * y);
    }

    // ------------------------------------------------------------------------ small geometry

    /** Distance from the origin to the segment (x0, y0)-(x1, y1). */
    public static double segmentDistance(double x0, double y0, double x1, double y1) {
        double ex = x1 - x0, ey = y1 - y0;
        double len2 = ex * ex + ey * ey;
        double along = -(x0 * ex + y0 * ey);
        if (len2 == 0 || along <= 0) {
            return length(x0, y0);
        }
        if (along >= len2) {
            return length(x1, y1);
        }
        return Math.abs(x0 * ey - y0 * ex) / Math.sqrt(len2);
    }

    /** Where two segments (first four values each) cross, ends included; null if they do not or are parallel. */
    public static double[] segmentCrossing(double[] e, double[] f) {
        double ex = e[2] - e[0], ey = e[3] - e[1];
        double fx = f[2] - f[0], fy = f[3] - f[1];
        double den = ex * fy - ey * fx;
        if (den == 0) {
            return null;
        }
        double gx = f[0] - e[0], gy = f[1] - e[1];
        double t = (gx * fy - gy * fx) / den;
        double u = (gx * ey - gy * ex) / den;
        if (t < 0 || t > 1 || u < 0 || u > 1) {
            return null;
        }
        return new double[] {e[0] + t * ex, e[1] + t * ey};
    }

}
