package hitbox.bench;

import static hitbox.bench.NarrowCase.CAPSULE;
import static hitbox.bench.NarrowCase.CIRCLE;
import static hitbox.bench.NarrowCase.ELLIPSE;
import static hitbox.bench.NarrowCase.OCTAGON;
import static hitbox.bench.NarrowCase.POINT;
import static hitbox.bench.NarrowCase.RECT;
import static hitbox.bench.NarrowCase.SEGMENT;
import static hitbox.bench.NarrowCase.STAR16;
import static hitbox.bench.NarrowCase.TRIANGLE;
import static hitbox.bench.NarrowContender.Role.HITBOX;
import static hitbox.bench.NarrowContender.Role.PEER;
import static hitbox.bench.NarrowContender.Role.SHAPE;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.function.Function;
import java.util.function.IntPredicate;
import java.util.function.IntToDoubleFunction;
import java.util.function.Supplier;

import com.badlogic.gdx.math.Intersector;
import com.badlogic.gdx.math.Vector2;
import com.badlogic.gdx.math.Vector3;
import com.badlogic.gdx.math.collision.BoundingBox;
import hitbox.Collide;
import hitbox.Contact;
import hitbox.Hit;
import hitbox.Hybrid;
import hitbox.Manifold;
import hitbox.PixelMask;
import hitbox.Polygon;
import hitbox.Ray;
import hitbox.RayHit;
import hitbox.Separation;
import hitbox.Shape;
import hitbox.Sweep;
import org.dyn4j.collision.continuous.ConservativeAdvancement;
import org.dyn4j.collision.continuous.TimeOfImpact;
import org.dyn4j.collision.manifold.ClippingManifoldSolver;
import org.dyn4j.collision.manifold.ManifoldPoint;
import org.dyn4j.collision.narrowphase.Gjk;
import org.dyn4j.collision.narrowphase.Penetration;
import org.dyn4j.collision.narrowphase.Raycast;
import org.dyn4j.collision.narrowphase.Sat;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Transform;
import org.jbox2d.collision.Collision;
import org.jbox2d.collision.Distance;
import org.jbox2d.collision.DistanceInput;
import org.jbox2d.collision.DistanceOutput;
import org.jbox2d.collision.RayCastInput;
import org.jbox2d.collision.RayCastOutput;
import org.jbox2d.collision.TimeOfImpact.TOIInput;
import org.jbox2d.collision.TimeOfImpact.TOIOutput;
import org.jbox2d.collision.TimeOfImpact.TOIOutputState;
import org.jbox2d.collision.shapes.PolygonShape;
import org.jbox2d.pooling.normal.DefaultWorldPool;
import org.locationtech.jts.algorithm.RayCrossingCounter;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.Location;
import org.locationtech.jts.geom.prep.PreparedGeometry;
import org.locationtech.jts.geom.prep.PreparedGeometryFactory;
import org.locationtech.jts.operation.distance.DistanceOp;

/**
 * Every question of the narrow-phase table and every contender for it, in table order: the
 * one list that the benchmark ({@link NarrowPhaseBench}), the agreement check and the table
 * ({@link NarrowPhaseTable}) read. Each contender is built from the question's cases and
 * answers one case per call; peers get the cases in their own types (see {@link NarrowPeers}).
 */
final class NarrowQuestions {
    /**
     * A question: its row title, its cases, how far a nudge must move a shape to call a case
     * touching, and how far (in pixels) a peer's distance, depth or time times speed may be off;
     * when {@code relative}, that tolerance is a fraction of the case's size
     * ({@link NarrowCase#size}) instead.
     */
    record Question(String id, String title, Supplier<NarrowCase> cases, float step, double tolerance, boolean relative,
                    List<NarrowContender> contenders) {
    }

    private static final Map<String, Question> ALL = new LinkedHashMap<>();
    private static Question current;

    private NarrowQuestions() {
    }

    /** Every question, in table order. */
    static List<Question> all() {
        return new ArrayList<>(ALL.values());
    }

    /** The contender with this id (question.key). */
    static NarrowContender contender(String id) {
        int dot = id.indexOf('.');
        Question q = ALL.get(id.substring(0, dot));
        for (NarrowContender c : q == null ? List.<NarrowContender>of() : q.contenders()) {
            if (c.id().equals(id)) {
                return c;
            }
        }
        throw new IllegalArgumentException("no contender " + id);
    }

    static Question question(String id) {
        return ALL.get(id);
    }

    // ---------------------------------------------------------------- the list

    private static void question(String id, String title, Supplier<NarrowCase> cases) {
        question(id, title, cases, 0.02f, 0.05);
    }

    /**
     * A sweep: JBox2D's time of impact stops within its skin (0.005 to 0.015 px) and a root
     * finder's tolerance in float, which at pixel coordinates is up to about 0.15 px of the
     * motion; dyn4j's stops within its distance epsilon.
     */
    private static void sweepQuestion(String id, String title, Supplier<NarrowCase> cases) {
        question(id, title, cases, 0.05f, 0.25);
    }

    private static void question(String id, String title, Supplier<NarrowCase> cases, float step, double tolerance) {
        question(id, title, cases, step, tolerance, false);
    }

    private static void question(String id, String title, Supplier<NarrowCase> cases, float step, double tolerance, boolean relative) {
        current = new Question(id, title, cases, step, tolerance, relative, new ArrayList<>());
        ALL.put(id, current);
    }

    private static void bool(String key, NarrowContender.Role role, String call, Function<NarrowCase, IntPredicate> f) {
        current.contenders().add(new NarrowContender.Bool(current.id(), key, role, call, f));
    }

    private static void num(String key, NarrowContender.Role role, String call, Function<NarrowCase, IntToDoubleFunction> f) {
        current.contenders().add(new NarrowContender.Num(current.id(), key, role, call, f));
    }

    private static void depth(String key, NarrowContender.Role role, String call, Function<NarrowCase, NarrowContender.ContactFn> f) {
        current.contenders().add(new NarrowContender.Depth(current.id(), key, role, call, f));
    }

    private static void points(String key, NarrowContender.Role role, String call, Function<NarrowCase, NarrowContender.PointsFn> f) {
        current.contenders().add(new NarrowContender.Points(current.id(), key, role, call, f));
    }

    /** Collide's test on raw floats: the shapes' floats as {@link NarrowCase#raw} gives them. */
    private interface Raw {
        IntPredicate over(float[][] a, float[][] b);
    }

    /** An overlap question between two generators: the raw Collide call and the Shape route. */
    private static void overlap(String id, String title, long seed, NarrowCase.Gen first, NarrowCase.Gen second,
                                String call, String shapeCall, Raw raw) {
        question(id, title, () -> NarrowCase.pairs(NarrowCase.Kind.OVERLAP, seed, first, second));
        bool("collide", HITBOX, call, q -> raw.over(q.ra, q.rb));
        shapeOverlaps(shapeCall);
    }

    /** A point-in-shape question: the raw Collide call and {@code Shape.contains}. */
    private static void pointIn(String id, String title, long seed, NarrowCase.Gen shape, String call, String shapeCall, Raw raw) {
        question(id, title, () -> NarrowCase.pairs(NarrowCase.Kind.OVERLAP, seed, shape, POINT));
        bool("collide", HITBOX, call, q -> raw.over(q.ra, q.rb));
        shapeContains(shapeCall);
    }

