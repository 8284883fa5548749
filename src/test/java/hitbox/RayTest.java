package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Rays against every kind of shape. Each table row gives the expected distance (Infinity: no
 * hit) and normal (from the ray into the shape, the package's convention), and is also checked moved by a million pixels and with the direction
 * scaled (the distance is in pixels, so it must not change).
 */
class RayTest {

    private static final float FAR = 1_000_000f;

    @ParameterizedTest(name = "[{index}] {11}")
    @CsvSource({
            // ox, oy, dx, dy, max, cx, cy, r, distance, nx, ny, scenario
            "0, 0, 1, 0, Infinity, 10, 0, 2, 8, 1, 0, head on",
            "0, 0, 3, 4, Infinity, 6, 8, 5, 5, 0.6, 0.8, three-four-five",
            "0, 2, 1, 0, Infinity, 10, 0, 2, Infinity, 0, 0, grazing the outline",
            "0, 0, 1, 0, 8, 10, 0, 2, Infinity, 0, 0, reaching the outline only at its end",
            "0, 0, 1, 0, 8.5, 10, 0, 2, 8, 1, 0, reaching just inside",
            "10, 1, 1, 0, Infinity, 10, 0, 2, 0, 1, 0, starting inside",
            "8, 0, 1, 0, Infinity, 10, 0, 2, 0, 1, 0, starting on the outline heading in",
            "8, 0, -1, 0, Infinity, 10, 0, 2, Infinity, 0, 0, starting on the outline heading out",
            "0, 0, -1, 0, Infinity, 10, 0, 2, Infinity, 0, 0, circle behind",
            "0, 0, 1, 0, Infinity, 10, 0, 0, Infinity, 0, 0, a circle of radius 0",
    })
    void cast_circle(float ox, float oy, float dx, float dy, float max, float cx, float cy, float r,
                     float distance, float nx, float ny, String scenario) {
        check(new Ray(ox, oy, dx, dy, max), new Circle(cx, cy, r), distance, nx, ny);
        assertEquals(distance, Ray.distanceToCircle(ox, oy, dx, dy, max, cx, cy, r), 1e-5f);
        check(new Ray(ox + FAR, oy - FAR, dx, dy, max), new Circle(cx + FAR, cy - FAR, r), distance, nx, ny);
        check(new Ray(ox, oy, dx * 4, dy * 4, max), new Circle(cx, cy, r), distance, nx, ny);
    }

    @ParameterizedTest(name = "[{index}] {12}")
    @CsvSource({
            // ox, oy, dx, dy, max, rx, ry, rw, rh, distance, nx, ny, scenario
            "0, 5, 1, 0, Infinity, 10, 0, 10, 10, 10, 1, 0, into the left side",
            "30, 5, -1, 0, Infinity, 10, 0, 10, 10, 10, -1, 0, into the right side",
            "5, -10, 0, 1, Infinity, 0, 0, 10, 10, 10, 0, 1, down onto the top",
            "5, 20, 0, -1, Infinity, 0, 0, 10, 10, 10, 0, -1, up into the bottom",
            "0, 5, 2, 0, Infinity, 10, 0, 10, 10, 10, 1, 0, direction not of unit length",
            "0, 0, 1, 0, Infinity, 10, 0, 10, 10, Infinity, 0, 0, along the top edge",
            "0, 20, 1, -1, Infinity, 0, 0, 10, 10, Infinity, 0, 0, touching only a corner",
            "0, 0, 1, 1, Infinity, 10, 10, 10, 10, 14.142136, 0, 1, into a corner counts as the top",
            "5, 5, 1, 0, Infinity, 0, 0, 10, 10, 0, 1, 0, starting inside",
            "10, 5, 1, 0, Infinity, 10, 0, 10, 10, 0, 1, 0, starting on the edge heading in",
            "10, 5, -1, 0, Infinity, 10, 0, 10, 10, Infinity, 0, 0, starting on the edge heading out",
            "0, 5, 1, 0, 10, 10, 0, 10, 10, Infinity, 0, 0, reaching the edge only at its end",
            "0, 5, 1, 0, 10.5, 10, 0, 10, 10, 10, 1, 0, reaching just inside",
            "0, 5, 1, 0, Infinity, 10, 0, 0, 10, Infinity, 0, 0, a rectangle of width 0",
            "0, 5, -1, 0, Infinity, 10, 0, 10, 10, Infinity, 0, 0, rectangle behind",
    })
    void cast_rect(float ox, float oy, float dx, float dy, float max, float rx, float ry, float rw, float rh,
                   float distance, float nx, float ny, String scenario) {
        check(new Ray(ox, oy, dx, dy, max), new Rect(rx, ry, rw, rh), distance, nx, ny);
        assertEquals(distance, Ray.distanceToRect(ox, oy, dx, dy, max, rx, ry, rw, rh), 1e-5f);
        check(new Ray(ox + FAR, oy - FAR, dx, dy, max), new Rect(rx + FAR, ry - FAR, rw, rh), distance, nx, ny);
        check(new Ray(ox, oy, dx * 4, dy * 4, max), new Rect(rx, ry, rw, rh), distance, nx, ny);
    }

    @ParameterizedTest(name = "[{index}] {12}")
    @CsvSource({
            // ox, oy, dx, dy, max, x1, y1, x2, y2, distance, nx, ny, scenario
            "0, 0, 1, 0, Infinity, 10, -5, 10, 5, 10, 1, 0, across a wall",
            "0, 0, 1, 0, Infinity, 10, 5, 10, -5, 10, 1, 0, across a wall given the other way",
            "0, 0, 1, 0, Infinity, 10, 0, 10, 5, 10, 1, 0, touching its end counts",
            "0, 0, 1, 0, Infinity, 10, 1, 10, 5, Infinity, 0, 0, passing its end",
            "0, 0, 1, 0, Infinity, 10, 0, 20, 0, 10, 1, 0, along it: the near end",
            "0, 0, 1, 0, Infinity, -20, 0, -10, 0, Infinity, 0, 0, along the line but behind",
            "0, 0, 1, 0, Infinity, -5, 0, 5, 0, 0, 1, 0, starting on it along it",
            "0, 0, 1, 0, Infinity, 0, -5, 0, 5, 0, 1, 0, starting on it across it",
            "0, 0, 1, 0, Infinity, 0, 1, 10, 1, Infinity, 0, 0, parallel",
            "0, 0, 1, 0, 10, 10, -5, 10, 5, 10, 1, 0, reaching it exactly at the end",
            "0, 0, 1, 0, 9, 10, -5, 10, 5, Infinity, 0, 0, falling short",
            "0, 0, 1, 0, Infinity, 5, 0, 5, 0, 5, 1, 0, a segment of length 0",
            "0, 0, 1, 0, Infinity, 10, -10, 20, 10, 15, 0.8944272, -0.4472136, a slanted wall",
    })
    void cast_segment(float ox, float oy, float dx, float dy, float max, float x1, float y1, float x2, float y2,
                      float distance, float nx, float ny, String scenario) {
        check(new Ray(ox, oy, dx, dy, max), new Segment(x1, y1, x2, y2), distance, nx, ny);
        assertEquals(distance, Ray.distanceToSegment(ox, oy, dx, dy, max, x1, y1, x2, y2), 1e-5f);
        check(new Ray(ox + FAR, oy - FAR, dx, dy, max), new Segment(x1 + FAR, y1 - FAR, x2 + FAR, y2 - FAR), distance, nx, ny);
        check(new Ray(ox, oy, dx * 4, dy * 4, max), new Segment(x1, y1, x2, y2), distance, nx, ny);
    }

    /** A U opening downwards: the notch is x in (10, 20), y in (10, 30). */
    private static final Polygon U = Polygon.of(0, 0, 30, 0, 30, 30, 20, 30, 20, 10, 10, 10, 10, 30, 0, 30);
    private static final Polygon TRIANGLE = Polygon.of(10, -10, 20, 0, 10, 10);

    @ParameterizedTest(name = "[{index}] {8}")
    @CsvSource({
            // shape, ox, oy, dx, dy, distance, nx, ny, scenario
            "TRIANGLE, 0, 0, 1, 0, 10, 1, 0, into a flat side",
            "TRIANGLE, 30, 0, -1, 0, 10, -1, 0, head on into a vertex: the two sides' normals together",
            "TRIANGLE, 20, -10, 0, 1, Infinity, 0, 0, touching only a vertex",
            "TRIANGLE, 12, 0, 1, 0, 0, 1, 0, starting inside",
            "TRIANGLE, 10, 0, 1, 0, 0, 1, 0, starting on a side heading in",
            "TRIANGLE, 10, 0, -1, 0, Infinity, 0, 0, starting on a side heading out",
            "U, 15, 40, 0, -1, 30, 0, -1, up through the notch to its top",
            "U, -10, 20, 1, 0, 10, 1, 0, into the left arm",
            "U, 15, 20, 1, 0, 5, 1, 0, from inside the notch to the right arm",
            "U, -10, 0, 1, 0, Infinity, 0, 0, along the top edge",
            "U, -10, 10, 1, 0, 10, 1, 0, along the notch's top edge, into the left arm",
            "U, 15, 15, -1, -1, 7.071068, -0.70710677, -0.70710677, through the inner corner",
            "U, 40, 15, 1, 0, Infinity, 0, 0, pointing away",
    })
    void cast_polygon(String shape, float ox, float oy, float dx, float dy, float distance, float nx, float ny, String scenario) {
        Polygon p = shape.equals("U") ? U : TRIANGLE;
        check(new Ray(ox, oy, dx, dy), p, distance, nx, ny);
        check(new Ray(ox + FAR, oy - FAR, dx, dy), p.translated(FAR, -FAR), distance, nx, ny);
        check(new Ray(ox, oy, dx * 3, dy * 3), p, distance, nx, ny);
    }

    @Test
    void cast_polygonBeyondMaxDistance_misses() {
        assertNull(new Ray(0, 0, 1, 0, 10).cast(TRIANGLE), "reaching the side only at the end");
        assertNotNull(new Ray(0, 0, 1, 0, 10.5f).cast(TRIANGLE));
    }

    @Test
    void between_endsExactlyAtTheSecondPoint() {
        Segment wallThroughTarget = new Segment(1, 0, 0, 1);
        Ray sight = Ray.between(0, 0, 0.5f, 0.5f);  // length sqrt(0.5): not a float
        RayHit hit = sight.cast(wallThroughTarget);
        assertNotNull(hit, "the wall passes through the end point");
        assertEquals(0.5f, hit.x());
        assertEquals(0.5f, hit.y());
        assertNull(Ray.between(0, 0, 0.49f, 0.49f).cast(wallThroughTarget));
    }

    @Test
    void ray_badArguments_throwWithTheirNames() {
        assertEquals("direction (dx, dy) must not be (0, 0): a ray needs a direction",
                assertThrows(IllegalArgumentException.class, () -> new Ray(0, 0, 0, 0)).getMessage());
        assertEquals("maxDistance must be >= 0 (or infinite), was -1.0",
                assertThrows(IllegalArgumentException.class, () -> new Ray(0, 0, 1, 0, -1)).getMessage());
        assertThrows(IllegalArgumentException.class, () -> new Ray(0, 0, 1, 0, Float.NaN));
        assertEquals("dx must be a finite number, was Infinity",
                assertThrows(IllegalArgumentException.class, () -> new Ray(0, 0, Float.POSITIVE_INFINITY, 0)).getMessage());
        assertThrows(IllegalArgumentException.class, () -> Ray.between(1, 2, 1, 2));
        assertEquals("shape must not be null",
                assertThrows(IllegalArgumentException.class, () -> new Ray(0, 0, 1, 0).cast(null)).getMessage());
        assertThrows(IllegalArgumentException.class, () -> new RayHit(-1, 0, 0, 1, 0));
        assertEquals(0, new Ray(0, 0, 1, 0, 0).maxDistance());
    }

    @Test
    void distanceTo_nanOrZeroDirection_noHit() {
        assertEquals(Float.POSITIVE_INFINITY, Ray.distanceToRect(Float.NaN, 5, 1, 0, Float.POSITIVE_INFINITY, 10, 0, 10, 10));
        assertEquals(Float.POSITIVE_INFINITY, Ray.distanceToRect(0, 5, 0, 0, Float.POSITIVE_INFINITY, 10, 0, 10, 10));
        assertEquals(Float.POSITIVE_INFINITY, Ray.distanceToCircle(0, 0, 0, 0, Float.POSITIVE_INFINITY, 10, 0, 2));
        assertEquals(Float.POSITIVE_INFINITY, Ray.distanceToSegment(0, 0, 0, 0, Float.POSITIVE_INFINITY, 10, -5, 10, 5));
        assertEquals(Float.POSITIVE_INFINITY, Ray.distanceToSegment(0, 0, Float.NaN, 0, Float.POSITIVE_INFINITY, 10, -5, 10, 5));
    }

    // ------------------------------------------------------------------ properties

    /** A ray is a point moving along it: the same answer as the swept point against the box. */
    @Property(tries = 3000)
    void castRect_agreesWithASweptPoint(@ForAll @IntRange(min = -50, max = 50) int ox, @ForAll @IntRange(min = -50, max = 50) int oy,
                                        @ForAll @IntRange(min = -80, max = 80) int dx, @ForAll @IntRange(min = -80, max = 80) int dy,
                                        @ForAll @IntRange(min = -40, max = 40) int rx, @ForAll @IntRange(min = -40, max = 40) int ry,
                                        @ForAll @IntRange(min = 0, max = 30) int rw, @ForAll @IntRange(min = 0, max = 30) int rh) {
        if (dx == 0 && dy == 0) {
            return;
        }
        RayHit hit = Ray.between(ox, oy, ox + dx, oy + dy).cast(new Rect(rx, ry, rw, rh));
        float t = Sweep.rectRect(ox, oy, 0, 0, dx, dy, rx, ry, rw, rh);
        assertEquals(t <= 1, hit != null, "t = " + t);
        if (hit != null) {
            assertEquals(t * Math.hypot(dx, dy), hit.distance(), 1e-4);
            assertTrue(hit.nx() * dx + hit.ny() * dy > 0, "the normal points from the ray into the shape");
        }
    }

    /** Ray.between against a segment is closed segment against closed segment, decided by orientations. */
    @Property(tries = 3000)
    void castSegment_agreesWithOrientations(@ForAll @IntRange(min = -20, max = 20) int ox, @ForAll @IntRange(min = -20, max = 20) int oy,
                                            @ForAll @IntRange(min = -20, max = 20) int tx, @ForAll @IntRange(min = -20, max = 20) int ty,
                                            @ForAll @IntRange(min = -20, max = 20) int x1, @ForAll @IntRange(min = -20, max = 20) int y1,
                                            @ForAll @IntRange(min = -20, max = 20) int x2, @ForAll @IntRange(min = -20, max = 20) int y2) {
        if (ox == tx && oy == ty) {
            return;
        }
        RayHit hit = Ray.between(ox, oy, tx, ty).cast(new Segment(x1, y1, x2, y2));
        assertEquals(closedSegmentsMeet(ox, oy, tx, ty, x1, y1, x2, y2), hit != null);
        if (hit != null) {
            assertTrue(hit.distance() <= Math.hypot(tx - ox, ty - oy) + 1e-4);
        }
    }

    /** Circles: hit exactly when the ray's segment comes closer than r to the centre (exact reference). */
    @Property(tries = 3000)
    void castCircle_agreesWithExactDistance(@ForAll @IntRange(min = -50, max = 50) int ox, @ForAll @IntRange(min = -50, max = 50) int oy,
                                            @ForAll @IntRange(min = -80, max = 80) int dx, @ForAll @IntRange(min = -80, max = 80) int dy,
                                            @ForAll @IntRange(min = -40, max = 40) int cx, @ForAll @IntRange(min = -40, max = 40) int cy,
                                            @ForAll @IntRange(min = 0, max = 20) int r) {
        if (dx == 0 && dy == 0) {
            return;
        }
        RayHit hit = Ray.between(ox, oy, ox + dx, oy + dy).cast(new Circle(cx, cy, r));
        assertEquals(SweepReference.circleCircleHits(ox, oy, 0, dx, dy, cx, cy, r), hit != null);
        if (hit != null && hit.distance() > 0) {
            assertEquals(r, Math.hypot(hit.x() - cx, hit.y() - cy), 1e-3, "the hit is on the outline");
        }
    }

    /** Triangles: the first sampled point inside (exact orientation test) is never before the hit, and any inside sample means a hit. */
    @Property(tries = 2000)
    void castPolygon_agreesWithSampling(@ForAll @IntRange(min = -30, max = 30) int ax, @ForAll @IntRange(min = -30, max = 30) int ay,
                                        @ForAll @IntRange(min = -30, max = 30) int bx, @ForAll @IntRange(min = -30, max = 30) int by,
                                        @ForAll @IntRange(min = -30, max = 30) int cx, @ForAll @IntRange(min = -30, max = 30) int cy,
                                        @ForAll @IntRange(min = -60, max = 60) int ox, @ForAll @IntRange(min = -60, max = 60) int oy,
                                        @ForAll @IntRange(min = -30, max = 30) int tx, @ForAll @IntRange(min = -30, max = 30) int ty) {
        if (Lines.orient(ax, ay, bx, by, cx, cy) == 0 || (ox == tx && oy == ty)) {
            return;
        }
        Polygon p = Polygon.of(ax, ay, bx, by, cx, cy);
        Ray ray = Ray.between(ox, oy, tx, ty);
        RayHit hit = ray.cast(p);
        double length = Math.hypot(tx - ox, ty - oy);
        for (int k = 0; k <= 1024; k++) {
            double s = k / 1024.0;
            if (insideTriangle(ax, ay, bx, by, cx, cy, ox + s * (tx - ox), oy + s * (ty - oy))) {
                assertNotNull(hit, "sample " + s + " is inside");
                assertTrue(hit.distance() <= s * length + 1e-3, "sample " + s + " is inside before the hit at " + hit.distance());
                break;
            }
        }
        if (hit != null && hit.distance() > 0) {
            // Just past the hit the ray is inside.
            double s = Math.min(hit.distance() / length + 1e-4, 1);
            boolean inside = false;
            for (int k = 0; k < 64 && !inside; k++) {
                double q = hit.distance() / length + (s - hit.distance() / length) * (k + 1) / 64;
                inside = insideTriangle(ax, ay, bx, by, cx, cy, ox + q * (tx - ox), oy + q * (ty - oy));
            }
            assertTrue(inside, "not inside just after the hit " + hit);
        }
    }

    // ------------------------------------------------------------------ helpers

    private static void check(Ray ray, Shape shape, float distance, float nx, float ny) {
        RayHit hit = ray.cast(shape);
        if (distance == Float.POSITIVE_INFINITY) {
            assertNull(hit, () -> "expected no hit, got " + hit);
            return;
        }
        assertNotNull(hit, "expected a hit at " + distance);
        assertEquals(distance, hit.distance(), 1e-5f * Math.max(1, distance), "distance");
        double len = Math.hypot(ray.dx(), ray.dy());
        assertEquals(ray.ox() + distance * ray.dx() / len, hit.x(), 1e-4 * Math.max(1, Math.abs(hit.x())), "x");
        assertEquals(ray.oy() + distance * ray.dy() / len, hit.y(), 1e-4 * Math.max(1, Math.abs(hit.y())), "y");
        assertEquals(nx, hit.nx(), 1e-6f, "nx");
        assertEquals(ny, hit.ny(), 1e-6f, "ny");
    }

    /** Strictly inside the triangle: the same strict turn from all three sides (exact for these dyadic points). */
    private static boolean insideTriangle(double ax, double ay, double bx, double by, double cx, double cy, double px, double py) {
        double o1 = Math.signum(Lines.orient(ax, ay, bx, by, px, py));
        double o2 = Math.signum(Lines.orient(bx, by, cx, cy, px, py));
        double o3 = Math.signum(Lines.orient(cx, cy, ax, ay, px, py));
        return o1 != 0 && o1 == o2 && o2 == o3;
    }

    private static boolean closedSegmentsMeet(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
        double o1 = Lines.orient(ax, ay, bx, by, cx, cy), o2 = Lines.orient(ax, ay, bx, by, dx, dy);
        double o3 = Lines.orient(cx, cy, dx, dy, ax, ay), o4 = Lines.orient(cx, cy, dx, dy, bx, by);
        if (Math.signum(o1) * Math.signum(o2) < 0 && Math.signum(o3) * Math.signum(o4) < 0) {
            return true;
        }
        return o1 == 0 && within(ax, ay, bx, by, cx, cy) || o2 == 0 && within(ax, ay, bx, by, dx, dy)
                || o3 == 0 && within(cx, cy, dx, dy, ax, ay) || o4 == 0 && within(cx, cy, dx, dy, bx, by);
    }

    private static boolean within(double ax, double ay, double bx, double by, double px, double py) {
        return px >= Math.min(ax, bx) && px <= Math.max(ax, bx) && py >= Math.min(ay, by) && py <= Math.max(ay, by);
    }
}
