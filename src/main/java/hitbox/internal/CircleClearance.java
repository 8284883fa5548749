package hitbox.internal;

import hitbox.*;

import java.util.ArrayList;
import java.util.List;

/**
 * The shortest move that clears a concave polygon for a circle: {@link Clearance}'s search
 * in translation space, with round pieces. The centre must end at least r from the polygon,
 * so the outline of the set of moves that overlap is made of the polygon's edges pushed out
 * by r and circles of radius r around its corners; the candidates are the points of those
 * pieces nearest the origin, their ends, and where two pieces cross, and a candidate counts
 * when the circle moved there overlaps the polygon by no more than the tolerance.
 */
public final class CircleClearance {
    private CircleClearance() {
    }

    /**
     * A circle (first) of radius r &gt; 0 against a polygon (second) that it overlaps: the
     * shortest move of the centre to a point at least r from the polygon. Normal from the
     * circle to the polygon, or (flip) from the polygon to the circle, the tie rule applied
     * to the normal as reported.
     */
    public static Contact circle(float cx, float cy, float r, float[] xy, boolean flip) {
        int n = xy.length / 2;
        // Everything relative to the centre: the no-move point is the origin.
        double[] p = new double[xy.length];
        double extent = r;
        for (int i = 0; i < n; i++) {
            p[2 * i] = (double) xy[2 * i] - cx;
            p[2 * i + 1] = (double) xy[2 * i + 1] - cy;
            extent = Math.max(extent, Math.max(Math.abs(p[2 * i]), Math.abs(p[2 * i + 1])));
        }
        double tol = Clearance.TOLERANCE * (1 + extent);
        double turn = Polygons.winding(xy);

        // The outline's pieces: each edge pushed out by r (x0, y0, x1, y1, nx, ny), and a
        // circle of radius r around each corner.
        List<double[]> offsets = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ex = p[2 * j] - p[2 * i], ey = p[2 * j + 1] - p[2 * i + 1];
            double len = Clearance.length(ex, ey);
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
            double d = Clearance.length(vx, vy);
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
            offsetNear[i] = Clearance.segmentDistance(o[0], o[1], o[2], o[3]);
        }
        double[] circleNear = new double[n];
        for (int v = 0; v < n; v++) {
            circleNear[v] = Clearance.length(p[2 * v], p[2 * v + 1]) - r;
        }
        for (int i = 0; i < offsets.size(); i++) {
            if (best.beyond(offsetNear[i])) {
                continue;
            }
            double[] o = offsets.get(i);
            for (int j = i + 1; j < offsets.size(); j++) {
                if (!best.beyond(offsetNear[j])) {
                    double[] c = Clearance.segmentCrossing(o, offsets.get(j));
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
        double d = Clearance.length(qx, qy);
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
            if (Clearance.segmentDistance(p[2 * i] - qx, p[2 * i + 1] - qy, p[2 * j] - qx, p[2 * j + 1] - qy)
                    < disc.r() - disc.tol()) {
                return true;
            }
        }
        return false;
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
        double d = Clearance.length(dx, dy);
        if (d == 0 || d > 2 * r) {
            return new double[0][];
        }
        double h = Math.sqrt(Math.max(0, r * r - d * d / 4));
        double mx = (ax + bx) / 2, my = (ay + by) / 2;
        double px = -dy / d * h, py = dx / d * h;
        return new double[][] {{mx + px, my + py}, {mx - px, my - py}};
    }

}