    /**
     * An overlap question that Collide has no raw form for (issue 30 left ellipses and capsules
     * to the shapes): {@code Shape.overlaps} is Hitbox's call, timed against the peers.
     */
    private static void overlapOfShapes(String id, String title, long seed, NarrowCase.Gen first, NarrowCase.Gen second, String shapeCall) {
        question(id, title, () -> NarrowCase.pairs(NarrowCase.Kind.OVERLAP, seed, first, second));
        bool("shape", HITBOX, shapeCall, q -> {
            Shape[] a = q.a, b = q.b;
            return i -> a[i].overlaps(b[i]);
        });
    }

    /** A point-in-shape question that Collide has no raw form for: {@code Shape.contains} is Hitbox's call. */
    private static void pointInShape(String id, String title, long seed, NarrowCase.Gen shape, String shapeCall) {
        question(id, title, () -> NarrowCase.pairs(NarrowCase.Kind.OVERLAP, seed, shape, POINT));
        bool("shape", HITBOX, shapeCall, q -> {
            Shape[] a = q.a;
            float[][] b = q.rb;
            return i -> a[i].contains(b[i][0], b[i][1]);
        });
    }

    /** Hitbox through {@code Shape.overlaps}, the same for every pair. */
    private static void shapeOverlaps(String call) {
        bool("shape", SHAPE, call, q -> {
            Shape[] a = q.a, b = q.b;
            return i -> a[i].overlaps(b[i]);
        });
    }

    /** Hitbox through {@code Shape.contains}, for the point questions. */
    private static void shapeContains(String call) {
        bool("shape", SHAPE, call, q -> {
            Shape[] a = q.a;
            float[][] b = q.rb;
            return i -> a[i].contains(b[i][0], b[i][1]);
        });
    }

    /** dyn4j's GJK on the two shapes (its fastest test for curved shapes and polygons alike). */
    private static void dyn4jGjk() {
        bool("dyn4jGjk", PEER, "dyn4j Gjk.detect", q -> {
            Dyn4j d = new Dyn4j(q);
            Gjk gjk = new Gjk();
            return i -> gjk.detect(d.a[i], d.ta[i], d.b[i], d.tb[i]);
        });
    }

    /** libGDX's separating axis test on the two outlines. */
    private static void gdxConvex() {
        bool("gdx", PEER, "libGDX Intersector.overlapConvexPolygons", q -> {
            var a = each(q, true, NarrowPeers::gdxPolygon, com.badlogic.gdx.math.Polygon[]::new);
            var b = each(q, false, NarrowPeers::gdxPolygon, com.badlogic.gdx.math.Polygon[]::new);
            return i -> Intersector.overlapConvexPolygons(a[i], b[i]);
        });
    }

    private static void dyn4jSat() {
        bool("dyn4jSat", PEER, "dyn4j Sat.detect", q -> {
            Dyn4j d = new Dyn4j(q);
            Sat sat = new Sat();
            return i -> sat.detect(d.a[i], d.ta[i], d.b[i], d.tb[i]);
        });
    }

    /** Both shapes of every case in dyn4j. */
    private static final class Dyn4j {
        final Convex[] a = new Convex[NarrowCase.N], b = new Convex[NarrowCase.N];
        final Transform[] ta = new Transform[NarrowCase.N], tb = new Transform[NarrowCase.N];

        Dyn4j(NarrowCase q) {
            for (int i = 0; i < NarrowCase.N; i++) {
                if (q.a[i] != null) {
                    a[i] = NarrowPeers.dyn4j(q.a[i]);
                    ta[i] = NarrowPeers.dyn4jAt(q.a[i]);
                }
                b[i] = NarrowPeers.dyn4j(q.b[i]);
                tb[i] = NarrowPeers.dyn4jAt(q.b[i]);
            }
        }
    }

    private static <T> T[] each(NarrowCase q, boolean first, Function<Shape, T> convert, Function<Integer, T[]> array) {
        T[] out = array.apply(NarrowCase.N);
        for (int i = 0; i < NarrowCase.N; i++) {
            out[i] = convert.apply(first ? q.a[i] : q.b[i]);
        }
        return out;
    }

    private static com.badlogic.gdx.math.Circle gdxCircle(Shape s) {
        hitbox.Circle c = (hitbox.Circle) s;
        return new com.badlogic.gdx.math.Circle(c.x(), c.y(), c.r());
    }

    private static com.badlogic.gdx.math.Rectangle gdxRect(Shape s) {
        hitbox.Rect r = (hitbox.Rect) s;
        return new com.badlogic.gdx.math.Rectangle(r.x(), r.y(), r.w(), r.h());
    }

    private static final double INF = Double.POSITIVE_INFINITY;

