package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Assume;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Collide.trianglePoint: strictly inside, either winding, the same answer as polygonPoint;
 * and Polygon.contains, which answers a triangle with it, the same as polygonPoint too.
 */
class TrianglePointTest {

    static void assertTrianglePoint(boolean expected, float x1, float y1, float x2, float y2, float x3, float y3, float px, float py) {
        for (float shift : new float[] {0, 1_000_000, -1_000_000}) {
            float a = x1 + shift, b = y1 + shift, c = x2 + shift, d = y2 + shift, e = x3 + shift, f = y3 + shift;
            float p = px + shift, q = py + shift;
            // every order of the corners: both windings, every start
            assertEquals(expected, Collide.trianglePoint(a, b, c, d, e, f, p, q));
            assertEquals(expected, Collide.trianglePoint(c, d, e, f, a, b, p, q));
            assertEquals(expected, Collide.trianglePoint(e, f, a, b, c, d, p, q));
            assertEquals(expected, Collide.trianglePoint(a, b, e, f, c, d, p, q));
            assertEquals(expected, Collide.trianglePoint(c, d, a, b, e, f, p, q));
            assertEquals(expected, Collide.trianglePoint(e, f, c, d, a, b, p, q));
            assertEquals(expected, Collide.polygonPoint(new float[] {a, b, c, d, e, f}, p, q));
        }
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "inside,                      0, 0, 10, 0, 0, 10,  2,  2, true",
            "on the slanted edge,         0, 0, 10, 0, 0, 10,  5,  5, false",
            "just inside the slant,       0, 0, 10, 0, 0, 10,  4,  5, true",
            "on a leg,                    0, 0, 10, 0, 0, 10,  5,  0, false",
            "at a corner,                 0, 0, 10, 0, 0, 10, 10,  0, false",
            "outside beyond the slant,    0, 0, 10, 0, 0, 10,  6,  5, false",
            "outside on a leg's line,     0, 0, 10, 0, 0, 10, 11,  0, false",
            "flat triangle on its line,   0, 0, 10, 0, 5, 0,   3,  0, false",
            "flat triangle beside it,     0, 0, 10, 0, 5, 0,   3,  1, false",
            "all corners the same,        3, 3,  3, 3, 3, 3,   3,  3, false",
            "thin and long,               0, 0, 1000000, 1, 1000000, 2, 750000, 1, true",
            "thin and long on the edge,   0, 0, 1000000, 2, 1000000, 3, 500000, 1, false",
    })
    void trianglePoint_table(String scenario, float x1, float y1, float x2, float y2, float x3, float y3, float px, float py, boolean expected) {
        assertTrianglePoint(expected, x1, y1, x2, y2, x3, y3, px, py);
    }

    @ParameterizedTest(name = "NaN as argument {0}")
    @CsvSource({"0", "1", "2", "3", "4", "5", "6", "7"})
    void trianglePoint_nanIsNoCollision(int slot) {
        float[] v = {0, 0, 10, 0, 0, 10, 2, 2};
        v[slot] = Float.NaN;
        assertEquals(false, Collide.trianglePoint(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]));
    }

    @Property(tries = 3000)
    void trianglePoint_agreesWithPolygonPointAndReference(
            @ForAll @IntRange(min = -4, max = 4) int x1, @ForAll @IntRange(min = -4, max = 4) int y1,
            @ForAll @IntRange(min = -4, max = 4) int x2, @ForAll @IntRange(min = -4, max = 4) int y2,
            @ForAll @IntRange(min = -4, max = 4) int x3, @ForAll @IntRange(min = -4, max = 4) int y3,
            @ForAll @IntRange(min = -5, max = 5) int px, @ForAll @IntRange(min = -5, max = 5) int py) {
        float[] xy = {x1, y1, x2, y2, x3, y3};
        boolean t = Collide.trianglePoint(x1, y1, x2, y2, x3, y3, px, py);
        assertEquals(Collide.polygonPoint(xy, px, py), t, "polygonPoint");
        assertEquals(ExactReference.polygonPoint(xy, px, py), t, "reference");
    }
    /** Coordinates of mixed size: small whole numbers, fractions that do not add exactly, a million and more. */
    @Provide
    Arbitrary<Float> coordinate() {
        return Arbitraries.oneOf(
                Arbitraries.integers().between(-6, 6).map(i -> (float) i),
                Arbitraries.integers().between(-60, 60).map(i -> i * 0.1f),
                Arbitraries.integers().between(-3, 3).map(i -> i * 1_000_000f + 0.5f),
                Arbitraries.floats().between(-1e7f, 1e7f));
    }

    /**
     * Polygon.contains on a triangle (answered by trianglePoint) against Collide.polygonPoint
     * (the crossing count), at the points where they could part: the corners, points on each
     * edge (rounded to float, so on it or a hair off), the next floats either side of those,
     * and points well inside and outside.
     */
    @Property(tries = 3000)
    void polygonContains_onATriangle_isPolygonPoint(
            @ForAll("coordinate") float x1, @ForAll("coordinate") float y1,
            @ForAll("coordinate") float x2, @ForAll("coordinate") float y2,
            @ForAll("coordinate") float x3, @ForAll("coordinate") float y3,
            @ForAll @IntRange(min = 0, max = 2) int edge, @ForAll @IntRange(min = 0, max = 8) int at) {
        float[] xy = {x1, y1, x2, y2, x3, y3};
        Polygon p;
        try {
            p = Polygon.of(xy);
        } catch (IllegalArgumentException flat) {
            Assume.that(false); // no area: not a polygon
            return;
        }
        float ax = xy[2 * edge], ay = xy[2 * edge + 1];
        float bx = xy[(2 * edge + 2) % 6], by = xy[(2 * edge + 3) % 6];
        double t = at / 8.0;
        float ex = (float) (ax + t * (bx - ax)), ey = (float) (ay + t * (by - ay));
        float cx = (x1 + x2 + x3) / 3, cy = (y1 + y2 + y3) / 3;
        float[][] points = {
                {ex, ey}, {Math.nextUp(ex), ey}, {Math.nextDown(ex), ey}, {ex, Math.nextUp(ey)}, {ex, Math.nextDown(ey)},
                {cx, cy}, {2 * ex - cx, 2 * ey - cy}, {ax, ay},
        };
        for (float[] q : points) {
            assertEquals(Collide.polygonPoint(xy, q[0], q[1]), p.contains(q[0], q[1]), () -> "point " + q[0] + ", " + q[1]);
        }
    }

    /**
     * A point that is NaN or infinite is outside a triangle, as polygonPoint says: the
     * crossing count never counts it, and no three orientations of it share one sign (with x
     * infinite each sign is that of the edge's y step, or NaN for a level edge, and the
     * three y steps sum to 0; likewise with y infinite, or both).
     */
    @Test
    void polygonContains_onATriangle_notFinitePointIsOutside() {
        float inf = Float.POSITIVE_INFINITY;
        float[] values = {Float.NaN, inf, -inf, 0, 2, 1e30f};
        for (float[] xy : new float[][] {{0, 0, 10, 0, 0, 10}, {0, 0, 0, 10, 10, 0}, {-1e30f, -1e30f, 1e30f, 0, 0, 1e30f}}) {
            Polygon p = Polygon.of(xy);
            for (float px : values) {
                for (float py : values) {
                    assertEquals(Collide.polygonPoint(xy, px, py), p.contains(px, py), "point " + px + ", " + py);
                }
            }
        }
    }
}
