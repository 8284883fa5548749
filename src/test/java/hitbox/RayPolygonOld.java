package hitbox;

import hitbox.internal.*;

import java.util.Arrays;

/**
 * Ray.cast on a polygon as of commit 9c3ead8, the reference {@link RayConvexAgreementTest}
 * compares the convex clip with: every crossing of the outline sorted, and each stretch
 * between two asked of {@link Polygon#contains} at its middle.
 */
final class RayPolygonOld {
    private RayPolygonOld() {
    }

    static RayHit cast(Ray ray, Polygon p) {
        return new Cast(ray).castPolygon(p, RayCast.limit(ray.dx(), ray.dy(), ray.maxDistance()));
    }

    private static final class Cast {
        final float ox, oy, dx, dy;

        Cast(Ray r) {
            ox = r.ox();
            oy = r.oy();
            dx = r.dx();
            dy = r.dy();
        }

        RayHit castPolygon(Polygon p, double limit) {
            int n = p.size();
            double[] events = new double[2 * n];
            double[] alongFrom = new double[n], alongTo = new double[n];
            int count = 0, along = 0;
            boolean onOutline = false;
            for (int i = 0; i < n; i++) {
                int j = (i + 1) % n;
                double s = segmentParam(ox, oy, dx, dy, Slabs.INF, p.x(i), p.y(i), p.x(j), p.y(j));
                if (s == Slabs.INF) {
                    continue;
                }
                onOutline |= s == 0;
                events[count++] = s;
                double ex = (double) p.x(j) - p.x(i), ey = (double) p.y(j) - p.y(i);
                if (dx * ey - dy * ex == 0) {
                    double dd = (double) dx * dx + (double) dy * dy;
                    double si = (((double) p.x(i) - ox) * dx + ((double) p.y(i) - oy) * dy) / dd;
                    double sj = (((double) p.x(j) - ox) * dx + ((double) p.y(j) - oy) * dy) / dd;
                    events[count++] = Math.max(si, sj);
                    alongFrom[along] = s;
                    alongTo[along++] = Math.max(si, sj);
                }
            }
            if (!onOutline && p.contains(ox, oy)) {
                return hitAt(0, -dx, -dy);
            }
            Arrays.sort(events, 0, count);
            double scale = Math.max(1, Math.abs(events[Math.max(count - 1, 0)]));
            for (int k = 0; k + 1 < count; k++) {
                double s = events[k];
                if (!(s < limit)) {
                    break;
                }
                int next = k + 1;
                while (next < count && events[next] - s <= Ray.SAME_EVENT * scale) {
                    next++;
                }
                if (next == count) {
                    break;
                }
                double to = events[next];
                boolean onEdge = false;
                for (int a = 0; a < along && !onEdge; a++) {
                    onEdge = alongFrom[a] <= s && to <= alongTo[a];
                }
                double mid = (s + to) / 2;
                if (!onEdge && p.contains((float) (ox + mid * dx), (float) (oy + mid * dy))) {
                    double[] normal = polygonNormal(p, s, scale);
                    return hitAt(s, normal[0], normal[1]);
                }
                k = next - 1;
            }
            return null;
        }

        double[] polygonNormal(Polygon p, double s, double scale) {
            int n = p.size();
            int turn = Polygons.winding(p.raw());
            double sx = 0, sy = 0;
            for (int i = 0; i < n; i++) {
                int j = (i + 1) % n;
                double at = segmentParam(ox, oy, dx, dy, Slabs.INF, p.x(i), p.y(i), p.x(j), p.y(j));
                if (at != Slabs.INF && Math.abs(at - s) <= Ray.SAME_EVENT * scale) {
                    double[] out = Polygons.outwardNormal(p.raw(), i, turn);
                    if (out[0] * dx + out[1] * dy < 0) {
                        sx += out[0];
                        sy += out[1];
                    }
                }
            }
            return sx == 0 && sy == 0 ? new double[] {-dx, -dy} : new double[] {sx, sy};
        }

        RayHit hitAt(double s, double outX, double outY) {
            double len = Math.hypot(outX, outY);
            double length = Math.sqrt((double) dx * dx + (double) dy * dy);
            return new RayHit(Check.held(s * length), Check.held(ox + s * dx), Check.held(oy + s * dy),
                    (float) (-outX / len), (float) (-outY / len));
        }
    }

    static double segmentParam(float ox, float oy, float dx, float dy, double limit,
                               float x1, float y1, float x2, float y2) {
        double ex = (double) x2 - x1, ey = (double) y2 - y1;
        double wx = (double) x1 - ox, wy = (double) y1 - oy;
        double denom = dx * ey - dy * ex;
        double sNum = wx * ey - wy * ex;
        double uNum = wx * dy - wy * dx;
        if (denom != 0) {
            if (denom < 0) {
                denom = -denom;
                sNum = -sNum;
                uNum = -uNum;
            }
            if (!(sNum >= 0 && uNum >= 0 && uNum <= denom)) {
                return Slabs.INF;
            }
            double s = sNum / denom;
            return s <= limit ? s : Slabs.INF;
        }
        if (uNum != 0) {
            return Slabs.INF;
        }
        double dd = (double) dx * dx + (double) dy * dy;
        double s1 = (wx * dx + wy * dy) / dd;
        double s2 = (((double) x2 - ox) * dx + ((double) y2 - oy) * dy) / dd;
        double lo = Math.min(s1, s2), hi = Math.max(s1, s2);
        return hi >= 0 && lo <= limit ? Math.max(lo, 0) : Slabs.INF;
    }
}