    static {
        // ---- the questions of the table first
        overlap("poly8", "convex 8-gon vs 8-gon, overlap", 1, OCTAGON, OCTAGON, "Collide.polygonPolygon", "Polygon.overlaps",
                (a, b) -> i -> Collide.polygonPolygon(a[i], b[i]));
        dyn4jGjk();
        dyn4jSat();
        gdxConvex();
        bool("jbox2d", PEER, "JBox2D Collision.testOverlap", q -> {
            var a = each(q, true, NarrowPeers::jbox2d, org.jbox2d.collision.shapes.Shape[]::new);
            var b = each(q, false, NarrowPeers::jbox2d, org.jbox2d.collision.shapes.Shape[]::new);
            Collision collision = new Collision(new DefaultWorldPool(16, 16));
            org.jbox2d.common.Transform identity = new org.jbox2d.common.Transform();
            identity.setIdentity();
            return i -> collision.testOverlap(a[i], 0, b[i], 0, identity, identity);
        });

        question("poly8Contact", "convex 8-gon vs 8-gon, normal + depth", () -> NarrowCase.pairs(NarrowCase.Kind.CONTACT, 2, OCTAGON, OCTAGON));
        depth("between", HITBOX, "a.contact(b)", q -> contactOf(q.a, q.b));
        dyn4jContact("dyn4jGjk", "dyn4j Gjk.detect (GJK + EPA)", new Gjk());
        dyn4jContact("dyn4jSat", "dyn4j Sat.detect", new Sat());
        depth("gdx", PEER, "libGDX overlapConvexPolygons(.., mtv)", q -> {
            var a = each(q, true, NarrowPeers::gdxPolygon, com.badlogic.gdx.math.Polygon[]::new);
            var b = each(q, false, NarrowPeers::gdxPolygon, com.badlogic.gdx.math.Polygon[]::new);
            Intersector.MinimumTranslationVector mtv = new Intersector.MinimumTranslationVector();
            return (i, out) -> {
                if (!Intersector.overlapConvexPolygons(a[i], b[i], mtv)) return false;
                // libGDX's normal pushes the first polygon out of the second: Hitbox's, turned round
                out[0] = mtv.depth;
                out[1] = -mtv.normal.x;
                out[2] = -mtv.normal.y;
                return true;
            };
        });

        overlap("circlePoly8", "circle vs convex 8-gon", 3, OCTAGON, CIRCLE, "Collide.polygonCircle", "Polygon.overlaps(Circle)",
                (a, b) -> i -> Collide.polygonCircle(a[i], b[i][0], b[i][1], b[i][2]));
        dyn4jGjk();
        dyn4jSat();

        pointIn("star16Point", "point in concave 16-gon", 4, STAR16, "Collide.polygonPoint", "Polygon.contains",
                (a, b) -> i -> Collide.polygonPoint(a[i], b[i][0], b[i][1]));
        bool("gdx", PEER, "libGDX Intersector.isPointInPolygon", q -> {
            float[][] a = q.ra, b = q.rb;
            return i -> Intersector.isPointInPolygon(a[i], 0, a[i].length, b[i][0], b[i][1]);
        });
        bool("jts", PEER, "JTS RayCrossingCounter.locatePointInRing", q -> {
            Coordinate[][] rings = new Coordinate[NarrowCase.N][];
            Coordinate[] points = new Coordinate[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                float[] xy = q.ra[i];
                rings[i] = new Coordinate[xy.length / 2 + 1];
                for (int k = 0; k <= xy.length / 2; k++) {
                    int j = k % (xy.length / 2);
                    rings[i][k] = new Coordinate(xy[2 * j], xy[2 * j + 1]);
                }
                points[i] = new Coordinate(q.rb[i][0], q.rb[i][1]);
            }
            // JTS says BOUNDARY for a point on the outline: Hitbox's open set is INTERIOR only
            return i -> RayCrossingCounter.locatePointInRing(points[i], rings[i]) == Location.INTERIOR;
        });

        overlap("lineLine", "segment vs segment", 5, SEGMENT, SEGMENT, "Collide.lineLine", "Segment.overlaps",
                (a, b) -> i -> Collide.lineLine(a[i][0], a[i][1], a[i][2], a[i][3], b[i][0], b[i][1], b[i][2], b[i][3]));
        bool("gdx", PEER, "libGDX Intersector.intersectSegments", q -> {
            float[][] a = q.ra, b = q.rb;
            return i -> Intersector.intersectSegments(a[i][0], a[i][1], a[i][2], a[i][3], b[i][0], b[i][1], b[i][2], b[i][3], null);
        });

        question("rayCircle", "ray vs circle, distance", () -> NarrowCase.rays(6, CIRCLE));
        num("raw", HITBOX, "Ray.distanceToCircle", q -> {
            float[][] v = q.v, b = q.rb;
            return i -> Ray.distanceToCircle(v[i][0], v[i][1], v[i][2], v[i][3], Float.POSITIVE_INFINITY, b[i][0], b[i][1], b[i][2]);
        });
        rayCast();
        num("gdx", PEER, "libGDX Intersector.intersectRaySphere (z = 0)", q -> {
            var rays = gdxRays(q);
            Vector3[] centres = new Vector3[NarrowCase.N];
            float[] radii = new float[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                centres[i] = new Vector3(q.rb[i][0], q.rb[i][1], 0);
                radii[i] = q.rb[i][2];
            }
            Vector3 at = new Vector3();
            return i -> Intersector.intersectRaySphere(rays[i], centres[i], radii[i], at) ? at.dst(rays[i].origin) : INF;
        });
        jbox2dRay();

        question("rayRect", "ray vs rect, distance", () -> NarrowCase.rays(7, RECT));
        num("raw", HITBOX, "Ray.distanceToRect", q -> {
            float[][] v = q.v, b = q.rb;
            return i -> Ray.distanceToRect(v[i][0], v[i][1], v[i][2], v[i][3], Float.POSITIVE_INFINITY, b[i][0], b[i][1], b[i][2], b[i][3]);
        });
        rayCast();
        num("gdx", PEER, "libGDX Intersector.intersectRayBounds (z = 0)", q -> {
            var rays = gdxRays(q);
            BoundingBox[] boxes = new BoundingBox[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                float[] r = q.rb[i];
                boxes[i] = new BoundingBox(new Vector3(r[0], r[1], 0), new Vector3(r[0] + r[2], r[1] + r[3], 0));
            }
            Vector3 at = new Vector3();
            return i -> Intersector.intersectRayBounds(rays[i], boxes[i], at) ? at.dst(rays[i].origin) : INF;
        });
        jbox2dRay();

        sweepQuestion("sweepCircleRect", "swept circle vs rect, time of impact", () -> NarrowCase.sweeps(8, CIRCLE, RECT));
        sweepShape();
        jbox2dToi();
        dyn4jToi();

        overlap("rectRect", "two rects", 9, RECT, RECT, "Collide.rectRect", "Rect.overlaps",
                (a, b) -> i -> Collide.rectRect(a[i][0], a[i][1], a[i][2], a[i][3], b[i][0], b[i][1], b[i][2], b[i][3]));
        bool("gdx", PEER, "libGDX Rectangle.overlaps", q -> {
            var a = each(q, true, NarrowQuestions::gdxRect, com.badlogic.gdx.math.Rectangle[]::new);
            var b = each(q, false, NarrowQuestions::gdxRect, com.badlogic.gdx.math.Rectangle[]::new);
            return i -> a[i].overlaps(b[i]);
        });

        // ---- the rest of Collide
        overlap("circleCircle", "circle vs circle", 10, CIRCLE, CIRCLE, "Collide.circleCircle", "Circle.overlaps",
                (a, b) -> i -> Collide.circleCircle(a[i][0], a[i][1], a[i][2], b[i][0], b[i][1], b[i][2]));
        bool("gdx", PEER, "libGDX Circle.overlaps", q -> {
            var a = each(q, true, NarrowQuestions::gdxCircle, com.badlogic.gdx.math.Circle[]::new);
            var b = each(q, false, NarrowQuestions::gdxCircle, com.badlogic.gdx.math.Circle[]::new);
            return i -> a[i].overlaps(b[i]);
        });

        pointIn("circlePoint", "point in circle", 11, CIRCLE, "Collide.circlePoint", "Circle.contains",
                (a, b) -> i -> Collide.circlePoint(a[i][0], a[i][1], a[i][2], b[i][0], b[i][1]));
        bool("gdx", PEER, "libGDX Circle.contains", q -> {
            var a = each(q, true, NarrowQuestions::gdxCircle, com.badlogic.gdx.math.Circle[]::new);
            float[][] b = q.rb;
            return i -> a[i].contains(b[i][0], b[i][1]);
        });

        pointIn("rectPoint", "point in rect", 12, RECT, "Collide.rectPoint", "Rect.contains",
                (a, b) -> i -> Collide.rectPoint(a[i][0], a[i][1], a[i][2], a[i][3], b[i][0], b[i][1]));
        bool("gdx", PEER, "libGDX Rectangle.contains", q -> {
            var a = each(q, true, NarrowQuestions::gdxRect, com.badlogic.gdx.math.Rectangle[]::new);
            float[][] b = q.rb;
            return i -> a[i].contains(b[i][0], b[i][1]);
        });

        overlap("circleRect", "circle vs rect", 13, CIRCLE, RECT, "Collide.circleRect", "Circle.overlaps(Rect)",
                (a, b) -> i -> Collide.circleRect(a[i][0], a[i][1], a[i][2], b[i][0], b[i][1], b[i][2], b[i][3]));
        bool("gdx", PEER, "libGDX Intersector.overlaps(Circle, Rectangle)", q -> {
            var a = each(q, true, NarrowQuestions::gdxCircle, com.badlogic.gdx.math.Circle[]::new);
            var b = each(q, false, NarrowQuestions::gdxRect, com.badlogic.gdx.math.Rectangle[]::new);
            return i -> Intersector.overlaps(a[i], b[i]);
        });

        overlap("lineCircle", "segment vs circle", 14, SEGMENT, CIRCLE, "Collide.lineCircle", "Segment.overlaps(Circle)",
                (a, b) -> i -> Collide.lineCircle(a[i][0], a[i][1], a[i][2], a[i][3], b[i][0], b[i][1], b[i][2]));
        bool("gdx", PEER, "libGDX Intersector.intersectSegmentCircle", q -> {
            Vector2[] s = new Vector2[NarrowCase.N], e = new Vector2[NarrowCase.N], c = new Vector2[NarrowCase.N];
            float[] r2 = new float[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                float[] a = q.ra[i], b = q.rb[i];
                s[i] = new Vector2(a[0], a[1]);
                e[i] = new Vector2(a[2], a[3]);
                c[i] = new Vector2(b[0], b[1]);
                r2[i] = b[2] * b[2];
            }
            return i -> Intersector.intersectSegmentCircle(s[i], e[i], c[i], r2[i]);
        });
        dyn4jGjk();

        overlap("lineRect", "segment vs rect", 15, SEGMENT, RECT, "Collide.lineRect", "Segment.overlaps(Rect)",
                (a, b) -> i -> Collide.lineRect(a[i][0], a[i][1], a[i][2], a[i][3], b[i][0], b[i][1], b[i][2], b[i][3]));
        bool("gdx", PEER, "libGDX Intersector.intersectSegmentRectangle", q -> {
            float[][] a = q.ra;
            var b = each(q, false, NarrowQuestions::gdxRect, com.badlogic.gdx.math.Rectangle[]::new);
            return i -> Intersector.intersectSegmentRectangle(a[i][0], a[i][1], a[i][2], a[i][3], b[i]);
        });
        dyn4jGjk();

        overlap("polygonRect", "convex 8-gon vs rect", 16, OCTAGON, RECT, "Collide.polygonRect", "Polygon.overlaps(Rect)",
                (a, b) -> i -> Collide.polygonRect(a[i], b[i][0], b[i][1], b[i][2], b[i][3]));
        dyn4jGjk();
        dyn4jSat();
        gdxConvex();

        overlap("polygonLine", "convex 8-gon vs segment", 17, OCTAGON, SEGMENT, "Collide.polygonLine", "Polygon.overlaps(Segment)",
                (a, b) -> i -> Collide.polygonLine(a[i], b[i][0], b[i][1], b[i][2], b[i][3]));
        dyn4jGjk();

        pointIn("trianglePoint", "point in triangle", 18, TRIANGLE, "Collide.trianglePoint", "Polygon.contains",
                (a, b) -> i -> Collide.trianglePoint(a[i][0], a[i][1], a[i][2], a[i][3], a[i][4], a[i][5], b[i][0], b[i][1]));
        bool("gdx", PEER, "libGDX Intersector.isPointInTriangle", q -> {
            float[][] a = q.ra, b = q.rb;
            return i -> Intersector.isPointInTriangle(b[i][0], b[i][1], a[i][0], a[i][1], a[i][2], a[i][3], a[i][4], a[i][5]);
        });

        pointInShape("ellipsePoint", "point in ellipse", 19, ELLIPSE, "Ellipse.contains");
        bool("gdx", PEER, "libGDX Ellipse.contains", q -> {
            com.badlogic.gdx.math.Ellipse[] a = new com.badlogic.gdx.math.Ellipse[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                float[] e = q.ra[i];
                a[i] = new com.badlogic.gdx.math.Ellipse(e[0], e[1], 2 * e[2], 2 * e[3]);
            }
            float[][] b = q.rb;
            return i -> a[i].contains(b[i][0], b[i][1]);
        });

        overlapOfShapes("ellipseCircle", "ellipse vs circle", 20, ELLIPSE, CIRCLE, "Ellipse.overlaps(Circle)");
        dyn4jGjk();

        overlapOfShapes("ellipseRect", "ellipse vs rect", 21, ELLIPSE, RECT, "Ellipse.overlaps(Rect)");
        dyn4jGjk();

        overlapOfShapes("ellipseLine", "ellipse vs segment", 22, ELLIPSE, SEGMENT, "Ellipse.overlaps(Segment)");
        dyn4jGjk();

        overlapOfShapes("ellipseEllipse", "ellipse vs ellipse", 23, ELLIPSE, ELLIPSE, "Ellipse.overlaps");
        dyn4jGjk();

        overlapOfShapes("polygonEllipse", "convex 8-gon vs ellipse", 24, OCTAGON, ELLIPSE, "Polygon.overlaps(Ellipse)");
        dyn4jGjk();

        overlapOfShapes("ellipseCapsule", "ellipse vs capsule", 25, ELLIPSE, CAPSULE, "Ellipse.overlaps(Capsule)");
        dyn4jGjk();

        pointInShape("capsulePoint", "point in capsule", 26, CAPSULE, "Capsule.contains");
        bool("dyn4j", PEER, "dyn4j Capsule.contains", q -> {
            Convex[] a = each(q, true, NarrowPeers::dyn4j, Convex[]::new);
            Transform[] t = each(q, true, NarrowPeers::dyn4jAt, Transform[]::new);
            org.dyn4j.geometry.Vector2[] p = new org.dyn4j.geometry.Vector2[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                p[i] = new org.dyn4j.geometry.Vector2(q.rb[i][0], q.rb[i][1]);
            }
            return i -> a[i].contains(p[i], t[i], false);
        });

        overlapOfShapes("capsuleCircle", "capsule vs circle", 27, CAPSULE, CIRCLE, "Capsule.overlaps(Circle)");
        dyn4jGjk();

        overlapOfShapes("capsuleRect", "capsule vs rect", 28, CAPSULE, RECT, "Capsule.overlaps(Rect)");
        dyn4jGjk();

        overlapOfShapes("capsuleLine", "capsule vs segment", 29, CAPSULE, SEGMENT, "Capsule.overlaps(Segment)");
        dyn4jGjk();

        overlapOfShapes("capsuleCapsule", "capsule vs capsule", 30, CAPSULE, CAPSULE, "Capsule.overlaps");
        dyn4jGjk();

        overlapOfShapes("polygonCapsule", "convex 8-gon vs capsule", 31, OCTAGON, CAPSULE, "Polygon.overlaps(Capsule)");
        dyn4jGjk();

        // ---- Contact
        question("circleCircleContact", "circle vs circle, normal + depth", () -> NarrowCase.pairs(NarrowCase.Kind.CONTACT, 40, CIRCLE, CIRCLE));
        depth("shape", HITBOX, "Circle.contact", q -> contactOf(q.a, q.b));
        dyn4jContact("dyn4jSat", "dyn4j Sat.detect", new Sat());

        question("circleRectContact", "circle vs rect, normal + depth", () -> NarrowCase.pairs(NarrowCase.Kind.CONTACT, 41, CIRCLE, RECT));
        depth("shape", HITBOX, "Circle.contact(Rect)", q -> contactOf(q.a, q.b));
        dyn4jContact("dyn4jSat", "dyn4j Sat.detect", new Sat());

        question("rectRectContact", "rect vs rect, normal + depth", () -> NarrowCase.pairs(NarrowCase.Kind.CONTACT, 42, RECT, RECT));
        depth("shape", HITBOX, "Rect.contact", q -> contactOf(q.a, q.b));
        dyn4jContact("dyn4jSat", "dyn4j Sat.detect", new Sat());

        question("polygonCircleContact", "convex 8-gon vs circle, normal + depth", () -> NarrowCase.pairs(NarrowCase.Kind.CONTACT, 43, OCTAGON, CIRCLE));
        depth("between", HITBOX, "a.contact(b)", q -> contactOf(q.a, q.b));
        dyn4jContact("dyn4jSat", "dyn4j Sat.detect", new Sat());
        dyn4jContact("dyn4jGjk", "dyn4j Gjk.detect (GJK + EPA)", new Gjk());

        // ---- Ray, the other shapes
        question("raySegment", "ray vs segment, distance", () -> NarrowCase.rays(50, SEGMENT));
        num("raw", HITBOX, "Ray.distanceToSegment", q -> {
            float[][] v = q.v, b = q.rb;
            return i -> Ray.distanceToSegment(v[i][0], v[i][1], v[i][2], v[i][3], Float.POSITIVE_INFINITY, b[i][0], b[i][1], b[i][2], b[i][3]);
        });
        rayCast();
        jbox2dRay();

        question("rayPoly8", "ray vs convex 8-gon, distance", () -> NarrowCase.rays(51, OCTAGON));
        rayCast();
        jbox2dRay();
        num("dyn4j", PEER, "dyn4j Gjk.raycast", q -> {
            Dyn4j d = new Dyn4j(q);
            org.dyn4j.geometry.Ray[] rays = new org.dyn4j.geometry.Ray[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                float[] v = q.v[i];
                rays[i] = new org.dyn4j.geometry.Ray(new org.dyn4j.geometry.Vector2(v[0], v[1]), new org.dyn4j.geometry.Vector2(v[2], v[3]));
            }
            Gjk gjk = new Gjk();
            Raycast out = new Raycast();
            return i -> gjk.raycast(rays[i], 0, d.b[i], d.tb[i], out) ? out.getDistance() : INF;
        });

        // ---- Sweep, the other pairs
        sweepQuestion("sweepRectRect", "swept rect vs rect, time of impact", () -> NarrowCase.sweeps(60, RECT, RECT));
        num("raw", HITBOX, "Sweep.rectRect", q -> {
            float[][] a = q.ra, b = q.rb, v = q.v;
            return i -> Sweep.rectRect(a[i][0], a[i][1], a[i][2], a[i][3], v[i][0], v[i][1], b[i][0], b[i][1], b[i][2], b[i][3]);
        });
        sweepShape();
        jbox2dToi();

        sweepQuestion("sweepCircleCircle", "swept circle vs circle, time of impact", () -> NarrowCase.sweeps(61, CIRCLE, CIRCLE));
        sweepShape();
        jbox2dToi();

        sweepQuestion("sweepPoly8", "swept 8-gon vs 8-gon, time of impact", () -> NarrowCase.sweeps(62, OCTAGON, OCTAGON));
        // A straight sweep: the turning sweep (ShapesBench's turning blade, against dyn4j) is a
        // conservative bound within its tolerance, not the largest clear float t.
        num("shape", HITBOX, "Sweep.timeOfImpact(Shape ..)", q -> {
            Shape[] a = q.a, b = q.b;
            float[][] v = q.v;
            return i -> time(Sweep.timeOfImpact(a[i], v[i][0], v[i][1], b[i]));
        });
        jbox2dToi();
        dyn4jToi();

        // ---- PixelMask and Hybrid: no peer has them
        question("maskOverlap", "two 64 x 64 pixel masks", NarrowQuestions::noShapes);
        bool("overlaps", HITBOX, "PixelMask.overlaps", q -> {
            Masks m = new Masks();
            return i -> m.a[i].overlaps(m.b[i], m.dx[i], m.dy[i]);
        });
        question("maskHybrid", "two 64 x 64 pixel masks, box then pixels", NarrowQuestions::noShapes);
        bool("check", HITBOX, "Hybrid.check(PixelMask ..)", q -> {
            Masks m = new Masks();
            return i -> Hybrid.check(m.a[i], 0, 0, m.b[i], m.dx[i], m.dy[i]).overlaps();
        });
        question("hybridPoly8", "convex 8-gon vs 8-gon, box then shapes", () -> NarrowCase.pairs(NarrowCase.Kind.OVERLAP, 70, OCTAGON, OCTAGON));
        bool("check", HITBOX, "Hybrid.check(Shape, Shape)", q -> {
            Shape[] a = q.a, b = q.b;
            return i -> Hybrid.check(a[i], b[i]).overlaps();
        });

        // ---- issue 23: the distance between shapes apart, one shape in another, contact points,
        // two bodies that both move and turn. The Hitbox call first (raw where Hitbox has a raw form).
        // A distance agrees to 1e-4 of the case's size (NarrowCase.size): JBox2D works in float.
        question("sepPoly8", "separation, convex 8-gon vs 8-gon (apart)", () -> NarrowCase.apart(90, OCTAGON, OCTAGON), 0.02f, 1e-4, true);
        separationShape();
        dyn4jDistance();
        jbox2dDistance();
        jtsDistance();

        question("sepCirclePoly8", "separation, circle vs convex 8-gon", () -> NarrowCase.apart(91, OCTAGON, CIRCLE), 0.02f, 1e-4, true);
        separationShape();
        dyn4jDistance();
        jbox2dDistance();
        jtsDistance();

        question("sepCircleCircle", "separation, circle vs circle", () -> NarrowCase.apart(92, CIRCLE, CIRCLE), 0.02f, 1e-4, true);
        num("raw", HITBOX, "Separation.circleCircle", q -> {
            float[][] a = q.ra, b = q.rb;
            return i -> Separation.circleCircle(a[i][0], a[i][1], a[i][2], b[i][0], b[i][1], b[i][2]);
        });
        separationShape();
        dyn4jDistance();
        jbox2dDistance();
        jtsDistance();

        // Containment: Hitbox's rule counts a shape touching the outline from inside as held.
        question("containRect", "rect in rect", () -> NarrowCase.containing(93, RECT, NarrowCase.RECT_IN_RECT));
        shapeContainsShape("Rect.contains(Shape)");
        bool("gdx", PEER, "libGDX Rectangle.contains(Rectangle)", q -> {
            var a = each(q, true, NarrowQuestions::gdxRect, com.badlogic.gdx.math.Rectangle[]::new);
            var b = each(q, false, NarrowQuestions::gdxRect, com.badlogic.gdx.math.Rectangle[]::new);
            return i -> a[i].contains(b[i]);
        });
        dyn4jContains();
        jtsCovers();

        question("containCircle", "circle in circle", () -> NarrowCase.containing(94, CIRCLE, NarrowCase.CIRCLE_IN_CIRCLE));
        shapeContainsShape("Circle.contains(Shape)");
        bool("gdx", PEER, "libGDX Circle.contains(Circle)", q -> {
            var a = each(q, true, NarrowQuestions::gdxCircle, com.badlogic.gdx.math.Circle[]::new);
            var b = each(q, false, NarrowQuestions::gdxCircle, com.badlogic.gdx.math.Circle[]::new);
            return i -> a[i].contains(b[i]);
        });
        dyn4jContains();

        question("containPoly8", "convex 8-gon in 8-gon", () -> NarrowCase.containing(95, OCTAGON, NarrowCase.POLY_IN_POLY));
        bool("contains", HITBOX, "Polygon.contains(Shape)", q -> {
            Shape[] a = q.a, b = q.b;
            return i -> a[i].contains(b[i]);
        });
        dyn4jContains();
        jtsCovers();

        // Contact points: the count, the depth and normal (which must agree as a.contact(b)'s do),
        // and the points, each an end of the incident edge clipped, to 0.05 px.
        question("manifoldPoly8", "manifold, convex 8-gon vs 8-gon", () -> NarrowCase.pairs(NarrowCase.Kind.CONTACT, 96, OCTAGON, OCTAGON));
        manifolds();
        question("manifoldBoxes", "manifold, rect vs rect (turned boxes)", () -> NarrowCase.pairs(NarrowCase.Kind.CONTACT, 97, NarrowCase.BOX, NarrowCase.BOX));
        manifolds();

        // Two bodies that both move and turn about their centroids: times compared to 0.25 px of
        // the fastest any point of one gains on the other (NarrowCase.scale).
        sweepQuestion("turnTwoPoly8", "turning sweep, two 8-gons both moving and turning", () -> NarrowCase.turning(98));
        num("turning", HITBOX, "Sweep.turningTimeOfImpact(Polygon .., Polygon ..)", q -> {
            Shape[] a = q.a, b = q.b;
            float[][] v = q.v;
            return i -> {
                float[] m = v[i];
                return time(Sweep.turningTimeOfImpact((Polygon) a[i], m[0], m[1], m[2], m[3], m[4], (Polygon) b[i], m[5], m[6], m[7], m[8], m[9]));
            };
        });
        num("dyn4j", PEER, "dyn4j ConservativeAdvancement (turning)", q -> {
            Convex[] a = new Convex[NarrowCase.N], b = new Convex[NarrowCase.N];
            Transform[] ta = new Transform[NarrowCase.N], tb = new Transform[NarrowCase.N];
            org.dyn4j.geometry.Vector2[] va = new org.dyn4j.geometry.Vector2[NarrowCase.N], vb = new org.dyn4j.geometry.Vector2[NarrowCase.N];
            double[] turnA = new double[NarrowCase.N], turnB = new double[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                float[] m = q.v[i];
                // each body about its pivot, which dyn4j turns it about (its transform's origin)
                a[i] = NarrowPeers.dyn4jAbout((Polygon) q.a[i], m[0], m[1]);
                b[i] = NarrowPeers.dyn4jAbout((Polygon) q.b[i], m[5], m[6]);
                ta[i] = new Transform();
                ta[i].translate(m[0], m[1]);
                tb[i] = new Transform();
                tb[i].translate(m[5], m[6]);
                va[i] = new org.dyn4j.geometry.Vector2(m[2], m[3]);
                vb[i] = new org.dyn4j.geometry.Vector2(m[7], m[8]);
                turnA[i] = m[4];
                turnB[i] = m[9];
            }
            ConservativeAdvancement ca = new ConservativeAdvancement();
            TimeOfImpact out = new TimeOfImpact();
            return i -> ca.getTimeOfImpact(a[i], ta[i], va[i], turnA[i], b[i], tb[i], vb[i], turnB[i], out) ? out.getTime() : INF;
        });
        num("jbox2d", PEER, "JBox2D TimeOfImpact (turning sweeps)", q -> {
            DefaultWorldPool pool = new DefaultWorldPool(16, 16);
            TOIInput[] in = new TOIInput[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                float[] m = q.v[i];
                in[i] = new TOIInput();
                in[i].proxyA.set(NarrowPeers.jbox2dAbout((Polygon) q.a[i], m[0], m[1]), 0);
                in[i].proxyB.set(NarrowPeers.jbox2dAbout((Polygon) q.b[i], m[5], m[6]), 0);
                in[i].sweepA.c0.set(m[0], m[1]);
                in[i].sweepA.c.set(m[0] + m[2], m[1] + m[3]);
                in[i].sweepA.a = m[4];
                in[i].sweepB.c0.set(m[5], m[6]);
                in[i].sweepB.c.set(m[5] + m[7], m[6] + m[8]);
                in[i].sweepB.a = m[9];
                in[i].tMax = 1;
            }
            org.jbox2d.collision.TimeOfImpact toi = new org.jbox2d.collision.TimeOfImpact(pool);
            TOIOutput out = new TOIOutput();
            return i -> {
                toi.timeOfImpact(out, in[i]);
                return switch (out.state) {
                    case TOUCHING -> out.t;
                    case OVERLAPPED -> 0;
                    case SEPARATED -> INF;
                    default -> Double.NaN; // FAILED: its root finder gave up
                };
            };
        });
    }

