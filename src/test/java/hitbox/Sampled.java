package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Function;

/**
 * An oracle for overlap tests that shares no code with the library: each shape is its
 * plain-double "is this point strictly inside?" formula and a dense sample of its outline.
 * Two convex shapes with area overlap exactly when a point of one's outline is strictly
 * inside the other, or one holds the other (its centre is inside); a sampled outline finds
 * such a point whenever the overlap is deeper than the sampling's spacing. So the oracle is
 * asked about a shape grown or shrunk by a margin ({@link #scaled}), and only its sure
 * answers are checked: a pair the library says overlaps must overlap when grown, a pair it
 * says is apart must be apart when shrunk (a point found inside proves an overlap).
 */
final class Sampled {
    private Sampled() {
    }

    static final int N = 8192;

    /** Is the point strictly inside the shape (false for shapes without area)? */
    static boolean inside(Shape s, double x, double y) {
        if (s instanceof Circle c) {
            return Math.hypot(x - c.x(), y - c.y()) < c.r();
        }
        if (s instanceof Ellipse e) {
            if (e.rx() == 0 || e.ry() == 0) {
                return false;
            }
            double c = Math.cos(e.angle()), sn = Math.sin(e.angle());
            double dx = x - e.x(), dy = y - e.y();
            double u = (dx * c + dy * sn) / e.rx(), v = (-dx * sn + dy * c) / e.ry();
            return u * u + v * v < 1;
        }
        if (s instanceof Rect r) {
            return x > r.x() && x < (double) r.x() + r.w() && y > r.y() && y < (double) r.y() + r.h();
        }
        if (s instanceof Capsule k) {
            return segmentDistance(k.x1(), k.y1(), k.x2(), k.y2(), x, y) < k.r();
        }
        if (s instanceof Polygon p) {
            boolean in = false;
            int n = p.size();
            for (int i = 0, j = n - 1; i < n; j = i++) {
                double xi = p.x(i), yi = p.y(i), xj = p.x(j), yj = p.y(j);
                double cross = (xj - xi) * (y - yi) - (yj - yi) * (x - xi);
                if (cross == 0 && Math.min(xi, xj) <= x && x <= Math.max(xi, xj)
                        && Math.min(yi, yj) <= y && y <= Math.max(yi, yj)) {
                    return false; // on the outline
                }
                if ((yi > y) != (yj > y) && x < xi + (y - yi) * (xj - xi) / (yj - yi)) {
                    in = !in;
                }
            }
            return in;
        }
        return false;
    }

