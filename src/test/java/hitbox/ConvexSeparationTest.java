package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.operation.distance.DistanceOp;

/**
 * {@link Separation} between two convex outlines (rectangles, turned boxes, convex polygons of
 * 3 to 64 corners in either winding), which the library answers by walking the two outlines'
 * difference rather than every pair of edges: against JTS's {@code DistanceOp}, which shares
 * no code with it, with the outlines' hard cases made on purpose: corners on a line, flat
 * rectangles, shapes touching at a corner or along an edge, parallel edges, far from the
 * origin. And the rule for equally close pairs, checked on the geometry of the answer.
 */
class ConvexSeparationTest {

    /** A convex shape near (cx, cy): a rectangle (flat now and then), a turned box, a polygon of many corners, or one with corners on its edges. */
    private static Shape convex(SplittableRandom rnd, double cx, double cy) {
        float x = (float) (cx + rnd.nextDouble(-20, 20)), y = (float) (cy + rnd.nextDouble(-20, 20));
        switch (rnd.nextInt(5)) {
            case 0: {
                float w = rnd.nextInt(8) == 0 ? 0 : (float) rnd.nextDouble(1, 40), h = (float) rnd.nextDouble(1, 40);
                return rnd.nextBoolean() ? new Rect(x, y, w, h) : new Rect(x, y, h, w);
            }
            case 1:
                return new Rect(x, y, (float) rnd.nextDouble(1, 40), (float) rnd.nextDouble(1, 40))
                        .rotated((float) rnd.nextDouble(-4, 4), x, y);
            case 2:
                return TestShapes.convexRing(rnd, 3 + rnd.nextInt(62), x, y, false);
            case 3:
                return TestShapes.convexRing(rnd, 3 + rnd.nextInt(6), x, y, true);
            default: {
                // Corners halfway along some edges: three corners in a line.
                Polygon p = TestShapes.convexRing(rnd, 3 + rnd.nextInt(6), x, y, true);
                float[] xy = p.coordinates();
                List<Float> out = new ArrayList<>();
                for (int i = 0; i < xy.length / 2; i++) {
                    int j = (i + 1) % (xy.length / 2);
                    out.add(xy[2 * i]);
                    out.add(xy[2 * i + 1]);
                    float mx = (xy[2 * i] + xy[2 * j]) / 2, my = (xy[2 * i + 1] + xy[2 * j + 1]) / 2;
                    if (rnd.nextBoolean() && mx == (xy[2 * i] + (double) xy[2 * j]) / 2 && my == (xy[2 * i + 1] + (double) xy[2 * j + 1]) / 2
                            && (mx != xy[2 * i] || my != xy[2 * i + 1]) && (mx != xy[2 * j] || my != xy[2 * j + 1])) {
                        out.add(mx);
                        out.add(my);
                    }
                }
                float[] with = new float[out.size()];
                for (int k = 0; k < with.length; k++) {
                    with[k] = out.get(k);
                }
                return Polygon.of(with);
            }
        }
    }

    /** The shape's corners (a rectangle's four), for placing one shape's corner on another's. */
    private static float[] corners(Shape s) {
        return s instanceof Rect r ? ExactReference.rectPolygon(r.x(), r.y(), r.w(), r.h()) : ((Polygon) s).coordinates();
    }