    // ---------------------------------------------------------------- issue 23's contenders

    /** Hitbox's separation through {@code Separation.between}, beside the raw form. */
    private static void separationShape() {
        // The Hitbox row where the question has no raw form (issue 30 left one, Separation.circleCircle).
        num("shape", current.contenders().isEmpty() ? HITBOX : SHAPE, "Separation.between", q -> {
            Shape[] a = q.a, b = q.b;
            return i -> {
                Separation s = Separation.between(a[i], b[i]);
                return s == null ? INF : s.distance();
            };
        });
    }

    /** dyn4j's GJK distance: false (no answer) when the shapes overlap, and it may say so when they touch. */
    private static void dyn4jDistance() {
        num("dyn4j", PEER, "dyn4j Gjk.distance", q -> {
            Dyn4j d = new Dyn4j(q);
            Gjk gjk = new Gjk();
            org.dyn4j.collision.narrowphase.Separation out = new org.dyn4j.collision.narrowphase.Separation();
            return i -> gjk.distance(d.a[i], d.ta[i], d.b[i], d.tb[i], out) ? out.getDistance() : INF;
        });
    }

    /**
     * JBox2D's GJK distance (Box2D's b2Distance), in float, on its distance proxies with the
     * polygons' 0.01 skin taken off (radius 0) and a circle's radius kept.
     */
    private static void jbox2dDistance() {
        num("jbox2d", PEER, "JBox2D Distance.distance", q -> {
            DistanceInput[] in = new DistanceInput[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                in[i] = new DistanceInput();
                in[i].proxyA.set(NarrowPeers.jbox2d(q.a[i]), 0);
                in[i].proxyB.set(NarrowPeers.jbox2d(q.b[i]), 0);
                if (!(q.a[i] instanceof hitbox.Circle)) in[i].proxyA.m_radius = 0;
                if (!(q.b[i] instanceof hitbox.Circle)) in[i].proxyB.m_radius = 0;
                in[i].useRadii = true;
            }
            Distance distance = new Distance();
            Distance.SimplexCache cache = new Distance.SimplexCache();
            DistanceOutput out = new DistanceOutput();
            return i -> {
                cache.count = 0;
                distance.distance(out, cache, in[i]);
                return out.distance;
            };
        });
    }

