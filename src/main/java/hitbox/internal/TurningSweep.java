package hitbox.internal;

import hitbox.*;

import java.util.ArrayList;
import java.util.List;

/**
 * The time of impact of a convex polygon that moves and turns during the frame
 * ({@link Sweep#turningTimeOfImpact}), by conservative advancement (B. Mirtich, "Impulse-based
 * Dynamic Simulation of Rigid Body Systems", 1996; Ericson, <i>Real-Time Collision
 * Detection</i>, 9.5.3): at time t the gap d to the obstacle is bounded from below, and no
 * point of the mover can travel faster than {@code |v| + |turn| R} (R its farthest vertex
 * from the pivot), so it can advance by {@code d / (|v| + |turn| R)} without touching. Each
 * gap is a lower bound (a separating direction's gap never exceeds the distance), so the
 * mover never passes through anything, however fast it turns.
 *
 * <p>Touching (a gap below {@link #TOUCH}) is a hit only while the gap is closing; a
 * mover leaving a shape it touches moves on, and may come within {@link #TOUCH} minus the
 * gap of it for that one step: the only overlap it can make, and only with what it was
 * already touching.
 *
 * <p>The gap between convex pieces is {@code -(h_A(n) + h_B(-n))} maximised over the
 * direction n, as in {@link Supports}; a concave polygon obstacle is its convex pieces.
 *
 * <p>This class is longer than most (about 510 lines) because it holds both forms, a mover against a
 * standing shape and two bodies that both move and turn, which share the gap searches and
 * the advancement's stopping rule; split apart, each would need the other's private gap code.
 */
public final class TurningSweep {
    private TurningSweep() {
    }

    /** Closer than this (pixels) counts as touching: the hit. */
    public static final double TOUCH = 1e-3;
    private static final int MAX_STEPS = 2000;
    private static final int DIRECTIONS = 32;

    /**
     * The mover's vertices at time t, into {@code out}, returned: turned by t * turn about the
     * pivot, then moved by t * v.
     */
    private static double[] at(float[] xy, double px, double py, double vx, double vy, double turn, double t, double[] out) {
        double c = turn == 0 ? 1 : StrictMath.cos(t * turn), s = turn == 0 ? 0 : StrictMath.sin(t * turn);
        for (int i = 0; i + 1 < xy.length; i += 2) {
            double x = xy[i] - px, y = xy[i + 1] - py;
            out[i] = px + t * vx + c * x - s * y;
            out[i + 1] = py + t * vy + s * x + c * y;
        }
        return out;
    }

    public static Hit timeOfImpact(Polygon mover, float px, float py, float vx, float vy, float turn, Shape obstacle) {
        float[] xy = HiddenParts.raw(mover);
        if (Overlaps.test(mover, obstacle)) {
            return SweptPairs.OVERLAPPING;
        }
        double reach = 0;
        for (int i = 0; i < xy.length; i += 2) {
            reach = Math.max(reach, Math.hypot(xy[i] - px, xy[i + 1] - py));
        }
        double spin = Math.abs(turn) * reach;
        double speed = Math.hypot(vx, vy) + spin;
        if (speed == 0) {
            return null;
        }
        List<double[]> pieces = pieces(obstacle);
        double t = 0;
        double[] normal = new double[2], scratch = new double[2];
        double[] a = new double[xy.length];
        for (int step = 0; step < MAX_STEPS; step++) {
            double gap = gap(at(xy, px, py, vx, vy, turn, t, a), pieces, obstacle, normal);
            if (gap <= TOUCH) {
                // Touching: a hit if the mover is closing in, not if it is leaving (a blade
                // turning back from the post it just touched). One TOUCH of motion on, the
                // gap tells which.
                double later = t + TOUCH / speed;
                if (later > 1 || gap(at(xy, px, py, vx, vy, turn, later, a), pieces, obstacle, scratch) <= gap) {
                    return SweptPairs.hit((float) t, normal[0], normal[1]);
                }
                t = later;
                continue;
            }
            // Advance by most of the safe step, so the gap shrinks towards TOUCH and never past 0.
            // With one piece the gap is the separation along the normal n, and no point of the
            // mover gains on the obstacle along n faster than v.n + |turn| R: the bound that
            // lets the step grow where the motion is not head-on (and no step at all is
            // needed when it never gains).
            double rate = pieces.size() == 1 ? Math.min(speed, vx * normal[0] + vy * normal[1] + spin) : speed;
            if (!(rate > 0)) {
                return null;
            }
            t += (gap - TOUCH / 2) / rate;
            if (t > 1) {
                return null;
            }
        }
        return SweptPairs.hit((float) t, normal[0], normal[1]);
    }