    static double segmentDistance(double x1, double y1, double x2, double y2, double px, double py) {
        double dx = x2 - x1, dy = y2 - y1, len2 = dx * dx + dy * dy;
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((px - x1) * dx + (py - y1) * dy) / len2));
        return Math.hypot(px - (x1 + t * dx), py - (y1 + t * dy));
    }

    /** Points on the shape's outline (for a segment, the segment itself), and a point inside it. */
    static List<double[]> outline(Shape s) {
        List<double[]> out = new ArrayList<>();
        if (s instanceof Circle c) {
            ellipse(out, c.x(), c.y(), c.r(), c.r(), 0);
        } else if (s instanceof Ellipse e) {
            ellipse(out, e.x(), e.y(), e.rx(), e.ry(), e.angle());
        } else if (s instanceof Rect r) {
            double x = r.x(), y = r.y(), w = r.w(), h = r.h();
            polyline(out, new double[] {x, y, x + w, y, x + w, y + h, x, y + h}, true);
        } else if (s instanceof Segment g) {
            polyline(out, new double[] {g.x1(), g.y1(), g.x2(), g.y2()}, false);
        } else if (s instanceof Polygon p) {
            double[] xy = new double[2 * p.size()];
            for (int i = 0; i < p.size(); i++) {
                xy[2 * i] = p.x(i);
                xy[2 * i + 1] = p.y(i);
            }
            polyline(out, xy, true);
        } else if (s instanceof Capsule k) {
            double dx = k.x2() - k.x1(), dy = k.y2() - k.y1();
            double a = Math.atan2(dy, dx);
            for (int i = 0; i <= N / 2; i++) {
                double t = a - Math.PI / 2 + Math.PI * i / (N / 2);
                out.add(new double[] {k.x2() + k.r() * Math.cos(t), k.y2() + k.r() * Math.sin(t)});
                out.add(new double[] {k.x1() - k.r() * Math.cos(t), k.y1() - k.r() * Math.sin(t)});
            }
            double nx = -Math.sin(a) * k.r(), ny = Math.cos(a) * k.r();
            for (int i = 0; i <= N / 4; i++) {
                double t = (double) i / (N / 4);
                out.add(new double[] {k.x1() + t * dx + nx, k.y1() + t * dy + ny});
                out.add(new double[] {k.x1() + t * dx - nx, k.y1() + t * dy - ny});
            }
            out.add(new double[] {(k.x1() + k.x2()) / 2.0, (k.y1() + k.y2()) / 2.0});
        }
        return out;
    }

    private static void ellipse(List<double[]> out, double x, double y, double a, double b, double angle) {
        double c = Math.cos(angle), s = Math.sin(angle);
        for (int i = 0; i < N; i++) {
            double t = 2 * Math.PI * i / N;
            double u = a * Math.cos(t), v = b * Math.sin(t);
            out.add(new double[] {x + u * c - v * s, y + u * s + v * c});
        }
        out.add(new double[] {x, y});
    }

    private static void polyline(List<double[]> out, double[] xy, boolean closed) {
        int n = xy.length / 2, edges = closed ? n : n - 1, per = Math.max(1, N / Math.max(1, edges) / 2);
        for (int i = 0; i < edges; i++) {
            int j = (i + 1) % n;
            for (int k = 0; k <= per; k++) {
                double t = (double) k / per;
                out.add(new double[] {xy[2 * i] + t * (xy[2 * j] - xy[2 * i]), xy[2 * i + 1] + t * (xy[2 * j + 1] - xy[2 * i + 1])});
            }
        }
    }

    /** Do the shapes overlap, as far as the samples can tell (a true answer is a proof, up to rounding)? */
    static boolean overlap(Shape a, Shape b) {
        for (double[] p : outline(a)) {
            if (inside(b, p[0], p[1])) {
                return true;
            }
        }
        for (double[] p : outline(b)) {
            if (inside(a, p[0], p[1])) {
                return true;
            }
        }
        return false;
    }

    /** The ellipse or capsule grown (f greater than 1) or shrunk (f less than 1) by factor f in its radii. */
    static Shape scaled(Shape s, double f) {
        if (s instanceof Ellipse e) {
            return new Ellipse(e.x(), e.y(), (float) (e.rx() * f), (float) (e.ry() * f), e.angle());
        }
        if (s instanceof Capsule k) {
            return new Capsule(k.x1(), k.y1(), k.x2(), k.y2(), (float) (k.r() * f));
        }
        throw new IllegalArgumentException(String.valueOf(s));
    }

    /**
     * Random shapes from {@code make} against random shapes of every kind: both orders agree,
     * a pair said to overlap overlaps when the first is grown 2%, a pair said to be apart is
     * apart when it is shrunk 2%. Both answers must come up often.
     */
    static void assertAgreesWithOracle(long seed, int count, Function<Random, Shape> make) {
        assertAgreesWithOracle(seed, count, make, Sampled::any);
    }

    /** As above, the other shape from {@code others}. */
    static void assertAgreesWithOracle(long seed, int count, Function<Random, Shape> make,
                                       Function<Random, Shape> others) {
        Random rnd = new Random(seed);
        int overlapping = 0, apart = 0;
        for (int i = 0; i < count; i++) {
            Shape s = make.apply(rnd);
            Shape other = others.apply(rnd);
            boolean answer = s.overlaps(other);
            assertEquals(answer, other.overlaps(s), "both orders for " + s + " and " + other);
            if (answer) {
                overlapping++;
                assertTrue(overlap(scaled(s, 1.02), other), "says overlapping, but grown 2% it is apart: " + s + " " + other);
            } else {
                apart++;
                assertFalse(overlap(scaled(s, 0.98), other), "says apart, but shrunk 2% it overlaps: " + s + " " + other);
            }
        }
        assertTrue(overlapping > count / 6 && apart > count / 6, overlapping + " overlapping, " + apart + " apart");
    }

    // ------------------------------------------------------------------ random shapes, modest sizes

    static Ellipse ellipse(Random rnd) {
        return new Ellipse(coord(rnd), coord(rnd), 2 + rnd.nextInt(40) + rnd.nextFloat(), 2 + rnd.nextInt(40) + rnd.nextFloat());
    }

    /** An ellipse turned by any angle (now and then a right angle or a half turn, written in float). */
    static Ellipse turnedEllipse(Random rnd) {
        Ellipse e = ellipse(rnd);
        float angle = rnd.nextInt(6) == 0 ? (float) (Math.PI / 2 * rnd.nextInt(4)) : (float) (rnd.nextDouble() * 7 - 3.5);
        return new Ellipse(e.x(), e.y(), e.rx(), e.ry(), angle);
    }

    static Capsule capsule(Random rnd) {
        float x = coord(rnd), y = coord(rnd);
        boolean point = rnd.nextInt(8) == 0;
        return new Capsule(x, y, point ? x : coord(rnd), point ? y : coord(rnd), 2 + rnd.nextInt(25) + rnd.nextFloat());
    }

    /** Any kind of shape with positive sizes; polygons convex or concave. */
    static Shape any(Random rnd) {
        switch (rnd.nextInt(7)) {
            case 0:
                return new Circle(coord(rnd), coord(rnd), 1 + rnd.nextInt(30) + rnd.nextFloat());
            case 1:
                return new Rect(coord(rnd), coord(rnd), 1 + rnd.nextInt(50), 1 + rnd.nextInt(50) + rnd.nextFloat());
            case 2:
                return new Segment(coord(rnd), coord(rnd), coord(rnd), coord(rnd));
            case 3: {
                float x = coord(rnd), y = coord(rnd);
                return Polygon.of(x, y, x + 30 + rnd.nextInt(20), y + rnd.nextInt(10), x + rnd.nextInt(10), y + 25 + rnd.nextInt(20));
            }
            case 4: {
                float x = coord(rnd), y = coord(rnd);
                // An arrow head, concave at (x + 15, y + 15).
                return Polygon.of(x, y, x + 40, y + 10, x + 15, y + 15, x + 10, y + 40);
            }
            case 5:
                return ellipse(rnd);
            default:
                return capsule(rnd);
        }
    }

    static float coord(Random rnd) {
        return rnd.nextInt(120) + (rnd.nextBoolean() ? 0 : rnd.nextFloat());
    }
}