    /** JTS's distance between the geometries; a circle is its centre, its radius taken off after. */
    private static void jtsDistance() {
        num("jts", PEER, "JTS DistanceOp.distance (a circle as centre - r)", q -> {
            Geometry[] a = each(q, true, NarrowPeers::jts, Geometry[]::new), b = each(q, false, NarrowPeers::jts, Geometry[]::new);
            double[] radii = new double[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                radii[i] = NarrowPeers.jtsRadius(q.a[i]) + NarrowPeers.jtsRadius(q.b[i]);
            }
            return i -> DistanceOp.distance(a[i], b[i]) - radii[i];
        });
    }

    /** Hitbox through {@code Shape.contains(Shape)}: its call for the question (Collide has no raw form for it). */
    private static void shapeContainsShape(String call) {
        bool("shape", HITBOX, call, q -> {
            Shape[] a = q.a, b = q.b;
            return i -> a[i].contains(b[i]);
        });
    }

    /** dyn4j's containment (separating axes, each projection strictly inside: touching is not held). */
    private static void dyn4jContains() {
        bool("dyn4j", PEER, "dyn4j Sat.contains", q -> {
            Dyn4j d = new Dyn4j(q);
            Sat sat = new Sat();
            org.dyn4j.collision.narrowphase.Containment out = new org.dyn4j.collision.narrowphase.Containment();
            return i -> sat.contains(d.a[i], d.ta[i], d.b[i], d.tb[i], out) && out.isBContainedInA();
        });
    }