    /**
     * The time of impact of two polygons that both move and turn, each taken as its convex
     * pieces: a turned by {@code t * turnA} about its pivot and moved by {@code t * va}, b (its convex
     * pieces) likewise with its own pivot, motion and turn. Conservative advancement as for a
     * standing obstacle: the gap between the two sets of vertices at time t is a lower bound
     * on their distance, and no point of a gains on a point of b faster than
     * {@code |va - vb| + |turnA| Ra + |turnB| Rb} (each R the farthest vertex from its
     * pivot), so stepping by gap over that bound never passes through. The hit's normal
     * points from a into b; both at rest gives null.
     */
    public static Hit timeOfImpact(Polygon a, float pax, float pay, float vax, float vay, float turnA,
                                   Polygon b, float pbx, float pby, float vbx, float vby, float turnB) {
        if (Overlaps.test(a, b)) {
            return SweptPairs.OVERLAPPING;
        }
        Scratch sc = SCRATCH.get();
        List<float[]> piecesA = floatPieces(a, sc.piecesA);
        double spinA = Math.abs(turnA) * reach(HiddenParts.raw(a), pax, pay);
        double spinB = Math.abs(turnB) * reach(HiddenParts.raw(b), pbx, pby);
        double rvx = (double) vax - vbx, rvy = (double) vay - vby;
        double speed = Math.hypot(rvx, rvy) + spinA + spinB;
        if (speed == 0) {
            return null;
        }
        List<float[]> piecesB = floatPieces(b, sc.piecesB);
        List<double[]> pa = placeholders(piecesA, sc.placedA, sc.byLengthA), at = placeholders(piecesB, sc.placedB, sc.byLengthB);
        double t = 0;
        double[] normal = sc.normal, scratch = sc.other;
        for (int step = 0; step < MAX_STEPS; step++) {
            double gap = gapBetween(piecesA, pax, pay, vax, vay, turnA, piecesB, pbx, pby, vbx, vby, turnB, t, pa, at, normal);
            if (Double.isNaN(gap)) {
                return null;  // placed past the double range (huge motions): nothing there to meet
            }
            if (gap <= TOUCH) {
                // Touching: a hit if closing in, not if leaving, as for a standing obstacle.
                double later = t + TOUCH / speed;
                if (later > 1 || gapBetween(piecesA, pax, pay, vax, vay, turnA, piecesB, pbx, pby, vbx, vby, turnB, later,
                        pa, at, scratch) <= gap) {
                    return SweptPairs.hit((float) t, normal[0], normal[1]);
                }
                t = later;
                continue;
            }
            // With one piece the gap is the separation along n, from a to b, and a gains on b
            // along n no faster than (va - vb).n plus both spins.
            double rate = piecesA.size() == 1 && piecesB.size() == 1 ? Math.min(speed, rvx * normal[0] + rvy * normal[1] + spinA + spinB) : speed;
            if (!(rate > 0)) {
                return null;
            }
            t += (gap - TOUCH / 2) / rate;
            if (!(t <= 1)) {
                return null;
            }
        }
        return SweptPairs.hit((float) t, normal[0], normal[1]);
    }

    /** The farthest vertex's distance from the pivot. */
    private static double reach(float[] xy, double px, double py) {
        double reach = 0;
        for (int i = 0; i + 1 < xy.length; i += 2) {
            reach = Math.max(reach, Math.hypot(xy[i] - px, xy[i + 1] - py));
        }
        return reach;
    }

    /**
     * A polygon's convex pieces as float vertex lists (a convex one is one piece: its own
     * vertices, only read), exact copies, into {@code out}.
     */
    private static List<float[]> floatPieces(Polygon p, List<float[]> out) {
        out.clear();
        if (p.isConvex()) {
            out.add(HiddenParts.raw(p));
            return out;
        }
        for (Object piece : ConvexSweep.pieces(p)) {
            double[] xy = (double[]) piece;
            float[] f = new float[xy.length];
            for (int i = 0; i < xy.length; i++) {
                f[i] = (float) xy[i];
            }
            out.add(f);
        }
        return out;
    }

    /**
     * An array per piece, for its vertices placed at a time, into {@code out}: the thread's
     * own, one per length, for a polygon of one piece (most polygons); made for several.
     */
    private static List<double[]> placeholders(List<float[]> pieces, List<double[]> out, ByLength kept) {
        out.clear();
        for (int i = 0; i < pieces.size(); i++) {
            int n = pieces.get(i).length;
            out.add(pieces.size() == 1 ? kept.of(n) : new double[n]);
        }
        return out;
    }

