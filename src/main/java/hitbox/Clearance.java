package hitbox;

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
 * <p>Reference: C. Ericson, <i>Real-Time Collision Detection</i>, 2005, section 3.11
 * (Minkowski sums and differences); D. Eberly, "Triangulation by Ear Clipping", 2002;
 * S. Hertel, K. Mehlhorn, "Fast triangulation of simple polygons", 1983.
 */
final class Clearance {
    private Clearance() {
    }

    /** Relative tolerance for "inside the overlap set", a fraction of the problem's size. */
    static final double TOLERANCE = 1e-9;

    /**
     * A shape as convex pieces (x0, y0, x1, y1, ...), the cuts between them (each x0, y0, x1,
     * y1), and whether it is flat: a rectangle of width or height 0, one piece that is a
     * segment or a point.
     */
    record Parts(List<double[]> pieces, List<double[]> cuts, boolean flat) {

        static Parts of(Shape s) {
            double[] xy = Polygons.corners(s);
            if (s instanceof Rect r) {
                return new Parts(List.of(xy), List.of(), r.w() == 0 || r.h() == 0);
            }
            if (((Polygon) s).isConvex()) {
                return new Parts(List.of(xy), List.of(), false);
            }
            List<int[]> cuts = new ArrayList<>();
            List<double[]> pieces = new ArrayList<>();
            for (int[] piece : convexPieces(xy, cuts)) {
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

        static Region of(double[] m) {
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
         * t = 0 and t = 1 are decided exactly.
         */
        double[] span(double[] e, double tol) {
            if (Math.max(e[0], e[2]) <= minX || Math.min(e[0], e[2]) >= maxX
                    || Math.max(e[1], e[3]) <= minY || Math.min(e[1], e[3]) >= maxY) {
                return null;
            }
            double lo = Double.NEGATIVE_INFINITY, hi = Double.POSITIVE_INFINITY;
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
                    lo = Math.max(lo, t);
                } else {
                    hi = Math.min(hi, t);
                }
            }
            return lo < hi && hi > 0 && lo < 1 ? new double[] {lo, hi} : null;
        }
    }


    // ---------------------------------------------------------------- polygons and rectangles

