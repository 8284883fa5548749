package hitbox.internal;

import hitbox.*;

import java.util.List;

/**
 * The contact of a curved shape ({@link Ellipse}, {@link Capsule}) with a concave polygon:
 * the shortest push that clears the whole polygon, not just its nearest convex piece (pushing
 * out of one piece can land the shape in another).
 *
 * <p>The translations of the curved shape K that overlap the polygon are the union of the
 * regions {@code C_i (+) -K} over the polygon's convex pieces C_i. Along a direction n, each
 * region is an open interval of push lengths (lo_i, hi_i); the shortest push along n that
 * clears them all, f(n), is the least d &gt;= 0 in no interval. The shortest push overall is
 * the least f(n) over n: the union's boundary point nearest the origin is reached along a
 * straight push that stays inside the union. Each interval end is the entry time of the
 * shape moving along the line towards the piece ({@link ConvexSweep#entry}, never late, so a
 * push is never short); f is sampled at 48 directions and at every edge normal of the
 * pieces, and its local least values refined by golden-section search. The depth is found to
 * about 1e-6 pixels (the entries' tolerance) where the least is smooth; a least value in a
 * gap narrower than the sampling between directions can be missed, giving a longer push that
 * still clears. Costs a few thousand support evaluations per direction: a rare pair.
 */
public final class CurvedClearance {
    private CurvedClearance() {
    }

    private static final int STEPS = 48;

    /**
     * The contact of curved k and concave polygon p (they overlap); normal from the first
     * shape to the second: from k to p unless {@code polygonFirst}.
     */
    public static Contact contact(Shape k, Polygon p, boolean polygonFirst) {
        List<Object> pieces = ConvexSweep.pieces(p);
        Object round = ConvexSweep.pieces(k).get(0);
        Rect a = k.bounds(), b = p.bounds();
        // Farther than any push can need: both boxes' sizes and the gap between them.
        double far = 2 * (Math.max(a.w(), a.h()) + Math.max(b.w(), b.h()))
                + Math.hypot((double) a.x() - b.x(), (double) a.y() - b.y()) + 1;
        double bestD = Double.POSITIVE_INFINITY, bestAngle = 0;
        double[] f = new double[STEPS];
        for (int i = 0; i < STEPS; i++) {
            f[i] = push(round, pieces, 2 * Math.PI * i / STEPS, far);
        }
        for (int i = 0; i < STEPS; i++) {
            double prev = f[(i + STEPS - 1) % STEPS], next = f[(i + 1) % STEPS];
            if (f[i] <= prev && f[i] <= next) {
                double[] r = refine(round, pieces, 2 * Math.PI * (i - 1) / STEPS, 2 * Math.PI * (i + 1) / STEPS, far);
                if (r[1] < bestD) {
                    bestD = r[1];
                    bestAngle = r[0];
                }
            }
            if (f[i] < bestD) {
                bestD = f[i];
                bestAngle = 2 * Math.PI * i / STEPS;
            }
        }
        for (Object piece : pieces) {
            double[] xy = (double[]) piece;
            int n = xy.length / 2;
            for (int i = 0; i < n; i++) {
                int j = (i + 1) % n;
                double ex = xy[2 * j] - xy[2 * i], ey = xy[2 * j + 1] - xy[2 * i + 1];
                for (double angle : new double[] {Math.atan2(ex, -ey), Math.atan2(-ex, ey)}) {
                    double d = push(round, pieces, angle, far);
                    if (d < bestD) {
                        bestD = d;
                        bestAngle = angle;
                    }
                }
            }
        }
        double nx = Math.cos(bestAngle), ny = Math.sin(bestAngle);
        // The push moves k along n: k is the second shape, or the normal turns round.
        double sign = polygonFirst ? 1 : -1;
        return Contacts.of(sign * nx, sign * ny, bestD);
    }

    /** f at the angle: the shortest push of k along it that clears every piece. */
    private static double push(Object k, List<Object> pieces, double angle, double far) {
        double nx = Math.cos(angle), ny = Math.sin(angle);
        double[] lo = new double[pieces.size()], hi = new double[pieces.size()];
        double[] normal = new double[2];
        for (int i = 0; i < pieces.size(); i++) {
            Object c = pieces.get(i);
            // Coming back from far along n: hi (entered at time te of the way back).
            double te = ConvexSweep.entry(k, c, far * nx, far * ny, -far * nx, -far * ny, normal);
            if (te > 1) {
                lo[i] = hi[i] = Double.NEGATIVE_INFINITY; // the line misses the piece
                continue;
            }
            hi[i] = far * (1 - te);
            if (hi[i] <= 0) {
                lo[i] = hi[i]; // wholly behind the start: no push along n meets it
                continue;
            }
            double ts = ConvexSweep.entry(k, c, -far * nx, -far * ny, far * nx, far * ny, normal);
            lo[i] = -far + (ts > 1 ? far : far * ts);
        }
        double d = 0;
        for (boolean moved = true; moved; ) {
            moved = false;
            for (int i = 0; i < lo.length; i++) {
                if (lo[i] < d && d < hi[i]) {
                    d = hi[i];
                    moved = true;
                }
            }
        }
        return d;
    }

    /** Golden-section search for the least f in [lo, hi]: {angle, f}. */
    private static double[] refine(Object k, List<Object> pieces, double lo, double hi, double far) {
        return Golden.least(t -> push(k, pieces, t, far), lo, hi, 32, Tolerance.CLEARANCE_ANGLE);
    }
}
