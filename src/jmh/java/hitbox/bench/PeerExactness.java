package hitbox.bench;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

import com.badlogic.gdx.math.Intersector;
import hitbox.Collide;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Transform;

/**
 * What the peers' speed on the small tests buys: the narrow-phase table's small rows (a point
 * in a circle, two rectangles, ...) are faster in libGDX and dyn4j because they compute in
 * float or without Hitbox's guards. This counts, for each such question, how often each
 * answer differs from the exact one on shapes that nearly touch (the second shape placed
 * within a relative 1e-6 of the first's outline, then rounded to float, as a sketch's floats
 * are), at screen coordinates (up to 2,000 px) and world coordinates (up to 100,000 px). The
 * exact answer is computed here in {@link BigDecimal} from the floats, independently of
 * Hitbox, with the one touching rule (open shapes, closed segments and points); cases that
 * touch exactly are left out, so a peer's closed shapes are not counted against it.
 *
 * <p>Run: {@code gradle peerExactness}; it writes {@code docs/peer-exactness.md} and fails if
 * Hitbox answers any case wrongly. The narrow-phase table's reasons point to it.
 */
public final class PeerExactness {
    private PeerExactness() {
    }

    static final int CASES = 200_000;
    static final double NEAR = 1e-6;

    /** One question: makes a near case into {@code f} and answers it three ways; null to skip the case. */
    interface Question {
        /** {exact, hitbox, peer}, or null when the case touches exactly. */
        boolean[] answer(SplittableRandom r, float scale);
    }

    record Row(String title, String peer, Question q) {
    }

    public static void main(String[] args) throws java.io.IOException {
        List<Row> rows = new ArrayList<>();
        rows.add(new Row("point in circle", "libGDX Circle.contains", PeerExactness::circlePoint));
        rows.add(new Row("circle vs circle", "libGDX Circle.overlaps", PeerExactness::circleCircle));
        rows.add(new Row("point in rect", "libGDX Rectangle.contains", PeerExactness::rectPoint));
        rows.add(new Row("two rects", "libGDX Rectangle.overlaps", PeerExactness::rectRect));
        rows.add(new Row("circle vs rect", "libGDX Intersector.overlaps(Circle, Rectangle)", PeerExactness::circleRect));
        rows.add(new Row("segment vs segment", "libGDX Intersector.intersectSegments", PeerExactness::lineLine));
        rows.add(new Row("point in triangle", "libGDX Intersector.isPointInTriangle", PeerExactness::trianglePoint));
        rows.add(new Row("point in ellipse", "libGDX Ellipse.contains", PeerExactness::ellipsePoint));
        rows.add(new Row("point in capsule", "dyn4j Capsule.contains", PeerExactness::capsulePoint));
        rows.add(new Row("point in concave 16-gon", "libGDX Intersector.isPointInPolygon", PeerExactness::polygonPoint));
        StringBuilder out = new StringBuilder();
        out.append("# What the peers' faster small tests get wrong\n\n")
                .append("Made by `gradle peerExactness` (src/jmh/java/hitbox/bench/PeerExactness.java); edit the generator, not the output.\n\n")
                .append("For each small question of the narrow-phase table where a peer is faster, ").append(String.format(Locale.ROOT, "%,d", CASES))
                .append(" cases whose second shape\nlies within a relative 1e-6")
                .append(" of the first's outline, rounded to float as a sketch's floats are, at screen\n")
                .append("coordinates (up to 2,000 px) and world coordinates (up to 100,000 px). The exact answer is computed in\n")
                .append("`BigDecimal` from the floats, independently of Hitbox, by the one touching rule; cases that touch exactly\n")
                .append("are left out, so a peer's closed shapes are not counted against it. The rate depends on how near the cases\n")
                .append("are made: read it as \"this happens\", not as a frequency in a game.\n\n");
        out.append("| question | peer | scale | cases | peer wrong | Hitbox wrong |\n| --- | --- | --- | ---: | ---: | ---: |\n");
        for (Row row : rows) {
            for (float scale : new float[] {2_000, 100_000}) {
                SplittableRandom r = new SplittableRandom(row.title().hashCode() * 31L + (long) scale);
                int cases = 0, peerWrong = 0, hitboxWrong = 0;
                while (cases < CASES) {
                    boolean[] a = row.q().answer(r, scale);
                    if (a == null) continue;
                    cases++;
                    if (a[1] != a[0]) hitboxWrong++;
                    if (a[2] != a[0]) peerWrong++;
                }
                out.append(String.format(Locale.ROOT, "| %s | `%s` | %,.0f px | %,d | %,d (%.2f%%) | %,d |%n", row.title(), row.peer(),
                        scale, cases, peerWrong, 100.0 * peerWrong / cases, hitboxWrong));
                if (hitboxWrong > 0) {
                    throw new AssertionError(row.title() + ": Hitbox answered " + hitboxWrong + " cases wrongly at " + scale + " px");
                }
            }
        }
        java.nio.file.Files.writeString(java.nio.file.Path.of("docs/peer-exactness.md"), out.toString());
        System.out.print(out);
    }