    /**
     * The contact between a and b, each given as convex pieces, or null when they do not
     * overlap. Normal from a to b.
     */
    static Contact polygons(Parts a, Parts b) {
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
                        inside.add(span);
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
            for (double[] span : inside) {
                if (span[0] >= from) {
                    offerGap(best, e, from, Math.min(span[0], 1), foot, lines, tol);
                }
                from = Math.max(from, span[1]);
                if (from > 1) {
                    break;
                }
            }
            if (from <= 1) {
                offerGap(best, e, from, 1, foot, lines, tol);
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
                                 List<double[]> lines, double tol) {
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
        if (d > 0) {
            best.offer(px / d, py / d, d);
        }
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
    static double[] hull(double[] xy) {
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
    static double length(double x, double y) {
        return Math.sqrt(x * x + y * y);
    }

    // ------------------------------------------------------------------------------ circles

    /**
     * A circle (first) of radius r &gt; 0 against a polygon (second) that it overlaps: the
     * shortest move of the centre to a point at least r from the polygon. Normal from the
     * circle to the polygon, or (flip) from the polygon to the circle, the tie rule applied
     * to the normal as reported.
     */
    static Contact circle(float cx, float cy, float r, float[] xy, boolean flip) {
        int n = xy.length / 2;
        // Everything relative to the centre: the no-move point is the origin.
        double[] p = new double[xy.length];
        double extent = r;
        for (int i = 0; i < n; i++) {
            p[2 * i] = (double) xy[2 * i] - cx;
            p[2 * i + 1] = (double) xy[2 * i + 1] - cy;
            extent = Math.max(extent, Math.max(Math.abs(p[2 * i]), Math.abs(p[2 * i + 1])));
        }
        double tol = TOLERANCE * (1 + extent);
        double turn = Polygons.winding(xy);

        // The outline's pieces: each edge pushed out by r (x0, y0, x1, y1, nx, ny), and a
        // circle of radius r around each corner.
        List<double[]> offsets = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ex = p[2 * j] - p[2 * i], ey = p[2 * j + 1] - p[2 * i + 1];
            double len = length(ex, ey);
            if (len == 0) {
                continue;
            }
            double nx = turn * ey / len, ny = -turn * ex / len;
            offsets.add(new double[] {p[2 * i] + r * nx, p[2 * i + 1] + r * ny,
                    p[2 * j] + r * nx, p[2 * j + 1] + r * ny, nx, ny});
        }

        Disc disc = new Disc(xy, cx, cy, p, r, tol);
        Contacts.Shortest best = new Contacts.Shortest(2 * tol, flip);
        for (double[] o : offsets) {
            offerCentre(best, o[0], o[1], disc);
            double ex = o[2] - o[0], ey = o[3] - o[1];
            double len2 = ex * ex + ey * ey;
            double along = -(o[0] * ex + o[1] * ey);
            if (along > 0 && along < len2) {
                double t = along / len2;
                double qx = o[0] + t * ex, qy = o[1] + t * ey;
                // The centre moves to q, along the edge's normal: the polygon moves against it.
                double s = o[0] * o[4] + o[1] * o[5];
                if (s != 0 && !coveredCentre(qx, qy, disc)) {
                    double sign = Math.signum(s);
                    best.offer(-sign * o[4], -sign * o[5], Math.abs(s));
                }
            }
        }
        for (int i = 0; i < n; i++) {
            double vx = p[2 * i], vy = p[2 * i + 1];
            double d = length(vx, vy);
            if (d > 0) {
                double k = 1 - r / d;
                offerCentre(best, vx * k, vy * k, disc);
            } else {
                // The centre is on this corner: every direction of the corner's cone is as
                // short, so the axis ones are offered too (the cover test drops the others).
                offerCentre(best, 0, r, disc);
                offerCentre(best, 0, -r, disc);
                offerCentre(best, r, 0, disc);
                offerCentre(best, -r, 0, disc);
            }
        }
        // Crossings of two pieces, skipping any piece farther away than the best so far (a
        // crossing lies on both pieces, so it is at least as far as either).
        double[] offsetNear = new double[offsets.size()];
        for (int i = 0; i < offsets.size(); i++) {
            double[] o = offsets.get(i);
            offsetNear[i] = segmentDistance(o[0], o[1], o[2], o[3]);
        }
        double[] circleNear = new double[n];
        for (int v = 0; v < n; v++) {
            circleNear[v] = length(p[2 * v], p[2 * v + 1]) - r;
        }
        for (int i = 0; i < offsets.size(); i++) {
            if (best.beyond(offsetNear[i])) {
                continue;
            }
            double[] o = offsets.get(i);
            for (int j = i + 1; j < offsets.size(); j++) {
                if (!best.beyond(offsetNear[j])) {
                    double[] c = segmentCrossing(o, offsets.get(j));
                    if (c != null) {
                        offerCentre(best, c[0], c[1], disc);
                    }
                }
            }
            for (int v = 0; v < n; v++) {
                if (!best.beyond(circleNear[v])) {
                    for (double[] c : segmentCircle(o, p[2 * v], p[2 * v + 1], r)) {
                        offerCentre(best, c[0], c[1], disc);
                    }
                }
            }
        }
        for (int u = 0; u < n; u++) {
            if (best.beyond(circleNear[u])) {
                continue;
            }
            for (int v = u + 1; v < n; v++) {
                if (!best.beyond(circleNear[v])) {
                    for (double[] c : circleCircle(p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1], r)) {
                        offerCentre(best, c[0], c[1], disc);
                    }
                }
            }
        }
        return best.contact();
    }

    /**
     * The circle search's fixed data: the polygon as given ({@code xy}) and relative to the
     * circle's centre ({@code p}), the radius and the tolerance.
     */
    private record Disc(float[] xy, float cx, float cy, double[] p, double r, double tol) {
    }

    /** Offers moving the centre to (qx, qy), if the circle is clear there. */
    private static void offerCentre(Contacts.Shortest best, double qx, double qy, Disc disc) {
        double d = length(qx, qy);
        if (d == 0 || best.beyond(d) || coveredCentre(qx, qy, disc)) {
            return;
        }
        // The centre moves by q; the polygon, seen from the circle, moves by -q.
        best.offer(-qx / d, -qy / d, d);
    }

    /**
     * Would a circle of radius r centred at (qx, qy) overlap the polygon by more than tol?
     * The inside test is the exact {@link Polygons#contains}, at the centre's place in the
     * polygon's own coordinates; rounding that place matters only on the outline, where the
     * distance test already answers (for r above tol).
     */
    private static boolean coveredCentre(double qx, double qy, Disc disc) {
        if (Polygons.contains(disc.xy(), disc.cx() + qx, disc.cy() + qy)) {
            return true;
        }
        double[] p = disc.p();
        int n = p.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            if (segmentDistance(p[2 * i] - qx, p[2 * i + 1] - qy, p[2 * j] - qx, p[2 * j + 1] - qy)
                    < disc.r() - disc.tol()) {
                return true;
            }
        }
        return false;
    }