    /** JTS's covers (no point of b outside a: the outline counts), prepared once per outer shape and plain. */
    private static void jtsCovers() {
        bool("jtsPrepared", PEER, "JTS PreparedGeometry.covers", q -> {
            PreparedGeometry[] a = new PreparedGeometry[NarrowCase.N];
            Geometry[] b = each(q, false, NarrowPeers::jts, Geometry[]::new);
            for (int i = 0; i < NarrowCase.N; i++) {
                a[i] = PreparedGeometryFactory.prepare(NarrowPeers.jts(q.a[i]));
            }
            return i -> a[i].covers(b[i]);
        });
        bool("jts", PEER, "JTS Geometry.covers", q -> {
            Geometry[] a = each(q, true, NarrowPeers::jts, Geometry[]::new), b = each(q, false, NarrowPeers::jts, Geometry[]::new);
            return i -> a[i].covers(b[i]);
        });
    }

    /** The manifold's contenders: Hitbox's, dyn4j's clipping after SAT, JBox2D's polygon collision. */
    private static void manifolds() {
        points("manifold", HITBOX, "Contact.manifold", q -> {
            Shape[] a = q.a, b = q.b;
            return (i, out) -> {
                Manifold m = Contact.manifold(a[i], b[i]);
                if (m == null) return false;
                out[0] = m.contact().depth();
                out[1] = m.contact().nx();
                out[2] = m.contact().ny();
                out[3] = m.pointCount();
                out[4] = m.x1();
                out[5] = m.y1();
                out[6] = m.depth1();
                out[7] = m.x2();
                out[8] = m.y2();
                out[9] = m.depth2();
                return true;
            };
        });
        points("dyn4j", PEER, "dyn4j Sat.detect + ClippingManifoldSolver", q -> {
            Dyn4j d = new Dyn4j(q);
            Sat sat = new Sat();
            ClippingManifoldSolver solver = new ClippingManifoldSolver();
            Penetration p = new Penetration();
            org.dyn4j.collision.manifold.Manifold m = new org.dyn4j.collision.manifold.Manifold();
            return (i, out) -> {
                m.clear(); // the solver adds to the manifold's points: the caller clears them
                if (!sat.detect(d.a[i], d.ta[i], d.b[i], d.tb[i], p) || !solver.getManifold(p, d.a[i], d.ta[i], d.b[i], d.tb[i], m)) {
                    return false;
                }
                // dyn4j's normal points from the first shape to the second, as Hitbox's
                out[0] = p.getDepth();
                out[1] = p.getNormal().x;
                out[2] = p.getNormal().y;
                List<ManifoldPoint> points = m.getPoints();
                int n = Math.min(2, points.size());
                out[3] = n;
                for (int k = 0; k < 2; k++) {
                    ManifoldPoint mp = points.get(Math.min(k, n - 1));
                    out[4 + 3 * k] = mp.getPoint().x;
                    out[5 + 3 * k] = mp.getPoint().y;
                    out[6 + 3 * k] = mp.getDepth();
                }
                return n > 0;
            };
        });
        points("jbox2d", PEER, "JBox2D Collision.collidePolygons", q -> {
            PolygonShape[] a = new PolygonShape[NarrowCase.N], b = new PolygonShape[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                a[i] = (PolygonShape) NarrowPeers.jbox2d(q.a[i]);
                b[i] = (PolygonShape) NarrowPeers.jbox2d(q.b[i]);
            }
            Collision collision = new Collision(new DefaultWorldPool(16, 16));
            org.jbox2d.common.Transform identity = new org.jbox2d.common.Transform();
            identity.setIdentity();
            org.jbox2d.collision.Manifold m = new org.jbox2d.collision.Manifold();
            return (i, out) -> {
                collision.collidePolygons(m, a[i], identity, b[i], identity);
                if (m.pointCount == 0) return false;
                // With identity transforms the manifold's local frame is the world. Its points are
                // the incident polygon's clipped vertices (as Hitbox's and dyn4j's); each point's
                // depth is how far it lies behind the reference face (Box2D's separation, turned
                // round, without the polygons' 0.01 skins). Box2D keeps points up to the skins
                // (0.02) in front of the face: such a point has a depth just below 0.
                double nx = m.localNormal.x, ny = m.localNormal.y, px = m.localPoint.x, py = m.localPoint.y;
                double max = Double.NEGATIVE_INFINITY;
                for (int k = 0; k < 2; k++) {
                    org.jbox2d.common.Vec2 c = m.points[Math.min(k, m.pointCount - 1)].localPoint;
                    double depth = -((c.x - px) * nx + (c.y - py) * ny);
                    out[4 + 3 * k] = c.x;
                    out[5 + 3 * k] = c.y;
                    out[6 + 3 * k] = depth;
                    max = Math.max(max, depth);
                }
                boolean faceB = m.type == org.jbox2d.collision.Manifold.ManifoldType.FACE_B;
                out[0] = max; // its contact depth: the deepest point's
                out[1] = faceB ? -nx : nx; // the normal from A to B, as its WorldManifold turns it
                out[2] = faceB ? -ny : ny;
                out[3] = m.pointCount;
                return true;
            };
        });
    }