    /** Arrays of doubles kept by their length. */
    private static final class ByLength {
        private double[][] kept = new double[0][];

        /** The kept array of exactly n doubles (the gap tests read the whole array). */
        double[] of(int n) {
            if (n >= kept.length) {
                kept = java.util.Arrays.copyOf(kept, Math.max(n + 1, 2 * kept.length));
            }
            if (kept[n] == null) {
                kept[n] = new double[n];
            }
            return kept[n];
        }
    }

    /**
     * A thread's lists and arrays for the sweep of two movers, so that two convex polygons'
     * sweep makes nothing but its hit.
     */
    private static final class Scratch {
        final List<float[]> piecesA = new ArrayList<>(), piecesB = new ArrayList<>();
        final List<double[]> placedA = new ArrayList<>(), placedB = new ArrayList<>();
        final ByLength byLengthA = new ByLength(), byLengthB = new ByLength();
        final double[] normal = new double[2], other = new double[2];
    }

    private static final ThreadLocal<Scratch> SCRATCH = ThreadLocal.withInitial(Scratch::new);

    /**
     * The least gap at time t between a's pieces and b's, each placed by its body's motion
     * (into {@code pa} and {@code pb}); its direction, from a to b, into normal.
     */
    private static double gapBetween(List<float[]> piecesA, double pax, double pay, double vax, double vay, double turnA,
                                     List<float[]> piecesB, double pbx, double pby, double vbx, double vby, double turnB,
                                     double t, List<double[]> pa, List<double[]> pb, double[] normal) {
        for (int k = 0; k < piecesB.size(); k++) {
            at(piecesB.get(k), pbx, pby, vbx, vby, turnB, t, pb.get(k));
        }
        double gap = Double.POSITIVE_INFINITY;
        for (int i = 0; i < piecesA.size(); i++) {
            double[] a = at(piecesA.get(i), pax, pay, vax, vay, turnA, t, pa.get(i));
            for (int k = 0; k < pb.size(); k++) {
                gap = Math.min(gap, polygonGap(a, pb.get(k), normal, gap));
            }
        }
        return gap;
    }

    /** The least gap between the mover's vertices {@code a} and the obstacle's pieces; its direction into {@code normal}. */
    private static double gap(double[] a, List<double[]> pieces, Shape obstacle, double[] normal) {
        double gap = Double.POSITIVE_INFINITY;
        for (double[] piece : pieces) {
            gap = Math.min(gap, piece.length >= 4 ? polygonGap(a, piece, normal, gap) : gap(a, piece, obstacle, normal, gap));
        }
        return gap;
    }