    // ------------------------------------------------------------------------ small geometry

    /** Distance from the origin to the segment (x0, y0)-(x1, y1). */
    static double segmentDistance(double x0, double y0, double x1, double y1) {
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
    static double[] segmentCrossing(double[] e, double[] f) {
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

    /** Where the segment (first four values of o) meets the circle of radius r about (cx, cy). */
    private static double[][] segmentCircle(double[] o, double cx, double cy, double r) {
        double ex = o[2] - o[0], ey = o[3] - o[1];
        double gx = o[0] - cx, gy = o[1] - cy;
        double a = ex * ex + ey * ey;
        double b = gx * ex + gy * ey;
        double c = gx * gx + gy * gy - r * r;
        double disc = b * b - a * c;
        if (a == 0 || disc < 0) {
            return new double[0][];
        }
        double root = Math.sqrt(disc);
        List<double[]> out = new ArrayList<>(2);
        for (double t : new double[] {(-b - root) / a, (-b + root) / a}) {
            if (t >= 0 && t <= 1) {
                out.add(new double[] {o[0] + t * ex, o[1] + t * ey});
            }
        }
        return out.toArray(new double[0][]);
    }

    /** Where two circles of the same radius r cross. */
    private static double[][] circleCircle(double ax, double ay, double bx, double by, double r) {
        double dx = bx - ax, dy = by - ay;
        double d = length(dx, dy);
        if (d == 0 || d > 2 * r) {
            return new double[0][];
        }
        double h = Math.sqrt(Math.max(0, r * r - d * d / 4));
        double mx = (ax + bx) / 2, my = (ay + by) / 2;
        double px = -dy / d * h, py = dx / d * h;
        return new double[][] {{mx + px, my + py}, {mx - px, my - py}};
    }

    // ------------------------------------------------------------------------- triangulation

    /**
     * Cuts a simple polygon into convex pieces: triangles by ear clipping, then, cut by cut,
     * the two pieces on either side are merged whenever the union is still convex (Hertel and
     * Mehlhorn's method: at most four times the fewest pieces possible, usually far fewer
     * than triangles). Pieces are vertex indices in the polygon's winding; the cuts kept are
     * added to {@code cuts}, each as two vertex indices.
     *
     * <p>Reference: S. Hertel, K. Mehlhorn, "Fast triangulation of simple polygons", 1983.
     */
    static List<int[]> convexPieces(double[] xy, List<int[]> cuts) {
        List<int[]> diagonals = new ArrayList<>();
        List<int[]> pieces = triangulate(xy, diagonals);
        double turn = Polygons.areaSign(xy);
        for (int[] d : diagonals) {
            int p = pieceWithEdge(pieces, d[0], d[1]);
            int q = pieceWithEdge(pieces, d[1], d[0]);
            if (p < 0 || q < 0) {
                cuts.add(d);
                continue;
            }
            int[] merged = merge(pieces.get(p), pieces.get(q), d[0], d[1]);
            if (convexAt(xy, merged, d[0], turn) && convexAt(xy, merged, d[1], turn)) {
                pieces.set(p, merged);
                pieces.remove(q);
            } else {
                cuts.add(d);
            }
        }
        return pieces;
    }

    /** The piece that runs from vertex u straight to vertex w, or -1. */
    private static int pieceWithEdge(List<int[]> pieces, int u, int w) {
        for (int k = 0; k < pieces.size(); k++) {
            int[] p = pieces.get(k);
            for (int i = 0; i < p.length; i++) {
                if (p[i] == u && p[(i + 1) % p.length] == w) {
                    return k;
                }
            }
        }
        return -1;
    }

    /** Piece p (with edge u to w) and piece q (with edge w to u) joined along that edge. */
    private static int[] merge(int[] p, int[] q, int u, int w) {
        int[] out = new int[p.length + q.length - 2];
        int i = 0;
        while (p[i] != w) {
            i++;
        }
        int k = 0;
        for (int s = 0; s < p.length; s++) {
            out[k++] = p[(i + s) % p.length]; // w ... u, all of p
        }
        int j = 0;
        while (q[j] != u) {
            j++;
        }
        for (int s = 1; s < q.length - 1; s++) {
            out[k++] = q[(j + s) % q.length]; // after u, up to before w
        }
        return out;
    }

    /** Does the piece turn with the polygon (or go straight) at vertex v? */
    private static boolean convexAt(double[] xy, int[] piece, int v, double turn) {
        int n = piece.length;
        for (int i = 0; i < n; i++) {
            if (piece[i] == v) {
                return orient(xy, piece[(i + n - 1) % n], v, piece[(i + 1) % n]) * turn >= 0;
            }
        }
        return false;
    }

    /**
     * Cuts a simple polygon into triangles by ear clipping; each triangle is three vertex
     * indices in the polygon's winding, and each cut (two vertex indices) is added to
     * {@code diagonals}. Straight vertices (on the line between their neighbours) are dropped
     * on the way; they change nothing. Orientation tests only, exact for whole numbers.
     *
     * <p>Reference: D. Eberly, "Triangulation by Ear Clipping", 2002.
     *
     * @throws IllegalArgumentException if the polygon has no area or crosses itself (then no
     *                                  ear can be found)
     */
    static List<int[]> triangulate(double[] xy, List<int[]> diagonals) {
        int n = xy.length / 2;
        double turn = Polygons.areaSign(xy);
        if (turn == 0) {
            throw new IllegalArgumentException("the polygon has no area, so it cannot be cut into triangles");
        }
        int[] v = new int[n];
        for (int i = 0; i < n; i++) {
            v[i] = i;
        }
        int count = n;
        List<int[]> triangles = new ArrayList<>(n - 2);
        while (count > 3) {
            boolean cut = false;
            for (int k = 0; k < count && !cut; k++) {
                int a = v[(k + count - 1) % count], b = v[k], c = v[(k + 1) % count];
                double o = orient(xy, a, b, c);
                if (o == 0) {
                    // Straight: b lies on the way from a to c, so dropping it changes nothing.
                    cut = true;
                } else if (o * turn > 0 && isEar(xy, v, count, a, b, c, turn)) {
                    triangles.add(new int[] {a, b, c});
                    diagonals.add(new int[] {a, c});
                    cut = true;
                }
                if (cut) {
                    System.arraycopy(v, k + 1, v, k, count - k - 1);
                    count--;
                }
            }
            if (!cut) {
                throw new IllegalArgumentException("the polygon crosses itself, so it cannot be cut into triangles");
            }
        }
        if (orient(xy, v[0], v[1], v[2]) != 0) {
            triangles.add(new int[] {v[0], v[1], v[2]});
        }
        return triangles;
    }

    /** Is triangle a, b, c (turning with the polygon) free of every other remaining vertex? */
    private static boolean isEar(double[] xy, int[] v, int count, int a, int b, int c, double turn) {
        for (int k = 0; k < count; k++) {
            int i = v[k];
            if (i == a || i == b || i == c) {
                continue;
            }
            // In the closed triangle: a vertex on the cut a-c would make the cut touch the outline.
            if (orient(xy, a, b, i) * turn >= 0 && orient(xy, b, c, i) * turn >= 0 && orient(xy, c, a, i) * turn >= 0) {
                return false;
            }
        }
        return true;
    }

    private static double orient(double[] xy, int a, int b, int c) {
        return Lines.orient(xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1], xy[2 * c], xy[2 * c + 1]);
    }
}