    // ---------------------------------------------------------------- shared contenders

    private static NarrowContender.ContactFn contactOf(Shape[] a, Shape[] b) {
        return (i, out) -> put(a[i].contact(b[i]), out);
    }

    private static boolean put(Contact c, float[] out) {
        if (c == null) return false;
        out[0] = c.depth();
        out[1] = c.nx();
        out[2] = c.ny();
        return true;
    }

    /** dyn4j's penetration; its normal already points from the first shape to the second. */
    private static void dyn4jContact(String key, String call, org.dyn4j.collision.narrowphase.NarrowphaseDetector detector) {
        depth(key, PEER, call, q -> {
            Dyn4j d = new Dyn4j(q);
            Penetration p = new Penetration();
            return (i, out) -> {
                if (!detector.detect(d.a[i], d.ta[i], d.b[i], d.tb[i], p)) return false;
                out[0] = (float) p.getDepth();
                out[1] = (float) p.getNormal().x;
                out[2] = (float) p.getNormal().y;
                return true;
            };
        });
    }

    /** Hitbox's {@code Ray.cast}, rays made before timing as a sketch keeps its rays. */
    private static void rayCast() {
        num("cast", current.contenders().isEmpty() ? HITBOX : SHAPE, "Ray.cast", q -> {
            Ray[] rays = new Ray[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                rays[i] = new Ray(q.v[i][0], q.v[i][1], q.v[i][2], q.v[i][3]);
            }
            Shape[] b = q.b;
            return i -> {
                RayHit hit = rays[i].cast(b[i]);
                return hit == null ? INF : hit.distance();
            };
        });
    }