    /**
     * The gap between two convex vertex lists (a segment is two vertices): the distance when
     * they are apart (the least over each vertex of one and each edge of the other, its
     * direction from the mover's closest point to the obstacle's), else the best separating
     * axis among both edge normals (0 or less). Writes the direction into {@code normal} when
     * the gap is below {@code best}. Allocates nothing.
     */
    private static double polygonGap(double[] a, double[] b, double[] normal, double best) {
        double sat = Double.NEGATIVE_INFINITY, sx = 0, sy = 0;
        // The last direction found (or the one between the centres) first: most steps it still
        // separates them, and then the edge normals need not be tried.
        double hx = normal[0], hy = normal[1];
        if (hx == 0 && hy == 0) {
            for (int k = 0; k < b.length; k += 2) {
                hx += b[k] / (b.length / 2);
                hy += b[k + 1] / (b.length / 2);
            }
            for (int k = 0; k < a.length; k += 2) {
                hx -= a[k] / (a.length / 2);
                hy -= a[k + 1] / (a.length / 2);
            }
            double len = Math.sqrt(hx * hx + hy * hy);
            hx /= len;
            hy /= len;
        }
        if (hx * hx + hy * hy > 0.5) {
            double maxA = Double.NEGATIVE_INFINITY, minB = Double.POSITIVE_INFINITY;
            for (int k = 0; k < a.length; k += 2) {
                double p = a[k] * hx + a[k + 1] * hy;
                maxA = p > maxA ? p : maxA;
            }
            for (int k = 0; k < b.length; k += 2) {
                double p = b[k] * hx + b[k + 1] * hy;
                minB = p < minB ? p : minB;
            }
            if (minB - maxA > 0) {
                sat = minB - maxA;
                sx = hx;
                sy = hy;
            }
        }
        for (int side = sat > 0 ? 2 : 0; side < 2; side++) {
            double[] e = side == 0 ? a : b;
            int n = e.length / 2;
            for (int i = 0; i < n; i++) {
                int j = i + 1 == n ? 0 : i + 1;
                double ex = e[2 * j] - e[2 * i], ey = e[2 * j + 1] - e[2 * i + 1], len = Math.sqrt(ex * ex + ey * ey);
                if (!(len > 0 && len < Double.POSITIVE_INFINITY)) {
                    continue;
                }
                double nx = ey / len, ny = -ex / len;
                // Both ways at once: along n, b's least minus a's greatest; along -n, a's least minus b's greatest.
                double minA = Double.POSITIVE_INFINITY, maxA = Double.NEGATIVE_INFINITY;
                double minB = Double.POSITIVE_INFINITY, maxB = Double.NEGATIVE_INFINITY;
                for (int k = 0; k < a.length; k += 2) {
                    double p = a[k] * nx + a[k + 1] * ny;
                    minA = p < minA ? p : minA;
                    maxA = p > maxA ? p : maxA;
                }
                for (int k = 0; k < b.length; k += 2) {
                    double p = b[k] * nx + b[k + 1] * ny;
                    minB = p < minB ? p : minB;
                    maxB = p > maxB ? p : maxB;
                }
                double g = minB - maxA, h = minA - maxB;
                if (h > g) {
                    g = h;
                    nx = -nx;
                    ny = -ny;
                }
                if (g > sat) {
                    sat = g;
                    sx = nx;
                    sy = ny;
                }
            }
        }
        if (sat > 0) {
            // Apart: the exact distance, from a vertex of one to an edge of the other. A vertex
            // of a is at least (b's least along s) - (its own reach along s) from b, and a
            // vertex of b (its reach) - (a's greatest) from a: those whose bound is already
            // beyond the best distance are skipped, and the two extreme vertices go first.
            double minB = Double.POSITIVE_INFINITY, maxA = Double.NEGATIVE_INFINITY;
            int ia = 0, ib = 0;
            for (int k = 0; k < a.length; k += 2) {
                double p = a[k] * sx + a[k + 1] * sy;
                if (p > maxA) {
                    maxA = p;
                    ia = k;
                }
            }
            for (int k = 0; k < b.length; k += 2) {
                double p = b[k] * sx + b[k + 1] * sy;
                if (p < minB) {
                    minB = p;
                    ib = k;
                }
            }
            double[] best2 = {Double.POSITIVE_INFINITY, 0, 0};
            vertexToEdges(a[ia], a[ia + 1], b, 1, best2);
            vertexToEdges(b[ib], b[ib + 1], a, -1, best2);
            for (int k = 0; k < a.length; k += 2) {
                double lb = minB - (a[k] * sx + a[k + 1] * sy);
                if (k != ia && lb * lb < best2[0]) {
                    vertexToEdges(a[k], a[k + 1], b, 1, best2);
                }
            }
            for (int k = 0; k < b.length; k += 2) {
                double lb = b[k] * sx + b[k + 1] * sy - maxA;
                if (k != ib && lb * lb < best2[0]) {
                    vertexToEdges(b[k], b[k + 1], a, -1, best2);
                }
            }
            double d = Math.sqrt(best2[0]);
            if (d > sat) {
                if (d < best) {
                    normal[0] = best2[1] / d;
                    normal[1] = best2[2] / d;
                }
                return d;
            }
        }
        if (sat < best) {
            normal[0] = sx;
            normal[1] = sy;
        }
        return sat;
    }

    /**
     * The squared distance from (qx, qy) to the edges of {@code e}, kept in {@code best} (squared
     * distance, then the direction times {@code sign}) when below it.
     */
    private static void vertexToEdges(double qx, double qy, double[] e, double sign, double[] best) {
        int n = e.length / 2;
        for (int i = 0; i < n; i++) {
            int j = i + 1 == n ? 0 : i + 1;
            double x0 = e[2 * i], y0 = e[2 * i + 1], ex = e[2 * j] - x0, ey = e[2 * j + 1] - y0;
            double l2 = ex * ex + ey * ey;
            double u = l2 > 0 ? ((qx - x0) * ex + (qy - y0) * ey) / l2 : 0;
            u = u < 0 ? 0 : u > 1 ? 1 : u;
            double cx = x0 + u * ex - qx, cy = y0 + u * ey - qy;
            double c2 = cx * cx + cy * cy;
            if (c2 < best[0]) {
                best[0] = c2;
                best[1] = sign * cx;
                best[2] = sign * cy;
            }
        }
    }