    // ---------------------------------------------------------------- exact arithmetic

    private static BigDecimal b(float v) {
        return new BigDecimal(v);
    }

    /** The sign of (b - a) x (c - a), exactly. */
    private static int orient(float ax, float ay, float bx, float by, float cx, float cy) {
        return b(bx).subtract(b(ax)).multiply(b(cy).subtract(b(ay)))
                .subtract(b(by).subtract(b(ay)).multiply(b(cx).subtract(b(ax)))).signum();
    }

    /** Squared distance from (px, py) to (x, y), exactly. */
    private static BigDecimal dist2(float px, float py, float x, float y) {
        BigDecimal dx = b(px).subtract(b(x)), dy = b(py).subtract(b(y));
        return dx.multiply(dx).add(dy.multiply(dy));
    }

    private static float coord(SplittableRandom r, float scale) {
        return (float) (r.nextDouble() * scale);
    }

    private static float size(SplittableRandom r) {
        return (float) (5 + r.nextDouble() * 200);
    }

    /** A factor 1 + e with e within NEAR of 0. */
    private static double near(SplittableRandom r) {
        return 1 + (r.nextDouble() * 2 - 1) * NEAR;
    }

    // ---------------------------------------------------------------- the questions

    static boolean[] circlePoint(SplittableRandom r, float scale) {
        float cx = coord(r, scale), cy = coord(r, scale), rad = size(r);
        double a = r.nextDouble() * 2 * Math.PI, d = rad * near(r);
        float px = (float) (cx + d * Math.cos(a)), py = (float) (cy + d * Math.sin(a));
        int c = dist2(px, py, cx, cy).compareTo(b(rad).multiply(b(rad)));
        if (c == 0) return null;
        return new boolean[] {c < 0, Collide.circlePoint(cx, cy, rad, px, py),
                new com.badlogic.gdx.math.Circle(cx, cy, rad).contains(px, py)};
    }

    static boolean[] circleCircle(SplittableRandom r, float scale) {
        float x1 = coord(r, scale), y1 = coord(r, scale), r1 = size(r), r2 = size(r);
        double a = r.nextDouble() * 2 * Math.PI, d = (r1 + (double) r2) * near(r);
        float x2 = (float) (x1 + d * Math.cos(a)), y2 = (float) (y1 + d * Math.sin(a));
        BigDecimal reach = b(r1).add(b(r2));
        int c = dist2(x2, y2, x1, y1).compareTo(reach.multiply(reach));
        if (c == 0) return null;
        return new boolean[] {c < 0, Collide.circleCircle(x1, y1, r1, x2, y2, r2),
                new com.badlogic.gdx.math.Circle(x1, y1, r1).overlaps(new com.badlogic.gdx.math.Circle(x2, y2, r2))};
    }

    static boolean[] rectPoint(SplittableRandom r, float scale) {
        float x = coord(r, scale), y = coord(r, scale), w = size(r), h = size(r);
        float px = (float) ((x + (double) w) * near(r)), py = (float) (y + h * r.nextDouble());
        int right = b(px).compareTo(b(x).add(b(w)));
        if (right == 0 || py == y) return null;
        boolean exact = b(px).compareTo(b(x)) > 0 && right < 0 && b(py).compareTo(b(y)) > 0 && b(py).compareTo(b(y).add(b(h))) < 0;
        return new boolean[] {exact, Collide.rectPoint(x, y, w, h, px, py),
                new com.badlogic.gdx.math.Rectangle(x, y, w, h).contains(px, py)};
    }

    static boolean[] rectRect(SplittableRandom r, float scale) {
        float x1 = coord(r, scale), y1 = coord(r, scale), w1 = size(r), h1 = size(r), w2 = size(r), h2 = size(r);
        float x2 = (float) ((x1 + (double) w1) * near(r)), y2 = (float) (y1 + (h1 - 1) * r.nextDouble());
        int c = b(x1).add(b(w1)).compareTo(b(x2));
        if (c == 0) return null;
        boolean exact = c > 0 && b(x2).add(b(w2)).compareTo(b(x1)) > 0
                && b(y1).add(b(h1)).compareTo(b(y2)) > 0 && b(y2).add(b(h2)).compareTo(b(y1)) > 0;
        return new boolean[] {exact, Collide.rectRect(x1, y1, w1, h1, x2, y2, w2, h2),
                new com.badlogic.gdx.math.Rectangle(x1, y1, w1, h1).overlaps(new com.badlogic.gdx.math.Rectangle(x2, y2, w2, h2))};
    }