    @Test
    void convexOutlines_agreeWithJts_bothOrders() {
        SplittableRandom rnd = new SplittableRandom(2911);
        int apart = 0, touching = 0, far = 0;
        List<String> wrong = new ArrayList<>();
        for (int n = 0; n < 6000; n++) {
            double offset = n % 7 == 0 ? 1e5 : 0;
            Shape a = convex(rnd, offset, offset), b = convex(rnd, offset + rnd.nextDouble(-80, 80), offset + rnd.nextDouble(-80, 80));
            if (n % 3 == 0) {
                // A corner of b put exactly on a corner of a: touching there, or overlapping.
                float[] p = corners(a), q = corners(b);
                int i = rnd.nextInt(p.length / 2), j = rnd.nextInt(q.length / 2);
                b = b.translated(p[2 * i] - q[2 * j], p[2 * i + 1] - q[2 * j + 1]);
            }
            double scale = SeparationOracleTest.scale(a, b);
            SeparationOracleTest.checkShape(a, b, 1e-5 * scale);
            double oracle = DistanceOp.distance(JtsShapes.core(a), JtsShapes.core(b));
            for (Separation s : new Separation[] {Separation.between(a, b), Separation.between(b, a)}) {
                if (s == null) {
                    if (oracle > 1e-9 * scale) {
                        wrong.add("null, but JTS says apart by " + oracle + ": " + a + " " + b);
                    }
                    continue;
                }
                apart++;
                touching += s.distance() == 0 ? 1 : 0;
                far += offset > 0 ? 1 : 0;
                if (Math.abs(s.distance() - oracle) > Math.ulp((float) oracle) + 1e-12 * scale) {
                    wrong.add(s.distance() + " vs JTS " + oracle + ": " + a + " " + b);
                }
            }
        }
        System.out.println("Convex separations vs JTS: " + apart + " answers apart (both orders), " + touching + " touching, "
                + far + " far from the origin");
        assertTrue(wrong.isEmpty(), wrong.size() + " disagree, first: " + (wrong.isEmpty() ? "" : wrong.get(0)));
        assertTrue(apart > 4000 && touching > 200 && far > 400, apart + " apart, " + touching + " touching, " + far + " far");
    }

    /** Rectangle r's outline as a polygon, from corner {@code start}, in either winding. */
    private static Polygon asPolygon(Rect r, int start, boolean reversed) {
        float[] c = ExactReference.rectPolygon(r.x(), r.y(), r.w(), r.h());
        float[] xy = new float[8];
        for (int k = 0; k < 4; k++) {
            int v = reversed ? (start - k + 4) % 4 : (start + k) % 4;
            xy[2 * k] = c[2 * v];
            xy[2 * k + 1] = c[2 * v + 1];
        }
        return Polygon.of(xy);
    }

    @Test
    void parallelEdges_giveThePairWithTheFirstMidpoint_eitherOrder() {
        // Two boxes side by side, their facing edges parallel and overlapping in y: every
        // height in the overlap gives a closest pair. The one given has the least midpoint: its
        // x is the same for all, so the least y, the top of the overlap. Each box also as a
        // polygon from each corner, in each winding, so that the walks start anywhere.
        SplittableRandom rnd = new SplittableRandom(4);
        for (int n = 0; n < 300; n++) {
            Rect a = new Rect(rnd.nextInt(-50, 50), rnd.nextInt(-50, 50), rnd.nextInt(1, 30), rnd.nextInt(1, 30));
            float h = rnd.nextInt(1, 30);
            float y = a.y() + rnd.nextInt((int) -h + 1, (int) a.h());
            Rect b = new Rect(a.right() + rnd.nextInt(1, 20), y, rnd.nextInt(1, 30), h);
            float top = Math.max(a.y(), b.y());
            Shape[] as = {a, asPolygon(a, n % 4, false), asPolygon(a, n % 4, true)};
            Shape[] bs = {b, asPolygon(b, (n + 1) % 4, n % 2 == 0), asPolygon(b, (n + 3) % 4, n % 2 == 1)};
            for (Shape p : as) {
                for (Shape q : bs) {
                    Separation s = Separation.between(p, q), back = Separation.between(q, p);
                    assertNotNull(s, p + " " + q);
                    String what = p + " and " + q + ": " + s + ", back " + back;
                    assertEquals(b.x() - a.right(), s.distance(), what);
                    assertEquals(a.right(), s.ax(), what);
                    assertEquals(top, s.ay(), what);
                    assertEquals(b.x(), s.bx(), what);
                    assertEquals(top, s.by(), what);
                    assertEquals(s.flipped(), back, what);
                }
            }
        }
    }
}