    /**
     * The obstacle as convex vertex lists: {@link ConvexSweep#pieces}, with each round piece
     * (a circle, ellipse or capsule, kept whole) standing as an empty list for the shape itself.
     */
    private static List<double[]> pieces(Shape s) {
        List<double[]> out = new ArrayList<>();
        for (Object piece : ConvexSweep.pieces(s)) {
            out.add(piece instanceof double[] xy ? xy : new double[0]);
        }
        return out;
    }

    /**
     * A lower bound on the gap between the mover's vertices and one obstacle piece (vertex
     * list, or the curved shape itself when empty): the best separating direction among a
     * ring of directions and the edge normals of both, refined. Writes the direction (from
     * the mover to the obstacle) into {@code normal} when the gap is below {@code best}.
     */
    private static double gap(double[] a, double[] piece, Shape obstacle, double[] normal, double best) {
        double bestGap = Double.NEGATIVE_INFINITY, bx = 0, by = 0;
        int k = 0;
        double[] dirs = directions(a, piece);
        for (int i = 0; i < dirs.length; i += 2) {
            double g = separation(a, piece, obstacle, dirs[i], dirs[i + 1]);
            if (g > bestGap) {
                bestGap = g;
                bx = dirs[i];
                by = dirs[i + 1];
                k = i;
            }
        }
        if (k < 2 * DIRECTIONS) {
            // A ring direction won: refine its angle by golden-section search (still a lower bound).
            double lo = Math.atan2(by, bx) - 2 * Math.PI / DIRECTIONS, hi = lo + 4 * Math.PI / DIRECTIONS;
            double g = (Math.sqrt(5) - 1) / 2;
            for (int i = 0; i < 60; i++) {
                double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
                if (separation(a, piece, obstacle, StrictMath.cos(m1), StrictMath.sin(m1)) > separation(a, piece, obstacle, StrictMath.cos(m2), StrictMath.sin(m2))) {
                    hi = m2;
                } else {
                    lo = m1;
                }
            }
            double m = (lo + hi) / 2, gm = separation(a, piece, obstacle, StrictMath.cos(m), StrictMath.sin(m));
            if (gm > bestGap) {
                bestGap = gm;
                bx = StrictMath.cos(m);
                by = StrictMath.sin(m);
            }
        }
        if (bestGap < best) {
            normal[0] = bx;
            normal[1] = by;
        }
        return bestGap;
    }

    /** The ring of directions, then each edge normal of both vertex lists, both ways. */
    private static double[] directions(double[] a, double[] piece) {
        int na = a.length / 2, nb = piece.length / 2;
        double[] d = new double[2 * DIRECTIONS + 4 * (na + nb)];
        for (int i = 0; i < DIRECTIONS; i++) {
            d[2 * i] = StrictMath.cos(2 * Math.PI * i / DIRECTIONS);
            d[2 * i + 1] = StrictMath.sin(2 * Math.PI * i / DIRECTIONS);
        }
        int k = 2 * DIRECTIONS;
        for (double[] xy : new double[][] {a, piece}) {
            int n = xy.length / 2;
            for (int i = 0; i < n; i++) {
                int j = (i + 1) % n;
                double ex = xy[2 * j] - xy[2 * i], ey = xy[2 * j + 1] - xy[2 * i + 1], len = Math.hypot(ex, ey);
                if (len > 0) {
                    d[k++] = ey / len;
                    d[k++] = -ex / len;
                    d[k++] = -ey / len;
                    d[k++] = ex / len;
                }
            }
        }
        return java.util.Arrays.copyOf(d, k);
    }

    /** How far apart along unit n: the obstacle's least reach minus the mover's greatest. */
    private static double separation(double[] a, double[] piece, Shape obstacle, double nx, double ny) {
        double reachA = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < a.length; i += 2) {
            reachA = Math.max(reachA, a[i] * nx + a[i + 1] * ny);
        }
        double leastB;
        if (piece.length == 0) {
            leastB = -Supports.support(obstacle, -nx, -ny);
        } else {
            leastB = Double.POSITIVE_INFINITY;
            for (int i = 0; i < piece.length; i += 2) {
                leastB = Math.min(leastB, piece[i] * nx + piece[i + 1] * ny);
            }
        }
        return leastB - reachA;
    }
}