    static boolean[] circleRect(SplittableRandom r, float scale) {
        float x = coord(r, scale), y = coord(r, scale), w = size(r), h = size(r), rad = size(r);
        // near a corner or a side: a point of the rect's outline, then out along a direction
        double a = r.nextDouble() * 2 * Math.PI, d = rad * near(r);
        double ox = x + w * (r.nextInt(3) / 2.0), oy = y + h * (r.nextInt(3) / 2.0);
        float cx = (float) (ox + d * Math.cos(a)), cy = (float) (oy + d * Math.sin(a));
        BigDecimal qx = b(cx).max(b(x)).min(b(x).add(b(w))), qy = b(cy).max(b(y)).min(b(y).add(b(h)));
        BigDecimal dx = b(cx).subtract(qx), dy = b(cy).subtract(qy);
        int c = dx.multiply(dx).add(dy.multiply(dy)).compareTo(b(rad).multiply(b(rad)));
        if (c == 0) return null;
        return new boolean[] {c < 0, Collide.circleRect(cx, cy, rad, x, y, w, h),
                Intersector.overlaps(new com.badlogic.gdx.math.Circle(cx, cy, rad), new com.badlogic.gdx.math.Rectangle(x, y, w, h))};
    }

    static boolean[] lineLine(SplittableRandom r, float scale) {
        float x1 = coord(r, scale), y1 = coord(r, scale);
        double a = r.nextDouble() * 2 * Math.PI, len = size(r);
        float x2 = (float) (x1 + len * Math.cos(a)), y2 = (float) (y1 + len * Math.sin(a));
        // the second segment ends near the first, from a point well to one side
        double t = r.nextDouble(), mx = x1 + t * (x2 - (double) x1), my = y1 + t * (y2 - (double) y1);
        double nx = -Math.sin(a), ny = Math.cos(a), e = (near(r) - 1) * len, far = size(r);
        float x3 = (float) (mx + nx * far), y3 = (float) (my + ny * far);
        float x4 = (float) (mx + nx * e), y4 = (float) (my + ny * e);
        int o1 = orient(x1, y1, x2, y2, x3, y3), o2 = orient(x1, y1, x2, y2, x4, y4);
        int o3 = orient(x3, y3, x4, y4, x1, y1), o4 = orient(x3, y3, x4, y4, x2, y2);
        if (o1 == 0 || o2 == 0 || o3 == 0 || o4 == 0) return null;
        boolean exact = o1 != o2 && o3 != o4;
        return new boolean[] {exact, Collide.lineLine(x1, y1, x2, y2, x3, y3, x4, y4),
                Intersector.intersectSegments(x1, y1, x2, y2, x3, y3, x4, y4, null)};
    }

    static boolean[] trianglePoint(SplittableRandom r, float scale) {
        float x1 = coord(r, scale), y1 = coord(r, scale);
        float x2 = x1 + size(r), y2 = y1 + size(r) * 0.3f, x3 = x1 + size(r) * 0.5f, y3 = y1 + size(r);
        // near the edge from corner 1 to corner 2
        double t = r.nextDouble(), e = near(r) - 1;
        double mx = x1 + t * (x2 - (double) x1), my = y1 + t * (y2 - (double) y1);
        double cx = (x1 + (double) x2 + x3) / 3, cy = (y1 + (double) y2 + y3) / 3;
        float px = (float) (mx + (mx - cx) * e * 100), py = (float) (my + (my - cy) * e * 100);
        int o1 = orient(x1, y1, x2, y2, px, py), o2 = orient(x2, y2, x3, y3, px, py), o3 = orient(x3, y3, x1, y1, px, py);
        if (o1 == 0 || o2 == 0 || o3 == 0) return null;
        boolean exact = o1 == o2 && o2 == o3;
        return new boolean[] {exact, Collide.trianglePoint(x1, y1, x2, y2, x3, y3, px, py),
                Intersector.isPointInTriangle(px, py, x1, y1, x2, y2, x3, y3)};
    }

