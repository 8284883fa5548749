package hitbox;

import hitbox.internal.Extents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import hitbox.ExactReference.Q;
import java.math.BigInteger;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.operation.distance.DistanceOp;

/**
 * {@link Separation} against oracles that share no code with it: JTS's {@code DistanceOp}
 * (LocationTech's Java Topology Suite 1.20) for the straight and round kinds, exact rational
 * arithmetic ({@link ExactReference.Q}) for whole-number cases, and for ellipses JTS's
 * distances of polygons inside and around them (a bracket) and dense sampling of the outline. Every pair is checked in both orders, with the closest points on the
 * outlines and as far apart as the distance says.
 *
 * <p>A shape is a core (a point, a segment, an outline) and a radius, as JTS sees it: a circle
 * is its centre, a capsule its segment, a rectangle or polygon its polygon. For shapes that do
 * not overlap, the distance is JTS's distance between the cores less the radii, held at 0.
 */
class SeparationOracleTest {

    private static final GeometryFactory GF = JtsShapes.GF;

    // ---------------------------------------------------------------- random shapes

    /** A random shape of kind k (0 circle, 1 rect, 2 segment, 3 convex polygon, 4 concave polygon, 5 capsule, 6 ellipse) near (cx, cy). */
    static Shape random(SplittableRandom rnd, int k, double cx, double cy, boolean whole) {
        java.util.function.DoubleUnaryOperator f = v -> whole ? Math.round(v) : (float) v;
        float x = (float) f.applyAsDouble(cx + rnd.nextDouble(-20, 20)), y = (float) f.applyAsDouble(cy + rnd.nextDouble(-20, 20));
        float s = (float) f.applyAsDouble(rnd.nextDouble(0, 30)), t = (float) f.applyAsDouble(rnd.nextDouble(0, 30));
        if (rnd.nextInt(12) == 0) {
            s = 0; // zero-size now and then
        }
        return switch (k) {
            case 0 -> new Circle(x, y, s);
            case 1 -> new Rect(x, y, s, t);
            case 2 -> new Segment(x, y, (float) f.applyAsDouble(x + rnd.nextDouble(-30, 30)), (float) f.applyAsDouble(y + rnd.nextDouble(-30, 30)));
            case 3 -> TestShapes.convexRing(rnd, 3 + rnd.nextInt(6), x, y, whole);
            case 4 -> TestShapes.starRing(rnd, 4 + rnd.nextInt(8), x, y, whole);
            case 5 -> new Capsule(x, y, (float) f.applyAsDouble(x + rnd.nextDouble(-30, 30)), (float) f.applyAsDouble(y + rnd.nextDouble(-30, 30)),
                    (float) f.applyAsDouble(rnd.nextDouble(0, 10)));
            // radii from 0.5 to 100, so that some are long and thin (several local least
            // distances around the outline)
            default -> new Ellipse(x, y, (float) Math.exp(rnd.nextDouble(-0.7, 4.6)), (float) Math.exp(rnd.nextDouble(-0.7, 4.6)),
                    rnd.nextBoolean() ? 0 : (float) rnd.nextDouble(-3, 3));
        };
    }

    // ---------------------------------------------------------------- JTS's view

    // ---------------------------------------------------------------- on the outline

