package hitbox;

import java.awt.geom.Area;
import java.awt.geom.Path2D;
import java.awt.geom.PathIterator;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Shared by the contact tests: shape generators for jqwik, and slow references that do not
 * use the code under test (java.awt.geom.Area for polygons, plain distance for circles).
 */
final class ContactFixtures {
    private ContactFixtures() {
    }

    /**
     * How far past (or short of) the depth the push-out tests move: moving b by depth + STEP
     * must separate, by depth - STEP must still overlap. Float rounding of coordinates up to
     * a few hundred is about 1e-5, far below this.
     */
    static final double STEP = 1e-3;

    /**
     * Intersection area below which two polygons count as touching. Rounding noise in the
     * area of two touching polygons with coordinates near 100 is about 1e-12; a corner pushed
     * in by d makes an area of order d^2, so the slow depth reference resolves d to ~1e-5.
     */
    static final double AREA_EPS = 1e-10;

    // ------------------------------------------------------------------------ references

    /** Do the shapes overlap? Collide for circle/rect pairs, Area or plain distance otherwise. */
    static boolean overlapsRef(Shape a, Shape b) {
        if (a instanceof Circle c && b instanceof Circle d) {
            return Collide.circleCircle(c.x(), c.y(), c.r(), d.x(), d.y(), d.r());
        }
        if (a instanceof Circle c && b instanceof Rect r) {
            return Collide.circleRect(c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h());
        }
        if (a instanceof Rect && b instanceof Circle) {
            return overlapsRef(b, a);
        }
        if (a instanceof Rect r && b instanceof Rect s) {
            return Collide.rectRect(r.x(), r.y(), r.w(), r.h(), s.x(), s.y(), s.w(), s.h());
        }
        if (a instanceof Circle c) {
            return circlePolygonRef(c, vertices(b));
        }
        if (b instanceof Circle c) {
            return circlePolygonRef(c, vertices(a));
        }
        if (a instanceof Rect r && (r.w() == 0 || r.h() == 0)) {
            return segmentPolygonRef(r.x(), r.y(), (double) r.x() + r.w(), (double) r.y() + r.h(), vertices(b));
        }
        if (b instanceof Rect r && (r.w() == 0 || r.h() == 0)) {
            return segmentPolygonRef(r.x(), r.y(), (double) r.x() + r.w(), (double) r.y() + r.h(), vertices(a));
        }
        double[] pa = vertices(a), pb = vertices(b);
        if (isConvexRef(pb)) {
            return clipArea(pa, pb) > AREA_EPS;
        }
        if (isConvexRef(pa)) {
            return clipArea(pb, pa) > AREA_EPS;
        }
        return intersectionArea(pa, pb) > AREA_EPS;
    }

