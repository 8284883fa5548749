package hitbox;

import hitbox.internal.*;

import java.util.List;

/**
 * TurningSweep as of commit 7d4f079, the reference TurningSweepAgreementTest compares with.
 *
 * <p>The time of impact of a convex polygon that moves and turns during the frame
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
 */
final class TurningSweepOld {
    private TurningSweepOld() {
    }

    /** Closer than this (pixels) counts as touching: the hit. */
    static final double TOUCH = 1e-3;
    private static final int MAX_STEPS = 2000;
    private static final int DIRECTIONS = 32;

    /** The mover's vertices at time t: turned by t * turn about the pivot, then moved by t * v. */
    static double[] at(float[] xy, double px, double py, double vx, double vy, double turn, double t) {
        double c = Math.cos(t * turn), s = Math.sin(t * turn);
        double[] out = new double[xy.length];
        for (int i = 0; i + 1 < xy.length; i += 2) {
            double x = xy[i] - px, y = xy[i + 1] - py;
            out[i] = px + t * vx + c * x - s * y;
            out[i + 1] = py + t * vy + s * x + c * y;
        }
        return out;
    }

    static Hit timeOfImpact(Polygon mover, float px, float py, float vx, float vy, float turn, Shape obstacle) {
        float[] xy = mover.raw();
        if (Overlaps.test(mover, obstacle)) {
            return SweptPairs.OVERLAPPING;
        }
        double reach = 0;
        for (int i = 0; i < xy.length; i += 2) {
            reach = Math.max(reach, Math.hypot(xy[i] - px, xy[i + 1] - py));
        }
        double speed = Math.hypot(vx, vy) + Math.abs(turn) * reach;
        List<double[]> pieces = pieces(obstacle);
        double t = 0;
        double[] normal = new double[2];
        for (int step = 0; step < MAX_STEPS; step++) {
            double gap = gap(xy, px, py, vx, vy, turn, t, pieces, obstacle, normal);
            if (speed == 0) {
                return null;
            }
            if (gap <= TOUCH) {
                // Touching: a hit if the mover is closing in, not if it is leaving (a blade
                // turning back from the post it just touched). One TOUCH of motion on, the
                // gap tells which.
                double later = t + TOUCH / speed;
                if (later > 1 || gap(xy, px, py, vx, vy, turn, later, pieces, obstacle, new double[2]) <= gap) {
                    return SweptPairs.hit((float) t, normal[0], normal[1]);
                }
                t = later;
                continue;
            }
            // Advance by most of the safe step, so the gap shrinks towards TOUCH and never past 0.
            t += (gap - TOUCH / 2) / speed;
            if (t > 1) {
                return null;
            }
        }
        return SweptPairs.hit((float) t, normal[0], normal[1]);
    }

    /** The least gap at time t over the obstacle's pieces; its direction into {@code normal}. */
    private static double gap(float[] xy, float px, float py, float vx, float vy, float turn, double t,
                              List<double[]> pieces, Shape obstacle, double[] normal) {
        double[] a = at(xy, px, py, vx, vy, turn, t);
        double gap = Double.POSITIVE_INFINITY;
        for (double[] piece : pieces) {
            gap = Math.min(gap, gap(a, piece, obstacle, normal, gap));
        }
        return gap;
    }

    /** The obstacle as convex vertex lists; circles, ellipses and capsules are one piece, kept as the shape. */
    private static List<double[]> pieces(Shape s) {
        if (s instanceof Polygon p && !p.isConvex()) {
            return Clearance.Parts.of(s).pieces();
        }
        if (s instanceof Segment g) {
            return List.of(new double[] {g.x1(), g.y1(), g.x2(), g.y2()});
        }
        if (s instanceof Rect || s instanceof Polygon) {
            return List.of(Polygons.corners(s));
        }
        return List.of(new double[0]);
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
                if (separation(a, piece, obstacle, Math.cos(m1), Math.sin(m1)) > separation(a, piece, obstacle, Math.cos(m2), Math.sin(m2))) {
                    hi = m2;
                } else {
                    lo = m1;
                }
            }
            double m = (lo + hi) / 2, gm = separation(a, piece, obstacle, Math.cos(m), Math.sin(m));
            if (gm > bestGap) {
                bestGap = gm;
                bx = Math.cos(m);
                by = Math.sin(m);
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
            d[2 * i] = Math.cos(2 * Math.PI * i / DIRECTIONS);
            d[2 * i + 1] = Math.sin(2 * Math.PI * i / DIRECTIONS);
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