    private static com.badlogic.gdx.math.collision.Ray[] gdxRays(NarrowCase q) {
        var rays = new com.badlogic.gdx.math.collision.Ray[NarrowCase.N];
        for (int i = 0; i < NarrowCase.N; i++) {
            float[] v = q.v[i];
            rays[i] = new com.badlogic.gdx.math.collision.Ray(new Vector3(v[0], v[1], 0), new Vector3(v[2], v[3], 0));
        }
        return rays;
    }

    /** JBox2D's shape raycast: from the origin to 20 directions out (far past every target). */
    private static void jbox2dRay() {
        num("jbox2d", PEER, "JBox2D Shape.raycast", q -> {
            var b = each(q, false, NarrowPeers::jbox2d, org.jbox2d.collision.shapes.Shape[]::new);
            RayCastInput[] in = new RayCastInput[NarrowCase.N];
            double[] length = new double[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                float[] v = q.v[i];
                in[i] = new RayCastInput();
                in[i].p1.set(v[0], v[1]);
                in[i].p2.set(v[0] + 20 * v[2], v[1] + 20 * v[3]);
                in[i].maxFraction = 1;
                length[i] = 20 * Math.hypot(v[2], v[3]);
            }
            RayCastOutput out = new RayCastOutput();
            org.jbox2d.common.Transform identity = new org.jbox2d.common.Transform();
            identity.setIdentity();
            return i -> b[i].raycast(out, in[i], identity, 0) ? out.fraction * length[i] : INF;
        });
    }

    private static double time(Hit hit) {
        return hit == null ? INF : hit.t();
    }

    private static void sweepShape() {
        // The Hitbox row where the question has no raw form (issue 30 left one, Sweep.rectRect).
        num("shape", current.contenders().isEmpty() ? HITBOX : SHAPE, "Sweep.timeOfImpact(Shape ..)", q -> {
            Shape[] a = q.a, b = q.b;
            float[][] v = q.v;
            return i -> time(Sweep.timeOfImpact(a[i], v[i][0], v[i][1], b[i]));
        });
    }

    /** JBox2D's time of impact (Box2D's conservative advancement with its skin), one input per case. */
    private static void jbox2dToi() {
        num("jbox2d", PEER, "JBox2D TimeOfImpact", q -> {
            DefaultWorldPool pool = new DefaultWorldPool(16, 16);
            TOIInput[] in = new TOIInput[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                in[i] = new TOIInput();
                in[i].proxyA.set(NarrowPeers.jbox2d(q.a[i]), 0);
                in[i].proxyB.set(NarrowPeers.jbox2d(q.b[i]), 0);
                in[i].sweepA.c.set(q.v[i][0], q.v[i][1]);
                in[i].tMax = 1;
            }
            org.jbox2d.collision.TimeOfImpact toi = new org.jbox2d.collision.TimeOfImpact(pool);
            TOIOutput out = new TOIOutput();
            return i -> {
                toi.timeOfImpact(out, in[i]);
                return out.state == TOIOutputState.TOUCHING ? out.t : out.state == TOIOutputState.OVERLAPPED ? 0 : INF;
            };
        });
    }

    /** dyn4j's conservative advancement (GJK distance); the obstacle stands still. */
    private static void dyn4jToi() {
        num("dyn4j", PEER, "dyn4j ConservativeAdvancement", q -> {
            Dyn4j d = new Dyn4j(q);
            org.dyn4j.geometry.Vector2[] v = new org.dyn4j.geometry.Vector2[NarrowCase.N];
            for (int i = 0; i < NarrowCase.N; i++) {
                v[i] = new org.dyn4j.geometry.Vector2(q.v[i][0], q.v[i][1]);
            }
            org.dyn4j.geometry.Vector2 still = new org.dyn4j.geometry.Vector2();
            ConservativeAdvancement ca = new ConservativeAdvancement();
            TimeOfImpact out = new TimeOfImpact();
            return i -> ca.getTimeOfImpact(d.a[i], d.ta[i], v[i], 0, d.b[i], d.tb[i], still, 0, out) ? out.getTime() : INF;
        });
    }

    private static NarrowCase noShapes() {
        return new NarrowCase(NarrowCase.Kind.OVERLAP);
    }

    /**
     * Pixel-mask cases: random blobs (a filled circle of 20 to 32 pixels' radius with holes) at
     * offsets within the other's box, half of them overlapping; the same seed for every contender.
     */
    private static final class Masks {
        final PixelMask[] a = new PixelMask[NarrowCase.N], b = new PixelMask[NarrowCase.N];
        final int[] dx = new int[NarrowCase.N], dy = new int[NarrowCase.N];

        Masks() {
            Random random = new Random(80);
            int hits = 0, misses = 0;
            while (hits + misses < NarrowCase.N) {
                PixelMask s = blob(random), t = blob(random);
                int x = random.nextInt(127) - 63, y = random.nextInt(127) - 63;
                boolean hit = s.overlaps(t, x, y);
                if (hit ? hits == NarrowCase.N / 2 : misses == NarrowCase.N / 2) continue;
                int i = hits + misses;
                a[i] = s;
                b[i] = t;
                dx[i] = x;
                dy[i] = y;
                if (hit) hits++; else misses++;
            }
        }

        private static PixelMask blob(Random random) {
            boolean[][] solid = new boolean[64][64];
            int r = 20 + random.nextInt(13);
            for (int y = 0; y < 64; y++) {
                for (int x = 0; x < 64; x++) {
                    solid[y][x] = (x - 32) * (x - 32) + (y - 32) * (y - 32) < r * r && random.nextInt(8) != 0;
                }
            }
            return PixelMask.fromGrid(solid);
        }
    }
}