    /** Is the polygon convex (no turn against the winding)? Plain double arithmetic. */
    static boolean isConvexRef(double[] p) {
        int n = p.length / 2;
        double area = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            area += p[2 * i] * p[2 * j + 1] - p[2 * j] * p[2 * i + 1];
        }
        for (int i = 0; i < n; i++) {
            int h = (i + n - 1) % n, j = (i + 1) % n;
            double turn = (p[2 * i] - p[2 * h]) * (p[2 * j + 1] - p[2 * h + 1]) - (p[2 * i + 1] - p[2 * h + 1]) * (p[2 * j] - p[2 * h]);
            if (turn * area < 0) {
                return false;
            }
        }
        return true;
    }

    /**
     * Area of polygon p (any simple polygon) clipped to convex polygon c: Sutherland-Hodgman.
     * Reference: I. Sutherland, G. Hodgman, "Reentrant polygon clipping", 1974.
     */
    static double clipArea(double[] p, double[] c) {
        int m = c.length / 2;
        double area = 0;
        for (int i = 0; i < m; i++) {
            int j = (i + 1) % m;
            area += c[2 * i] * c[2 * j + 1] - c[2 * j] * c[2 * i + 1];
        }
        double sign = Math.signum(area);
        List<double[]> poly = new ArrayList<>();
        for (int i = 0; i < p.length; i += 2) {
            poly.add(new double[] {p[i], p[i + 1]});
        }
        for (int i = 0; i < m && !poly.isEmpty(); i++) {
            int j = (i + 1) % m;
            double ax = c[2 * i], ay = c[2 * i + 1], bx = c[2 * j], by = c[2 * j + 1];
            List<double[]> out = new ArrayList<>();
            for (int k = 0; k < poly.size(); k++) {
                double[] u = poly.get(k), w = poly.get((k + 1) % poly.size());
                double su = sign * ((bx - ax) * (u[1] - ay) - (by - ay) * (u[0] - ax));
                double sw = sign * ((bx - ax) * (w[1] - ay) - (by - ay) * (w[0] - ax));
                if (su >= 0) {
                    out.add(u);
                }
                if ((su > 0 && sw < 0) || (su < 0 && sw > 0)) {
                    double t = su / (su - sw);
                    out.add(new double[] {u[0] + t * (w[0] - u[0]), u[1] + t * (w[1] - u[1])});
                }
            }
            poly = out;
        }
        double total = 0;
        for (int k = 0; k < poly.size(); k++) {
            double[] u = poly.get(k), w = poly.get((k + 1) % poly.size());
            total += u[0] * w[1] - w[0] * u[1];
        }
        return Math.abs(total) / 2;
    }

    /**
     * Does the segment reach strictly inside the polygon? It is cut wherever it meets an
     * edge, and the middle of each piece is tested.
     */
    static boolean segmentPolygonRef(double x0, double y0, double x1, double y1, double[] p) {
        double ex = x1 - x0, ey = y1 - y0;
        if (ex == 0 && ey == 0) {
            return insideRef(p, x0, y0);
        }
        List<Double> cuts = cuts(x0, y0, x1, y1, p);
        for (int k = 0; k + 1 < cuts.size(); k++) {
            double t = (cuts.get(k) + cuts.get(k + 1)) / 2;
            if (cuts.get(k + 1) - cuts.get(k) > 1e-12 && insideRef(p, x0 + t * ex, y0 + t * ey)) {
                return true;
            }
        }
        return false;
    }

    /** Parameters in [0, 1], sorted, where the segment meets the polygon's edges (and 0, 1). */
    static List<Double> cuts(double x0, double y0, double x1, double y1, double[] p) {
        double ex = x1 - x0, ey = y1 - y0;
        List<Double> cuts = new ArrayList<>(List.of(0.0, 1.0));
        int n = p.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ax = p[2 * i], ay = p[2 * i + 1], bx = p[2 * j], by = p[2 * j + 1];
            double fx = bx - ax, fy = by - ay;
            double den = ex * fy - ey * fx;
            // Where the segment's line meets the edge's ends, and where it crosses the edge.
            for (double[] q : new double[][] {{ax, ay}, {bx, by}}) {
                cuts.add(((q[0] - x0) * ex + (q[1] - y0) * ey) / (ex * ex + ey * ey));
            }
            if (den != 0) {
                cuts.add(((ax - x0) * fy - (ay - y0) * fx) / den);
            }
        }
        cuts.removeIf(t -> t < 0 || t > 1);
        cuts.sort(null);
        return cuts;
    }

    /** b moved by (dx, dy) in double, then rounded once to float. */
    static Shape moved(Shape b, double dx, double dy) {
        return b.translated((float) dx, (float) dy);
    }

    /**
     * The push-out property: moving b along the normal by depth + STEP separates the shapes,
     * by depth - STEP they still overlap (when the depth is larger than STEP).
     */
    static void assertPushOutTouches(Shape a, Shape b, Contact c) {
        assertNotNull(c, () -> a + " and " + b + " overlap but have no contact");
        double far = c.depth() + STEP;
        assertFalse(overlapsRef(a, moved(b, c.nx() * far, c.ny() * far)),
                () -> "moving " + b + " by depth + step along " + c + " should separate it from " + a);
        if (c.depth() > 2 * STEP) {
            double near = c.depth() - STEP;
            assertTrue(overlapsRef(a, moved(b, c.nx() * near, c.ny() * near)),
                    () -> "moving " + b + " by depth - step along " + c + " should leave it overlapping " + a);
        }
    }

    /**
     * How much a overlaps b, as a number that is 0 when they only touch: the intersection's
     * area for two polygons (rectangles with area included), the length inside for a flat
     * rectangle, the depth inside for a point, the penetration {@code r - dist} (or
     * {@code r + dist} from inside) for a circle.
     */
    static double overlapMeasure(Shape a, Shape b) {
        if (a instanceof Circle c && b instanceof Circle d) {
            return Math.max(0, (double) c.r() + d.r() - Math.hypot((double) d.x() - c.x(), (double) d.y() - c.y()));
        }
        if (b instanceof Circle) {
            return overlapMeasure(b, a);
        }
        if (a instanceof Circle c) {
            double[] p = vertices(b);
            double dist = boundaryDistance(p, c.x(), c.y());
            boolean flat = b instanceof Rect r && (r.w() == 0 || r.h() == 0);
            return !flat && insideRef(p, c.x(), c.y()) ? c.r() + dist : Math.max(0, c.r() - dist);
        }
        if (b instanceof Rect r && (r.w() == 0 || r.h() == 0)) {
            return insideLength(r.x(), r.y(), (double) r.x() + r.w(), (double) r.y() + r.h(), vertices(a));
        }
        if (a instanceof Rect r && (r.w() == 0 || r.h() == 0)) {
            return insideLength(r.x(), r.y(), (double) r.x() + r.w(), (double) r.y() + r.h(), vertices(b));
        }
        double[] pa = vertices(a), pb = vertices(b);
        if (isConvexRef(pb)) {
            return clipArea(pa, pb);
        }
        if (isConvexRef(pa)) {
            return clipArea(pb, pa);
        }
        return intersectionArea(pa, pb);
    }

    /** Length of the segment strictly inside the polygon; a point's distance inside. */
    static double insideLength(double x0, double y0, double x1, double y1, double[] p) {
        double ex = x1 - x0, ey = y1 - y0;
        if (ex == 0 && ey == 0) {
            return insideRef(p, x0, y0) ? boundaryDistance(p, x0, y0) : 0;
        }
        List<Double> cuts = cuts(x0, y0, x1, y1, p);
        double len = Math.hypot(ex, ey), total = 0;
        for (int k = 0; k + 1 < cuts.size(); k++) {
            double t = (cuts.get(k) + cuts.get(k + 1)) / 2;
            if (insideRef(p, x0 + t * ex, y0 + t * ey)) {
                total += (cuts.get(k + 1) - cuts.get(k)) * len;
            }
        }
        return total;
    }

    /**
     * How small the overlap may be after pushing out by exactly the depth: the move is
     * rounded to float, about 1e-5 at these coordinates, times a length of up to 100.
     */
    static final double FREE_MEASURE = 1e-3;

    /**
     * The push-out property for any shapes, convex or not: moving b along the normal by the
     * depth leaves (almost) no overlap, and by depth - STEP they still overlap. Concave shapes
     * can wedge: the nearest free position may be a single point (a segment that fits a
     * V-shaped notch exactly), so "a little further also separates" holds only for convex
     * pairs, which use {@link #assertPushOutTouches}.
     */
    static void assertPushOutFree(Shape a, Shape b, Contact c) {
        assertNotNull(c, () -> a + " and " + b + " overlap but have no contact");
        double measure = overlapMeasure(a, moved(b, c.nx() * (double) c.depth(), c.ny() * (double) c.depth()));
        assertTrue(measure <= FREE_MEASURE,
                () -> "moving " + b + " by the depth along " + c + " should clear " + a + ", but the overlap is " + measure);
        if (c.depth() > 2 * STEP) {
            double near = c.depth() - STEP;
            assertTrue(overlapsRef(a, moved(b, c.nx() * near, c.ny() * near)),
                    () -> "moving " + b + " by depth - step along " + c + " should leave it overlapping " + a);
        }
    }

    /**
     * Minimality, sampled: every move of b shorter than depth - STEP, in any of 72 directions,
     * leaves the shapes overlapping.
     */
    static void assertNoShorterMove(Shape a, Shape b, Contact c) {
        double reach = c.depth() - STEP;
        if (reach <= 0) {
            return;
        }
        for (int k = 0; k < 72; k++) {
            double t = Math.PI * 2 * k / 72;
            double dx = Math.cos(t) * reach, dy = Math.sin(t) * reach;
            assertTrue(overlapsRef(a, moved(b, dx, dy)),
                    () -> "a shorter move (" + dx + ", " + dy + ") separates " + a + " and " + b + ", but contact is " + c);
        }
    }

    /**
     * The minimum translation of b, found slowly: in each of 1440 directions, bisect for the
     * shortest move that separates the shapes (for convex shapes the overlapping moves along
     * a ray form one interval starting at 0, so bisection is valid). Convex pairs only.
     */
    static double slowDepth(Shape a, Shape b) {
        Rect ba = a.bounds(), bb = b.bounds();
        double hi = ba.w() + ba.h() + bb.w() + bb.h() + 1;
        double best = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 1440; k++) {
            double t = Math.PI * 2 * k / 1440;
            double ux = Math.cos(t), uy = Math.sin(t);
            double lo = 0, up = Math.min(hi, best);
            if (overlapsRef(a, moved(b, ux * up, uy * up))) {
                continue;
            }
            for (int i = 0; i < 40; i++) {
                double mid = (lo + up) / 2;
                if (overlapsRef(a, moved(b, ux * mid, uy * mid))) {
                    lo = mid;
                } else {
                    up = mid;
                }
            }
            best = Math.min(best, up);
        }
        return best;
    }

    /** contact(b, a) is contact(a, b) flipped, or both are null. */
    static void assertReversed(Contact ab, Contact ba) {
        if (ab == null) {
            assertEquals(null, ba);
            return;
        }
        assertNotNull(ba);
        assertEquals(ab.depth(), ba.depth(), 1e-5 * Math.max(1, ab.depth()), "depth");
        assertEquals(-ab.nx(), ba.nx(), 1e-6, "nx");
        assertEquals(-ab.ny(), ba.ny(), 1e-6, "ny");
    }

    /**
     * contact(b, a) against contact(a, b): the same depth, and the opposite normal unless the
     * two directions tie exactly (a symmetric placement, where the documented tie rule gives
     * the same normal in both orders). Such a tie is checked, not assumed: pushing b the
     * other way by the depth must separate the shapes too, by the push-out property that
     * holds for the pair: {@link #assertPushOutTouches} when both are convex, and
     * {@link #assertPushOutFree} when one is concave, since a concave shape can wedge: a
     * rectangle as wide as a comb's slot, pushed by the depth into the slot, is free there
     * but overlaps again a step further on (PolygonContactTest keeps that case).
     */
    static void assertReversedOrSymmetricTie(Shape a, Shape b, Contact ab, Contact ba) {
        if (ab == null || ba == null || Math.abs(ab.nx() + ba.nx()) < 1e-6 && Math.abs(ab.ny() + ba.ny()) < 1e-6) {
            assertReversed(ab, ba);
            return;
        }
        assertEquals(ab.depth(), ba.depth(), 1e-5 * Math.max(1, ab.depth()), "depth");
        assertEquals(ab.nx(), ba.nx(), 1e-6, "not opposite, so the same (a tie)");
        assertEquals(ab.ny(), ba.ny(), 1e-6, "not opposite, so the same (a tie)");
        Contact reversed = new Contact(-ab.nx(), -ab.ny(), ab.depth());
        if (convex(a) && convex(b)) {
            assertPushOutTouches(a, b, reversed);
        } else {
            assertPushOutFree(a, b, reversed);
        }
    }

    /** Is the shape convex (every shape with area but a concave polygon)? */
    static boolean convex(Shape s) {
        return !(s instanceof Polygon p) || p.isConvex();
    }

    static void assertUnit(Contact c) {
        assertEquals(1.0, Math.hypot(c.nx(), c.ny()), 1e-6, () -> "normal of " + c);
    }

    /** Circle against a polygon (vertex list), by centre distance to the outline and inside test. */
    static boolean circlePolygonRef(Circle c, double[] p) {
        double d = boundaryDistance(p, c.x(), c.y());
        if (insideRef(p, c.x(), c.y())) {
            return true;
        }
        return d < c.r();
    }

    static double boundaryDistance(double[] p, double x, double y) {
        double best = Double.POSITIVE_INFINITY;
        int n = p.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ax = p[2 * i], ay = p[2 * i + 1], bx = p[2 * j], by = p[2 * j + 1];
            double ex = bx - ax, ey = by - ay;
            double len2 = ex * ex + ey * ey;
            double dot = (x - ax) * ex + (y - ay) * ey;
            // The distance to the line from the cross product, exact for whole numbers, so a
            // point on an edge is at distance 0, not at a rounded foot point's 1e-15.
            double d = len2 == 0 || dot <= 0 ? Math.hypot(x - ax, y - ay)
                    : dot >= len2 ? Math.hypot(x - bx, y - by)
                    : Math.abs(ex * (y - ay) - ey * (x - ax)) / Math.sqrt(len2);
            best = Math.min(best, d);
        }
        return best;
    }

    /** Winding-number point in polygon (strict when the point is not on the outline). */
    static boolean insideRef(double[] p, double x, double y) {
        Path2D.Double path = path(p);
        return path.contains(x, y) && boundaryDistance(p, x, y) > 0;
    }

    /** Area of the intersection of two simple polygons, through java.awt.geom.Area. */
    static double intersectionArea(double[] a, double[] b) {
        Area area = new Area(path(a));
        area.intersect(new Area(path(b)));
        double total = 0;
        double[] seg = new double[6];
        double sx = 0, sy = 0, px = 0, py = 0;
        for (PathIterator it = area.getPathIterator(null); !it.isDone(); it.next()) {
            int type = it.currentSegment(seg);
            if (type == PathIterator.SEG_MOVETO) {
                sx = px = seg[0];
                sy = py = seg[1];
            } else if (type == PathIterator.SEG_LINETO) {
                total += px * seg[1] - seg[0] * py;
                px = seg[0];
                py = seg[1];
            } else if (type == PathIterator.SEG_CLOSE) {
                total += px * sy - sx * py;
                px = sx;
                py = sy;
            } else {
                throw new AssertionError("curves in a polygon intersection");
            }
        }
        return Math.abs(total) / 2;
    }

    static Path2D.Double path(double[] p) {
        Path2D.Double path = new Path2D.Double(Path2D.WIND_NON_ZERO);
        path.moveTo(p[0], p[1]);
        for (int i = 2; i < p.length; i += 2) {
            path.lineTo(p[i], p[i + 1]);
        }
        path.closePath();
        return path;
    }

    /** A rectangle's or polygon's vertices in double. */
    static double[] vertices(Shape s) {
        if (s instanceof Rect r) {
            double x = r.x(), y = r.y(), right = x + r.w(), bottom = y + r.h();
            return new double[] {x, y, right, y, right, bottom, x, bottom};
        }
        Polygon p = (Polygon) s;
        double[] d = new double[2 * p.size()];
        for (int i = 0; i < p.size(); i++) {
            d[2 * i] = p.x(i);
            d[2 * i + 1] = p.y(i);
        }
        return d;
    }

    // ------------------------------------------------------------------------ shapes

    /**
     * Rotated rectangles, as the library turns them ({@code Polygon.of(rect).rotated} about
     * the centre): whole-number centre and size, angle in tenths of a degree.
     */
    static Arbitrary<Polygon> rotatedRects() {
        return Combinators.combine(
                Arbitraries.integers().between(-20, 20),
                Arbitraries.integers().between(-20, 20),
                Arbitraries.integers().between(1, 40),
                Arbitraries.integers().between(1, 40),
                Arbitraries.integers().between(0, 3599))
            .as((cx, cy, w, h, tenths) -> Polygon.of(Rect.centered(cx, cy, w, h)).rotated((float) Math.toRadians(tenths / 10.0), cx, cy));
    }

    /** Concave shapes with whole-number corners, each drawn in a 0..6 box. */
    static final float[][] CONCAVE = {
        {0, 0, 6, 0, 6, 2, 2, 2, 2, 6, 0, 6},                   // L
        {0, 0, 2, 0, 2, 4, 4, 4, 4, 0, 6, 0, 6, 6, 0, 6},       // U (pocket open upwards)
        {0, 0, 6, 0, 6, 2, 4, 2, 4, 6, 2, 6, 2, 2, 0, 2},       // T
        {3, 0, 4, 2, 6, 3, 4, 4, 3, 6, 2, 4, 0, 3, 2, 2},       // four-point star
        {0, 0, 6, 3, 0, 6, 2, 3},                               // arrow head (dart)
        {0, 0, 1, 0, 1, 4, 2, 4, 2, 0, 3, 0, 3, 4, 4, 4, 4, 0, 5, 0, 5, 6, 0, 6}, // comb
        {0, 0, 2, 0, 3, 2, 4, 0, 6, 0, 6, 6, 4, 6, 3, 4, 2, 6, 0, 6}, // bow tie with notches
    };

    /** One of the concave shapes, scaled by 1..10, maybe mirrored, turned by a quarter turn, moved. */
    static Arbitrary<Polygon> concavePolygons() {
        return Combinators.combine(
                Arbitraries.integers().between(0, CONCAVE.length - 1),
                Arbitraries.integers().between(1, 10),
                Arbitraries.integers().between(0, 7),
                Arbitraries.integers().between(-30, 30),
                Arbitraries.integers().between(-30, 30))
            .as((k, scale, turn, dx, dy) -> {
                float[] base = CONCAVE[k];
                float[] xy = new float[base.length];
                for (int i = 0; i < base.length; i += 2) {
                    float x = base[i] * scale, y = base[i + 1] * scale;
                    if ((turn & 4) != 0) {
                        x = -x;
                    }
                    for (int q = 0; q < (turn & 3); q++) {
                        float t = x;
                        x = -y;
                        y = t;
                    }
                    xy[i] = x + dx;
                    xy[i + 1] = y + dy;
                }
                return Polygon.of(xy);
            });
    }

    /** Random convex polygons with whole-number corners: the hull of 3 to 8 points. */
    static Arbitrary<Polygon> convexPolygons() {
        return Arbitraries.integers().between(-40, 40).list().ofMinSize(6).ofMaxSize(16)
            .map(ContactFixtures::hullOrNull)
            .filter(p -> p != null);
    }

    /** Random star-shaped (mostly concave) polygons with whole-number corners, kept only if simple. */
    static Arbitrary<Polygon> starPolygons() {
        return Combinators.combine(
                Arbitraries.integers().between(5, 11),
                Arbitraries.integers().between(3, 40).list().ofSize(11),
                Arbitraries.integers().between(-30, 30),
                Arbitraries.integers().between(-30, 30))
            .as((n, radii, cx, cy) -> {
                float[] xy = new float[2 * n];
                for (int i = 0; i < n; i++) {
                    double t = Math.PI * 2 * i / n;
                    xy[2 * i] = cx + Math.round(Math.cos(t) * radii.get(i));
                    xy[2 * i + 1] = cy + Math.round(Math.sin(t) * radii.get(i));
                }
                return isSimple(xy) ? Polygon.of(xy) : null;
            })
            .filter(p -> p != null);
    }

    // Positions span less than the sizes, so that about half of the random pairs overlap.

    static Arbitrary<Circle> circles() {
        return Combinators.combine(
                Arbitraries.integers().between(-30, 30),
                Arbitraries.integers().between(-30, 30),
                Arbitraries.integers().between(0, 30))
            .as((x, y, r) -> new Circle(x, y, r));
    }

    static Arbitrary<Rect> rects() {
        return Combinators.combine(
                Arbitraries.integers().between(-40, 20),
                Arbitraries.integers().between(-40, 20),
                Arbitraries.integers().between(0, 50),
                Arbitraries.integers().between(0, 50))
            .as((x, y, w, h) -> new Rect(x, y, w, h));
    }

    /** Rectangles with area: the kind a Polygon can also be. */
    static Arbitrary<Rect> solidRects() {
        return Combinators.combine(
                Arbitraries.integers().between(-40, 20),
                Arbitraries.integers().between(-40, 20),
                Arbitraries.integers().between(1, 50),
                Arbitraries.integers().between(1, 50))
            .as((x, y, w, h) -> new Rect(x, y, w, h));
    }

    /** Convex hull (monotone chain, exact in long) of the points listed as x, y, ...; null if flat. */
    static Polygon hullOrNull(List<Integer> coords) {
        int n = coords.size() / 2;
        long[][] pts = new long[n][];
        for (int i = 0; i < n; i++) {
            pts[i] = new long[] {coords.get(2 * i), coords.get(2 * i + 1)};
        }
        Arrays.sort(pts, (p, q) -> p[0] != q[0] ? Long.compare(p[0], q[0]) : Long.compare(p[1], q[1]));
        List<long[]> h = new ArrayList<>();
        for (int pass = 0; pass < 2; pass++) {
            int start = h.size();
            for (int s = 0; s < n; s++) {
                long[] p = pass == 0 ? pts[s] : pts[n - 1 - s];
                while (h.size() - start >= 2 && cross(h.get(h.size() - 2), h.get(h.size() - 1), p) <= 0) {
                    h.remove(h.size() - 1);
                }
                h.add(p);
            }
            h.remove(h.size() - 1);
        }
        if (h.size() < 3) {
            return null;
        }
        float[] xy = new float[2 * h.size()];
        for (int i = 0; i < h.size(); i++) {
            xy[2 * i] = h.get(i)[0];
            xy[2 * i + 1] = h.get(i)[1];
        }
        return Polygon.of(xy);
    }

    private static long cross(long[] a, long[] b, long[] c) {
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    }

    /** Simple polygon check for whole-number corners: no two non-adjacent edges meet, no adjacent edges fold back. */
    static boolean isSimple(float[] xy) {
        int n = xy.length / 2;
        long[][] p = new long[n][];
        for (int i = 0; i < n; i++) {
            p[i] = new long[] {(long) xy[2 * i], (long) xy[2 * i + 1]};
        }
        for (int i = 0; i < n; i++) {
            long[] a = p[i], b = p[(i + 1) % n];
            if (a[0] == b[0] && a[1] == b[1]) {
                return false;
            }
            for (int j = i + 1; j < n; j++) {
                long[] c = p[j], d = p[(j + 1) % n];
                boolean adjacent = j == i + 1 || (i == 0 && j == n - 1);
                if (adjacent) {
                    // Sharing one end: they must not overlap along a line.
                    long[] shared = j == i + 1 ? b : a;
                    long[] u = j == i + 1 ? a : b;
                    long[] w = j == i + 1 ? d : c;
                    if (cross(shared, u, w) == 0
                            && (u[0] - shared[0]) * (w[0] - shared[0]) + (u[1] - shared[1]) * (w[1] - shared[1]) > 0) {
                        return false;
                    }
                } else if (segmentsMeet(a, b, c, d)) {
                    return false;
                }
            }
        }
        double area = 0;
        for (int i = 0; i < n; i++) {
            area += (double) p[i][0] * p[(i + 1) % n][1] - (double) p[(i + 1) % n][0] * p[i][1];
        }
        return area != 0;
    }

    private static boolean segmentsMeet(long[] a, long[] b, long[] c, long[] d) {
        long d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
        if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
            return true;
        }
        return (d1 == 0 && onSegment(c, d, a)) || (d2 == 0 && onSegment(c, d, b))
                || (d3 == 0 && onSegment(a, b, c)) || (d4 == 0 && onSegment(a, b, d));
    }

    private static boolean onSegment(long[] a, long[] b, long[] p) {
        return Math.min(a[0], b[0]) <= p[0] && p[0] <= Math.max(a[0], b[0])
                && Math.min(a[1], b[1]) <= p[1] && p[1] <= Math.max(a[1], b[1]);
    }
}