    static boolean[] ellipsePoint(SplittableRandom r, float scale) {
        float x = coord(r, scale), y = coord(r, scale), rx = size(r), ry = size(r);
        double a = r.nextDouble() * 2 * Math.PI, k = near(r);
        float px = (float) (x + rx * k * Math.cos(a)), py = (float) (y + ry * k * Math.sin(a));
        BigDecimal dx = b(px).subtract(b(x)), dy = b(py).subtract(b(y));
        BigDecimal rx2 = b(rx).multiply(b(rx)), ry2 = b(ry).multiply(b(ry));
        int c = dx.multiply(dx).multiply(ry2).add(dy.multiply(dy).multiply(rx2)).compareTo(rx2.multiply(ry2));
        if (c == 0) return null;
        return new boolean[] {c < 0, new hitbox.Ellipse(x, y, rx, ry).contains(px, py),
                new com.badlogic.gdx.math.Ellipse(x, y, 2 * rx, 2 * ry).contains(px, py)};
    }

    static boolean[] capsulePoint(SplittableRandom r, float scale) {
        float x1 = coord(r, scale), y1 = coord(r, scale), rad = size(r) / 4;
        double a = r.nextDouble() * 2 * Math.PI, len = size(r);
        float x2 = (float) (x1 + len * Math.cos(a)), y2 = (float) (y1 + len * Math.sin(a));
        double t = r.nextDouble() * 1.4 - 0.2, ct = Math.max(0, Math.min(1, t));
        double mx = x1 + ct * (x2 - (double) x1), my = y1 + ct * (y2 - (double) y1);
        double b = t == ct ? a + Math.PI / 2 * (r.nextBoolean() ? 1 : -1) : r.nextDouble() * 2 * Math.PI, d = rad * near(r);
        float px = (float) (mx + d * Math.cos(b)), py = (float) (my + d * Math.sin(b));
        // squared distance to the segment, compared with r^2 without dividing
        BigDecimal ex = b(x2).subtract(b(x1)), ey = b(y2).subtract(b(y1));
        BigDecimal qx = b(px).subtract(b(x1)), qy = b(py).subtract(b(y1));
        BigDecimal dot = qx.multiply(ex).add(qy.multiply(ey)), len2 = ex.multiply(ex).add(ey.multiply(ey));
        BigDecimal r2 = b(rad).multiply(b(rad));
        int c;
        if (dot.signum() <= 0) {
            c = dist2(px, py, x1, y1).compareTo(r2);
        } else if (dot.compareTo(len2) >= 0) {
            c = dist2(px, py, x2, y2).compareTo(r2);
        } else {
            BigDecimal cross = qx.multiply(ey).subtract(qy.multiply(ex));
            c = cross.multiply(cross).compareTo(r2.multiply(len2));
        }
        if (c == 0) return null;
        hitbox.Capsule k = new hitbox.Capsule(x1, y1, x2, y2, rad);
        Convex shape = NarrowPeers.dyn4j(k);
        Transform at = NarrowPeers.dyn4jAt(k);
        return new boolean[] {c < 0, k.contains(px, py),
                shape.contains(new org.dyn4j.geometry.Vector2(px, py), at, false)};
    }

    static boolean[] polygonPoint(SplittableRandom r, float scale) {
        // a star: 16 corners around a centre at alternating radii, so it is concave
        float cx = coord(r, scale), cy = coord(r, scale);
        float[] xy = new float[32];
        for (int i = 0; i < 16; i++) {
            double a = i * Math.PI / 8, rad = (i % 2 == 0 ? 1 : 0.5) * size(r);
            xy[2 * i] = (float) (cx + rad * Math.cos(a));
            xy[2 * i + 1] = (float) (cy + rad * Math.sin(a));
        }
        // near a point of one edge, off it along the line from the centre
        int e = r.nextInt(16), n = (e + 1) % 16;
        double t = r.nextDouble(), k = near(r);
        double mx = xy[2 * e] + t * (xy[2 * n] - (double) xy[2 * e]), my = xy[2 * e + 1] + t * (xy[2 * n + 1] - (double) xy[2 * e + 1]);
        float px = (float) (cx + (mx - cx) * k), py = (float) (cy + (my - cy) * k);
        // exact crossing number, leaving out points on an edge
        boolean inside = false;
        for (int i = 0, j = 15; i < 16; j = i++) {
            float ax = xy[2 * j], ay = xy[2 * j + 1], bx = xy[2 * i], by = xy[2 * i + 1];
            int o = orient(ax, ay, bx, by, px, py);
            if (o == 0 && b(px).compareTo(b(Math.min(ax, bx))) >= 0 && b(px).compareTo(b(Math.max(ax, bx))) <= 0
                    && b(py).compareTo(b(Math.min(ay, by))) >= 0 && b(py).compareTo(b(Math.max(ay, by))) <= 0) {
                return null;
            }
            if ((ay > py) != (by > py) && (by > ay ? o > 0 : o < 0)) {
                inside = !inside;
            }
        }
        return new boolean[] {inside, Collide.polygonPoint(xy, px, py), Intersector.isPointInPolygon(xy, 0, 32, px, py)};
    }
}