    /** The distance from (px, py) to the shape's outline (a segment: to the segment), by the test's own sums. */
    static double toOutline(Shape s, double px, double py) {
        if (s instanceof Circle c) {
            return Math.abs(Math.hypot(px - c.x(), py - c.y()) - c.r());
        }
        if (s instanceof Capsule k) {
            return Math.abs(toSegment(px, py, k.x1(), k.y1(), k.x2(), k.y2()) - k.r());
        }
        if (s instanceof Segment g) {
            return toSegment(px, py, g.x1(), g.y1(), g.x2(), g.y2());
        }
        if (s instanceof Ellipse e) {
            double c = Math.cos(e.angle()), sn = Math.sin(e.angle());
            double dx = px - e.x(), dy = py - e.y(), u = dx * c + dy * sn, v = -dx * sn + dy * c;
            if (e.rx() == e.ry()) {
                return Math.abs(Math.hypot(dx, dy) - e.rx());
            }
            if (e.rx() == 0 || e.ry() == 0) {
                double hx = e.rx() * c - e.ry() * sn, hy = e.rx() * sn + e.ry() * c;
                return toSegment(px, py, e.x() - hx, e.y() - hy, e.x() + hx, e.y() + hy);
            }
            // The implicit function's value over its gradient: the distance to first order.
            double g = u * u / (e.rx() * (double) e.rx()) + v * v / (e.ry() * (double) e.ry()) - 1;
            double gu = 2 * u / (e.rx() * (double) e.rx()), gv = 2 * v / (e.ry() * (double) e.ry());
            return Math.abs(g) / Math.max(1e-300, Math.hypot(gu, gv));
        }
        float[] xy = s instanceof Rect r ? ExactReference.rectPolygon(r.x(), r.y(), r.w(), r.h()) : ((Polygon) s).coordinates();
        int n = xy.length / 2;
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            best = Math.min(best, toSegment(px, py, xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1]));
        }
        return best;
    }

    static double toSegment(double px, double py, double ax, double ay, double bx, double by) {
        double ex = bx - ax, ey = by - ay, len2 = ex * ex + ey * ey;
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((px - ax) * ex + (py - ay) * ey) / len2));
        return Math.hypot(px - (ax + t * ex), py - (ay + t * ey));
    }

    /** The size of the pair: the largest extent from the origin, for relative tolerances. */
    static double scale(Shape a, Shape b) {
        double m = 1;
        for (Shape s : new Shape[] {a, b}) {
            m = Math.max(m, Math.max(Math.max(Math.abs(Extents.minX(s)), Math.abs(Extents.maxX(s))), Math.max(Math.abs(Extents.minY(s)), Math.abs(Extents.maxY(s)))));
        }
        return m;
    }

    /**
     * The checks every separation passes whatever the oracle: null exactly when the shapes
     * overlap, the same distance both ways round with the points swapped, each point on its
     * shape's outline and the two as far apart as the distance, within {@code tol}.
     */
    static void checkShape(Shape a, Shape b, double tol) {
        Separation s = Separation.between(a, b), back = Separation.between(b, a);
        if (a.overlaps(b)) {
            assertNull(s, a + " " + b);
            assertNull(back, b + " " + a);
            return;
        }
        assertNotNull(s, a + " " + b);
        assertNotNull(back, b + " " + a);
        String what = a + " and " + b + ": " + s + ", back " + back;
        assertTrue(s.distance() >= 0);
        assertEquals(s.distance(), back.distance(), tol, "both ways round, " + what);
        for (Separation t : new Separation[] {s, back.flipped()}) {
            assertTrue(toOutline(a, t.ax(), t.ay()) <= tol, "a's point off its outline by " + toOutline(a, t.ax(), t.ay()) + ", " + what);
            assertTrue(toOutline(b, t.bx(), t.by()) <= tol, "b's point off its outline by " + toOutline(b, t.bx(), t.by()) + ", " + what);
            assertEquals(t.distance(), Math.hypot((double) t.bx() - t.ax(), (double) t.by() - t.ay()), tol, "|b - a|, " + what);
        }
    }

    // ---------------------------------------------------------------- JTS

    @Test
    void straightAndRoundKinds_agreeWithJtsDistanceOp_bothOrders() {
        SplittableRandom rnd = new SplittableRandom(23);
        int pairs = 0, apart = 0, agreed = 0, exactlyEqual = 0;
        double worstUlps = 0;
        List<String> wrong = new ArrayList<>();
        for (int n = 0; n < 2000; n++) {
            int ka = rnd.nextInt(6), kb = rnd.nextInt(6);
            double gap = rnd.nextDouble(0, 60);
            Shape a = random(rnd, ka, 0, 0, false), b = random(rnd, kb, gap, rnd.nextDouble(-30, 30), false);
            pairs++;
            double oracle = Math.max(0, DistanceOp.distance(JtsShapes.core(a), JtsShapes.core(b)) - JtsShapes.radius(a) - JtsShapes.radius(b));
            double tol = Math.ulp((float) oracle) + 1e-12 * scale(a, b);
            checkShape(a, b, 1e-5 * scale(a, b));
            for (Separation s : new Separation[] {Separation.between(a, b), Separation.between(b, a)}) {
                if (s == null) {
                    if (oracle > 1e-9 * scale(a, b)) {
                        wrong.add("null, but JTS says apart by " + oracle + ": " + a + " " + b);
                    }
                    continue;
                }
                apart++;
                double err = Math.abs(s.distance() - oracle);
                worstUlps = Math.max(worstUlps, err / Math.ulp((float) Math.max(oracle, Float.MIN_NORMAL)));
                if (err <= tol) {
                    agreed++;
                } else {
                    wrong.add(s.distance() + " vs JTS " + oracle + ": " + a + " " + b);
                }
                if (s.distance() == (float) oracle) {
                    exactlyEqual++;
                }
            }
        }
        System.out.println("Separation vs JTS DistanceOp: " + pairs + " random pairs, " + apart + " answers (both orders) apart, "
                + agreed + " within a float's rounding, " + exactlyEqual + " equal to JTS rounded to float; worst "
                + worstUlps + " ulps");
        assertTrue(wrong.isEmpty(), wrong.size() + " disagree, first: " + (wrong.isEmpty() ? "" : wrong.get(0)));
        assertTrue(apart > 2000, "enough pairs apart: " + apart);
    }

    /** A gear: 2k corners at equal angle steps, alternately at radius r and s, concave when they differ. */
    private static Polygon gear(SplittableRandom rnd, int k, double cx, double cy) {
        double r = 10 + rnd.nextDouble(40), s = rnd.nextBoolean() ? r : r * rnd.nextDouble(0.6, 0.95), turn = rnd.nextDouble(7);
        float[] xy = new float[4 * k];
        for (int i = 0; i < 2 * k; i++) {
            double rad = i % 2 == 0 ? r : s, t = turn + Math.PI * i / k;
            xy[2 * i] = (float) (cx + rad * Math.cos(t));
            xy[2 * i + 1] = (float) (cy + rad * Math.sin(t));
        }
        return Polygon.of(xy);
    }

    @Test
    void manySidedPolygons_agreeWithJts_bothOrders() {
        // Enough edge pairs for Distances.chains to take them in order and stop early.
        SplittableRandom rnd = new SplittableRandom(230);
        int apart = 0;
        for (int n = 0; n < 60; n++) {
            Shape a = gear(rnd, 10 + rnd.nextInt(100), 0, 0);
            Shape b = n % 3 == 0 ? gear(rnd, 10 + rnd.nextInt(100), rnd.nextDouble(-120, 120), rnd.nextDouble(-120, 120))
                    : random(rnd, rnd.nextInt(6), rnd.nextDouble(-120, 120), rnd.nextDouble(-120, 120), false);
            double oracle = Math.max(0, DistanceOp.distance(JtsShapes.core(a), JtsShapes.core(b)) - JtsShapes.radius(a) - JtsShapes.radius(b));
            checkShape(a, b, 1e-5 * scale(a, b));
            for (Separation s : new Separation[] {Separation.between(a, b), Separation.between(b, a)}) {
                if (s != null) {
                    apart++;
                    assertEquals(oracle, s.distance(), Math.ulp((float) oracle) + 1e-12 * scale(a, b), a + " " + b);
                }
            }
        }
        assertTrue(apart > 60, "enough apart: " + apart);
    }

    // ---------------------------------------------------------------- exact

    private static Q exactSquaredDistance(Shape a, Shape b) {
        float[] p = corners(a), q = corners(b);
        Q best = null;
        for (float[][] pair : new float[][][] {{p, q}, {q, p}}) {
            float[] from = pair[0], to = pair[1];
            int n = to.length / 2;
            int edges = n == 1 ? 1 : n == 2 ? 1 : n;
            for (int i = 0; i < from.length / 2; i++) {
                for (int e = 0; e < edges; e++) {
                    int f = (e + 1) % n;
                    Q d = ExactReference.segmentDistanceSquared(Q.of(to[2 * e]), Q.of(to[2 * e + 1]), Q.of(to[2 * f]),
                            Q.of(to[2 * f + 1]), Q.of(from[2 * i]), Q.of(from[2 * i + 1]));
                    best = best == null || d.compareTo(best) < 0 ? d : best;
                }
            }
        }
        return best;
    }

    private static float[] corners(Shape s) {
        if (s instanceof Circle c) {
            return new float[] {c.x(), c.y()};
        }
        if (s instanceof Segment g) {
            return new float[] {g.x1(), g.y1(), g.x2(), g.y2()};
        }
        if (s instanceof Capsule k) {
            return new float[] {k.x1(), k.y1(), k.x2(), k.y2()};
        }
        return s instanceof Rect r ? ExactReference.rectPolygon(r.x(), r.y(), r.w(), r.h()) : ((Polygon) s).coordinates();
    }

    /** The square root of q when it is a rational square, else null. */
    private static Q root(Q q) {
        BigInteger n = q.num().sqrt(), d = q.den().sqrt();
        return n.multiply(n).equals(q.num()) && d.multiply(d).equals(q.den()) ? new Q(n, d) : null;
    }

    @Test
    void wholeNumbers_exactWhereTheDistanceIsAFloat() {
        SplittableRandom rnd = new SplittableRandom(2323);
        int rational = 0, apart = 0;
        for (int n = 0; n < 4000; n++) {
            Shape a = random(rnd, rnd.nextInt(6), 0, 0, true), b = random(rnd, rnd.nextInt(6), rnd.nextInt(60), rnd.nextInt(-20, 20), true);
            Separation s = Separation.between(a, b);
            if (s == null) {
                continue;
            }
            apart++;
            // Segments crossing: no end is closest, and the distance is 0.
            Q root = coresMeet(a, b) ? Q.ZERO : root(exactSquaredDistance(a, b));
            if (root == null) {
                continue;
            }
            Q exact = root.minus(Q.of((float) JtsShapes.radius(a))).minus(Q.of((float) JtsShapes.radius(b)));
            if (exact.signum() < 0) {
                exact = Q.ZERO;
            }
            float f = (float) exact.toDouble();
            if (Q.of(f).compareTo(exact) != 0) {
                continue;
            }
            rational++;
            assertEquals(f, s.distance(), a + " " + b);
            assertEquals(f, Separation.between(b, a).distance(), b + " " + a);
        }
        System.out.println("Separation on whole numbers: " + apart + " pairs apart, " + rational + " with a distance a float holds, all exact");
        assertTrue(rational > 300, "enough exact cases: " + rational);
    }

    /** Do the cores of two straight shapes meet (then their distance is 0, not an end's)? */
    private static boolean coresMeet(Shape a, Shape b) {
        return JtsShapes.core(a).intersects(JtsShapes.core(b)) || JtsShapes.core(a).distance(JtsShapes.core(b)) == 0;
    }

    // ---------------------------------------------------------------- ellipses

    /** The distance from a point to the other shape's core (without its radius): the test's own sums, JTS's for a polygon. */
    private static double pointTo(Shape s, double px, double py) {
        if (s instanceof Ellipse e) {
            throw new IllegalArgumentException("sampled separately: " + e);
        }
        if (s instanceof Rect || s instanceof Polygon) {
            Geometry g = JtsShapes.core(s);
            return g.distance(GF.createPoint(new Coordinate(px, py)));
        }
        if (s instanceof Circle c) {
            return Math.hypot(px - c.x(), py - c.y());
        }
        if (s instanceof Capsule k) {
            return toSegment(px, py, k.x1(), k.y1(), k.x2(), k.y2());
        }
        Segment g = (Segment) s;
        return toSegment(px, py, g.x1(), g.y1(), g.x2(), g.y2());
    }

    /** A point of the ellipse's outline at eccentric angle t. */
    private static double[] on(Ellipse e, double t) {
        double c = Math.cos(e.angle()), sn = Math.sin(e.angle());
        double u = e.rx() * Math.cos(t), v = e.ry() * Math.sin(t);
        return new double[] {e.x() + u * c - v * sn, e.y() + u * sn + v * c};
    }

    /**
     * The ellipse as a JTS polygon of n corners on its outline (inscribed), or, grown by
     * 1 / cos(pi / n) about its centre, around it (circumscribed: the affine image of a
     * circle's circumscribed polygon): the true distance lies between the two polygons'.
     */
    private static Geometry polygonOf(Ellipse e, int n, boolean around) {
        double grow = around ? 1 / Math.cos(Math.PI / n) : 1;
        Coordinate[] c = new Coordinate[n + 1];
        for (int i = 0; i < n; i++) {
            double[] p = on(e, 2 * Math.PI * i / n);
            c[i] = new Coordinate(e.x() + grow * (p[0] - e.x()), e.y() + grow * (p[1] - e.y()));
        }
        c[n] = c[0];
        return GF.createPolygon(c);
    }

    /** JTS's bracket of the distance between an ellipse and another shape: {lower, upper}. */
    private static double[] bracket(Ellipse e, Shape other) {
        int n = 1024;
        Geometry in = polygonOf(e, n, false), out = polygonOf(e, n, true);
        Geometry o = other instanceof Ellipse f ? null : JtsShapes.core(other);
        double lower = o == null ? out.distance(polygonOf((Ellipse) other, n, true)) : out.distance(o);
        double upper = o == null ? in.distance(polygonOf((Ellipse) other, n, false)) : in.distance(o);
        double r = JtsShapes.radius(other);
        return new double[] {Math.max(0, lower - r), Math.max(0, upper - r)};
    }

    /** Golden-section search: where in [lo, hi] f is least, and the value there. */
    private static double[] least(java.util.function.DoubleUnaryOperator f, double lo, double hi) {
        double g = (Math.sqrt(5) - 1) / 2;
        for (int k = 0; k < 70; k++) {
            double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
            if (f.applyAsDouble(m1) < f.applyAsDouble(m2)) {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        double t = (lo + hi) / 2;
        return new double[] {t, f.applyAsDouble(t)};
    }

    /**
     * The ellipse's distance from the other shape's core by sampling: 2048 points of its
     * outline, the least refined by golden section around it with the test's own point
     * distance (not for a second ellipse). A reference that shares nothing with Distances
     * but Math.
     */
    private static double sampled(Ellipse e, Shape other) {
        int m = 2048;
        double best = Double.POSITIVE_INFINITY, at = 0;
        for (int i = 0; i < m; i++) {
            double[] p = on(e, 2 * Math.PI * i / m);
            double d = pointTo(other, p[0], p[1]);
            if (d < best) {
                best = d;
                at = 2 * Math.PI * i / m;
            }
        }
        double[] r = least(t -> {
            double[] p = on(e, t);
            return pointTo(other, p[0], p[1]);
        }, at - 2 * Math.PI / m, at + 2 * Math.PI / m);
        return Math.min(best, r[1]);
    }

    @Test
    void ellipses_againstJtsBracketAndDenseSampling_bothOrders() {
        SplittableRandom rnd = new SplittableRandom(2300);
        int apart = 0, cases = 0;
        double worst = 0, widest = 0;
        // Long thin ellipses beside small ones: the distance around the long one's outline has
        // a second, larger least on its far side (and near its tips), which a search must not take.
        Ellipse thin = new Ellipse(0, 0, 100, 1), turned = new Ellipse(0, 0, 100, 1, 0.4f);
        Shape[][] fixed = {{thin, new Ellipse(30, 3, 2, 1)}, {thin, new Ellipse(30, -3, 2, 1)},
            {thin, new Ellipse(103, 1.5f, 1, 2)}, {thin, new Ellipse(-99, -2.5f, 3, 0.5f, 1)},
            {turned, new Ellipse(0, 5, 3, 1)}, {turned, new Ellipse(90, 40, 1, 3, -0.2f)},
            {new Ellipse(0, 0, 1, 100), new Ellipse(4, 60, 1, 100)}, {thin, new Circle(50, 3, 1)},
            {thin, new Capsule(-80, 2, 80, 3, 0.5f)}, {thin, Polygon.of(-50, 5, 50, 5, 0, 2.5f)}};
        for (int n = 0; n < 500 + fixed.length; n++) {
            int kb = n % 7;
            Ellipse e = n < fixed.length ? (Ellipse) fixed[n][0] : (Ellipse) random(rnd, 6, 0, 0, false);
            Shape b = n < fixed.length ? fixed[n][1] : random(rnd, kb, rnd.nextDouble(10, 80), rnd.nextDouble(-40, 40), false);
            cases++;
            double size = scale(e, b);
            checkShape(e, b, 1e-6 * size);
            Separation s = Separation.between(e, b);
            if (s == null) {
                continue;
            }
            apart++;
            double tol = Math.ulp(s.distance()) + hitbox.internal.Tolerance.SEPARATION_CURVED * size;
            // Between JTS's distances of the polygons inside and around the ellipse(s): a missed
            // least distance shows as an answer above the upper bound.
            double[] br = bracket(e, b);
            widest = Math.max(widest, (br[1] - br[0]) / size);
            assertTrue(s.distance() >= br[0] - tol && s.distance() <= br[1] + tol,
                    s.distance() + " outside JTS's [" + br[0] + ", " + br[1] + "]: " + e + " " + b);
            if (!(b instanceof Ellipse)) {
                // Refined sampling, accurate to double rounding: the answer is within its own float rounding.
                double reference = Math.max(0, sampled(e, b) - JtsShapes.radius(b));
                assertTrue(s.distance() <= reference + tol, s.distance() + " > sampled " + reference + ": " + e + " " + b);
                worst = Math.max(worst, (Math.abs(reference - s.distance()) - Math.ulp(s.distance())) / size);
            }
        }
        System.out.println("Separation of ellipses: " + cases + " pairs, " + apart + " apart, all inside JTS's bracket"
                + " (inscribed and circumscribed 1024-gons, at most " + widest + " of the size wide); against refined"
                + " sampling (one ellipse), within the answer's float rounding + " + Math.max(0, worst) + " of the size");
        assertTrue(apart > 300, "enough apart: " + apart);
    }
}
