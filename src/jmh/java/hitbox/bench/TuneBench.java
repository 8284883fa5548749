package hitbox.bench;

import java.util.Random;
import java.util.concurrent.TimeUnit;

import hitbox.Circle;
import hitbox.Collide;
import hitbox.Contact;
import hitbox.Hit;
import hitbox.Polygon;
import hitbox.Ray;
import hitbox.Segment;
import hitbox.Rect;
import hitbox.Shape;
import hitbox.Sweep;
import org.dyn4j.collision.narrowphase.Gjk;
import org.dyn4j.collision.narrowphase.Penetration;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Transform;
import org.dyn4j.geometry.Vector2;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * The narrow-phase cases of issue 12, 1,024 random cases per call (divide by 1,024 for one
 * case), for tuning Hitbox against itself before and after a change and against the peers
 * that need no extra dependency: dyn4j's GJK (and EPA) for convex polygons, and the plain
 * float forms that libGDX's {@code Intersector} uses, written out here (point in polygon,
 * segment against segment, ray against circle and box). Polygon cases are convex 8-gons
 * (random corners on a circle) whose boxes overlap, half of them overlapping.
 * Run with {@code -prof gc} for bytes per call.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class TuneBench {
    static final int N = 1024;

    Polygon[] pa = new Polygon[N], pb = new Polygon[N];
    float[][] ra = new float[N][], rb = new float[N][];
    Convex[] da = new Convex[N], db = new Convex[N];
    final Transform identity = new Transform();
    final Gjk gjk = new Gjk();
    final Penetration penetration = new Penetration();

    float[] star = new float[32];
    float[] px = new float[N], py = new float[N], cr = new float[N];
    float[] s = new float[8 * N];
    float[] ox = new float[N], oy = new float[N], dx = new float[N], dy = new float[N];
    float[] rx = new float[N], ry = new float[N], rw = new float[N], rh = new float[N];
    Rect[] rects = new Rect[N + 1];
    Ray[] rays = new Ray[N];
    Shape[] rectShapes = new Shape[N + 1];
    Circle[] circles = new Circle[N];
    Segment[] segments = new Segment[N];
    Shape[] circleShapes = new Shape[N], segmentShapes = new Shape[N], polygonShapes = new Shape[N];

    @Setup
    public void setup() {
        Random rnd = new Random(12);
        int hits = 0, misses = 0, k = 0;
        while (k < N) {
            float[] a = convex8(rnd, 200, 200);
            float[] b = convex8(rnd, 170 + rnd.nextInt(60), 170 + rnd.nextInt(60));
            if (!boxesOverlap(a, b)) {
                continue;
            }
            boolean hit = Collide.polygonPolygon(a, b);
            if (hit ? hits >= N / 2 : misses >= N / 2) {
                continue;
            }
            if (hit) {
                hits++;
            } else {
                misses++;
            }
            ra[k] = a;
            rb[k] = b;
            pa[k] = Polygon.of(a);
            pb[k] = Polygon.of(b);
            da[k] = dyn(a);
            db[k] = dyn(b);
            k++;
        }
        for (int i = 0; i < 16; i++) {
            double t = 2 * Math.PI * i / 16;
            float r = i % 2 == 0 ? 40 : 18;
            star[2 * i] = (float) (100 + r * Math.cos(t));
            star[2 * i + 1] = (float) (100 + r * Math.sin(t));
        }
        for (int i = 0; i < N; i++) {
            px[i] = 55 + rnd.nextInt(90);
            py[i] = 55 + rnd.nextInt(90);
            cr[i] = 5 + rnd.nextInt(30);
            for (int j = 0; j < 8; j++) {
                s[8 * i + j] = rnd.nextInt(100);
            }
            ox[i] = rnd.nextInt(400);
            oy[i] = rnd.nextInt(400);
            dx[i] = rnd.nextInt(21) - 10;
            dy[i] = rnd.nextInt(21) - 10;
            if (dx[i] == 0 && dy[i] == 0) {
                dx[i] = 1;
            }
            rx[i] = rnd.nextInt(400);
            ry[i] = rnd.nextInt(400);
            rw[i] = 10 + rnd.nextInt(60);
            rh[i] = 10 + rnd.nextInt(60);
            rays[i] = new Ray(ox[i], oy[i], dx[i], dy[i], 500);
        }
        for (int i = 0; i <= N; i++) {
            rects[i] = new Rect(rnd.nextInt(300), rnd.nextInt(300), 10 + rnd.nextInt(60), 10 + rnd.nextInt(60));
            rectShapes[i] = rects[i];
        }
        for (int i = 0; i < N; i++) {
            circles[i] = new Circle(rnd.nextInt(300), rnd.nextInt(300), 5 + rnd.nextInt(40));
            int x = rnd.nextInt(300), y = rnd.nextInt(300);
            segments[i] = new Segment(x, y, x + rnd.nextInt(121) - 60, y + rnd.nextInt(121) - 60);
            circleShapes[i] = circles[i];
            segmentShapes[i] = segments[i];
            polygonShapes[i] = pa[i];
        }
    }

    /** A convex 8-gon: eight random angles, sorted, on a circle of random radius. */
    static float[] convex8(Random rnd, float cx, float cy) {
        double[] t = new double[8];
        for (int i = 0; i < 8; i++) {
            t[i] = (i + 0.2 + 0.6 * rnd.nextDouble()) * 2 * Math.PI / 8;
        }
        float r = 20 + rnd.nextInt(30);
        float[] xy = new float[16];
        for (int i = 0; i < 8; i++) {
            xy[2 * i] = (float) (cx + r * Math.cos(t[i]));
            xy[2 * i + 1] = (float) (cy + r * Math.sin(t[i]));
        }
        return xy;
    }

    static boolean boxesOverlap(float[] a, float[] b) {
        Rect p = Polygon.of(a).bounds(), q = Polygon.of(b).bounds();
        return Collide.rectRect(p.x(), p.y(), p.w(), p.h(), q.x(), q.y(), q.w(), q.h());
    }

    /** The outline as a dyn4j polygon; angles grow anticlockwise in dyn4j's y-up frame, as it needs. */
    static Convex dyn(float[] xy) {
        Vector2[] v = new Vector2[xy.length / 2];
        for (int i = 0; i < v.length; i++) {
            v[i] = new Vector2(xy[2 * i], xy[2 * i + 1]);
        }
        return new org.dyn4j.geometry.Polygon(v);
    }

    // ---------------------------------------------------------------- convex polygons

    @Benchmark
    public int polygonPolygon_collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            n += Collide.polygonPolygon(ra[i], rb[i]) ? 1 : 0;
        }
        return n;
    }

    @Benchmark
    public int polygonPolygon_overlaps() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            n += pa[i].overlaps(pb[i]) ? 1 : 0;
        }
        return n;
    }

    @Benchmark
    public int polygonPolygon_dyn4jGjk() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            n += gjk.detect(da[i], identity, db[i], identity) ? 1 : 0;
        }
        return n;
    }

    @Benchmark
    public double polygonContact_hitbox() {
        double d = 0;
        for (int i = 0; i < N; i++) {
            Contact c = pa[i].contact(pb[i]);
            d += c == null ? 0 : c.depth();
        }
        return d;
    }

    @Benchmark
    public double polygonContact_dyn4jEpa() {
        double d = 0;
        for (int i = 0; i < N; i++) {
            if (gjk.detect(da[i], identity, db[i], identity, penetration)) {
                d += penetration.getDepth();
            }
        }
        return d;
    }

    @Benchmark
    public int polygonCircle_collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            float[] b = rb[i];
            n += Collide.polygonCircle(ra[i], b[0], b[1], cr[i]) ? 1 : 0;
        }
        return n;
    }

    // ---------------------------------------------------------------- point in concave 16-gon

    @Benchmark
    public int polygonPoint_collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            n += Collide.polygonPoint(star, px[i], py[i]) ? 1 : 0;
        }
        return n;
    }

    /** libGDX's Intersector.isPointInPolygon(float[], ...) form: crossing count with a division. */
    @Benchmark
    public int polygonPoint_gdxForm() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            n += gdxPointInPolygon(star, px[i], py[i]) ? 1 : 0;
        }
        return n;
    }

    static boolean gdxPointInPolygon(float[] polygon, float x, float y) {
        int last = polygon.length - 2;
        boolean oddNodes = false;
        for (int i = 0, j = last; i <= last; j = i, i += 2) {
            float yi = polygon[i + 1], yj = polygon[j + 1];
            if ((yi < y && yj >= y) || (yj < y && yi >= y)) {
                float xi = polygon[i];
                if (xi + (y - yi) / (yj - yi) * (polygon[j] - xi) < x) {
                    oddNodes = !oddNodes;
                }
            }
        }
        return oddNodes;
    }

    // ---------------------------------------------------------------- segments

    @Benchmark
    public int lineLine_collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            int j = 8 * i;
            n += Collide.lineLine(s[j], s[j + 1], s[j + 2], s[j + 3], s[j + 4], s[j + 5], s[j + 6], s[j + 7]) ? 1 : 0;
        }
        return n;
    }

    /** libGDX's Intersector.intersectSegments form (no intersection point asked for). */
    @Benchmark
    public int lineLine_gdxForm() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            int j = 8 * i;
            n += gdxSegments(s[j], s[j + 1], s[j + 2], s[j + 3], s[j + 4], s[j + 5], s[j + 6], s[j + 7]) ? 1 : 0;
        }
        return n;
    }

    static boolean gdxSegments(float x1, float y1, float x2, float y2, float x3, float y3, float x4, float y4) {
        float d = (y4 - y3) * (x2 - x1) - (x4 - x3) * (y2 - y1);
        if (d == 0) {
            return false;
        }
        float yd = y1 - y3, xd = x1 - x3;
        float ua = ((x4 - x3) * yd - (y4 - y3) * xd) / d;
        if (ua < 0 || ua > 1) {
            return false;
        }
        float ub = ((x2 - x1) * yd - (y2 - y1) * xd) / d;
        return !(ub < 0 || ub > 1);
    }

    // ---------------------------------------------------------------- rays

    @Benchmark
    public double rayCircle_distance() {
        double d = 0;
        for (int i = 0; i < N; i++) {
            float t = Ray.distanceToCircle(ox[i], oy[i], dx[i], dy[i], 500, rx[i], ry[i], cr[i]);
            d += t == Float.POSITIVE_INFINITY ? 0 : t;
        }
        return d;
    }

    /** libGDX's Intersector.intersectRayCircle-style form: normalise, project, one sqrt. */
    @Benchmark
    public double rayCircle_gdxForm() {
        double d = 0;
        for (int i = 0; i < N; i++) {
            float len = (float) Math.sqrt(dx[i] * dx[i] + dy[i] * dy[i]);
            float ux = dx[i] / len, uy = dy[i] / len;
            float lx = rx[i] - ox[i], ly = ry[i] - oy[i];
            float tca = lx * ux + ly * uy;
            float d2 = lx * lx + ly * ly - tca * tca;
            float r2 = cr[i] * cr[i];
            if (d2 < r2) {
                float t = tca - (float) Math.sqrt(r2 - d2);
                if (t <= 500 && tca >= 0) {
                    d += Math.max(t, 0);
                }
            }
        }
        return d;
    }

    @Benchmark
    public double rayRect_distance() {
        double d = 0;
        for (int i = 0; i < N; i++) {
            float t = Ray.distanceToRect(ox[i], oy[i], dx[i], dy[i], 500, rx[i], ry[i], rw[i], rh[i]);
            d += t == Float.POSITIVE_INFINITY ? 0 : t;
        }
        return d;
    }

    /** The slab form libGDX's intersectRayBoundsFast uses, in float. */
    @Benchmark
    public double rayRect_gdxForm() {
        double d = 0;
        for (int i = 0; i < N; i++) {
            float len = (float) Math.sqrt(dx[i] * dx[i] + dy[i] * dy[i]);
            float ix = len / dx[i], iy = len / dy[i];
            float t1 = (rx[i] - ox[i]) * ix, t2 = (rx[i] + rw[i] - ox[i]) * ix;
            float t3 = (ry[i] - oy[i]) * iy, t4 = (ry[i] + rh[i] - oy[i]) * iy;
            float lo = Math.max(Math.min(t1, t2), Math.min(t3, t4));
            float hi = Math.min(Math.max(t1, t2), Math.max(t3, t4));
            if (hi >= 0 && lo <= hi && lo <= 500) {
                d += Math.max(lo, 0);
            }
        }
        return d;
    }

    @Benchmark
    public double rayCast_rect() {
        double d = 0;
        for (int i = 0; i < N; i++) {
            var h = rays[i].cast(rects[i]);
            d += h == null ? 0 : h.distance();
        }
        return d;
    }

    // ---------------------------------------------------------------- sweeps

    @Benchmark
    public double sweepCircleRect_hit() {
        double d = 0;
        for (int i = 0; i < N; i++) {
            Hit h = Sweep.timeOfImpact(new Circle(ox[i], oy[i], cr[i]), 10 * dx[i], 10 * dy[i], new Rect(rx[i], ry[i], rw[i], rh[i]));
            d += h == null ? 0 : h.t();
        }
        return d;
    }

    // ---------------------------------------------------------------- rectangles

    @Benchmark
    public int rectRect_collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            Rect a = rects[i], b = rects[i + 1];
            n += Collide.rectRect(a.x(), a.y(), a.w(), a.h(), b.x(), b.y(), b.w(), b.h()) ? 1 : 0;
        }
        return n;
    }

    /** The tutorial's float form, the floor for rectRect. */
    @Benchmark
    public int rectRect_floatForm() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            Rect a = rects[i], b = rects[i + 1];
            n += a.x() + a.w() > b.x() && a.x() < b.x() + b.w() && a.y() + a.h() > b.y() && a.y() < b.y() + b.h() ? 1 : 0;
        }
        return n;
    }

    @Benchmark
    public int rectRect_overlaps() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            n += rectShapes[i].overlaps(rectShapes[i + 1]) ? 1 : 0;
        }
        return n;
    }

    // ---------------------------------------------------------------- Shape.overlaps dispatch against the raw call
    // Measured on fast12b: the instanceof chain itself is not the gap. Dispatching on a's kind
    // first (at most 4 + 4 checks instead of 9) measured no faster (circleRect 6.8 -> 7.2,
    // rectSegment 7.5 -> 7.0 us per 1,024, raw 4.9 and 4.2) and was backed out. With larger
    // JIT inlining limits (-XX:FreqInlineSize=1000 -XX:InlineSmallCode=6000) rectSegment_overlaps
    // matches the raw call (4.4 against 4.3): the gap there is Overlaps.test being too big to
    // inline into the caller's loop. circleRect stayed 7.0 against 4.7 even so (not understood).

    @Benchmark
    public int circleRect_collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            Circle c = circles[i];
            Rect r = rects[i];
            n += Collide.circleRect(c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h()) ? 1 : 0;
        }
        return n;
    }

    @Benchmark
    public int circleRect_overlaps() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            n += circleShapes[i].overlaps(rectShapes[i]) ? 1 : 0;
        }
        return n;
    }

    @Benchmark
    public int circleSegment_collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            Circle c = circles[i];
            Segment s = segments[i];
            n += Collide.lineCircle(s.x1(), s.y1(), s.x2(), s.y2(), c.x(), c.y(), c.r()) ? 1 : 0;
        }
        return n;
    }

    @Benchmark
    public int circleSegment_overlaps() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            n += circleShapes[i].overlaps(segmentShapes[i]) ? 1 : 0;
        }
        return n;
    }

    @Benchmark
    public int rectSegment_collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            Rect r = rects[i];
            Segment s = segments[i];
            n += Collide.lineRect(s.x1(), s.y1(), s.x2(), s.y2(), r.x(), r.y(), r.w(), r.h()) ? 1 : 0;
        }
        return n;
    }

    @Benchmark
    public int rectSegment_overlaps() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            n += rectShapes[i].overlaps(segmentShapes[i]) ? 1 : 0;
        }
        return n;
    }

    @Benchmark
    public int polygonCircle_overlaps() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            float[] b = rb[i];
            n += polygonShapes[i].overlaps(new Circle(b[0], b[1], cr[i])) ? 1 : 0;
        }
        return n;
    }

    @Benchmark
    public int polygonRect_collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            Rect r = rects[i];
            n += Collide.polygonRect(ra[i], r.x() - 100 + 200, r.y() - 100 + 200, r.w(), r.h()) ? 1 : 0;
        }
        return n;
    }

    @Benchmark
    public int polygonRect_overlaps() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            Rect r = rects[i];
            n += polygonShapes[i].overlaps(new Rect(r.x() - 100 + 200, r.y() - 100 + 200, r.w(), r.h())) ? 1 : 0;
        }
        return n;
    }

    /** Contact between a rectangle and a convex polygon (run with -prof gc: only the result allocates). */
    @Benchmark
    public double rectPolygonContact_hitbox() {
        double d = 0;
        for (int i = 0; i < N; i++) {
            float[] b = rb[i];
            Contact c = new Rect(b[0] - 20, b[1] - 20, 40, 40).contact(pa[i]);
            d += c == null ? 0 : c.depth();
        }
        return d;
    }
}
