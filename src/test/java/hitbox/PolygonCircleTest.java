package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Collide.polygonCircle and Circle-Polygon overlaps: two open shapes; touching is not overlapping. */
class PolygonCircleTest {

    /** One case, every way: both shape orders, both windings, every start, moved by a million. */
    static void assertPolygonCircle(boolean expected, float[] xy, float cx, float cy, float r) {
        int n = xy.length / 2;
        for (float shift : new float[] {0, 1_000_000, -1_000_000}) {
            float[] moved = ExactReference.translated(xy, shift, -shift);
            float x = cx + shift, y = cy - shift;
            String where = " (shifted by " + shift + ")";
            for (float[] wound : new float[][] {moved, ExactReference.reversed(moved)}) {
                for (int start = 0; start < n; start++) {
                    assertEquals(expected, Collide.polygonCircle(ExactReference.rotated(wound, start), x, y, r),
                            "from vertex " + start + where);
                }
            }
            assertEquals(expected, Polygon.of(moved).overlaps(new Circle(x, y, r)), "polygon first" + where);
            assertEquals(expected, new Circle(x, y, r).overlaps(Polygon.of(moved)), "circle first" + where);
        }
        assertEquals(expected, ExactReference.polygonCircle(xy, cx, cy, r), "the reference agrees");
    }

    @ParameterizedTest(name = "{0}: {1}")
    @CsvSource({
            // shape,      scenario,                                 cx,  cy,  r, expected
            "square,       circle inside,                              5,   5,  2, true",
            "square,       circle inside touching all four edges,      5,   5,  5, true",
            "square,       square inside the circle,                   5,   5, 20, true",
            "square,       touching the right edge from outside,      15,   5,  5, false",
            "square,       overlapping the right edge,                14,   5,  5, true",
            "square,       centre on an edge,                         10,   5,  1, true",
            "square,       centre on a corner,                        10,  10,  1, true",
            "square,       touching a corner,                         13,  14,  5, false",
            "square,       overlapping a corner,                      13,  14,  6, true",
            "square,       far away,                                  30,  30,  5, false",
            "triangle345,  tangent to the long side at (4 3),          7,   7,  5, false",
            "triangle345,  over the long side,                         7,   7,  6, true",
            "cup,          in the notch touching both walls,           5,   4,  1, false",
            "cup,          in the notch and into both walls,           5,   4,  2, true",
            "cup,          on the notch bottom touching three sides,   5,   7,  1, false",
            "cup,          at the notch mouth touching its corners,    5,   0,  1, false",
            "cup,          above the notch,                            5,  -2,  1, false",
            "crown,        centre on the V's bottom corner,            5,   5,  1, true",
            "crown,        in the V above its bottom corner,           5,   3,  1, false",
            "ell,          in the missing corner touching two edges,   7,   7,  2, false",
            "ell,          in the missing corner reaching in,          7,   7,  3, true",
    })
    void polygonCircle_table(String shape, String scenario, float cx, float cy, float r, boolean expected) {
        assertPolygonCircle(expected, TestShapes.get(shape), cx, cy, r);
    }

    /** A circle of radius 0 is a point: it collides when strictly inside. */
    @ParameterizedTest(name = "{0}: ({1}, {2})")
    @CsvSource({
            "square, 5,  5, true",
            "square, 0,  5, false",
            "square, 10, 10, false",
            "square, 11, 5, false",
            "crown,  5,  5, false",
            "crown,  5,  6, true",
    })
    void polygonCircle_radiusZero(String shape, float cx, float cy, boolean expected) {
        assertPolygonCircle(expected, TestShapes.get(shape), cx, cy, 0);
    }

    @ParameterizedTest(name = "NaN as argument {0}")
    @CsvSource({"0", "1", "2"})
    void polygonCircle_nanIsNoCollision(int slot) {
        float[] v = {5, 5, 1};
        v[slot] = Float.NaN;
        assertFalse(Collide.polygonCircle(TestShapes.SQUARE, v[0], v[1], v[2]));
    }

    @Test
    void polygonCircle_negativeRadiusAndShortArraysNeverCollide() {
        assertFalse(Collide.polygonCircle(TestShapes.SQUARE, 5, 5, -1));
        assertFalse(Collide.polygonCircle(new float[] {0, 0, 10, 10}, 5, 5, 20));
        assertFalse(Collide.polygonCircle(new float[0], 0, 0, 20));
        assertTrue(Collide.polygonCircle(new float[] {0, 0, 10, 0, 10, 10, 0, 10, 7}, 5, 5, 1), "odd last coordinate ignored");
    }

    @Provide
    Arbitrary<float[]> polygons() {
        return TestShapes.simplePolygons(6, 7);
    }

    @Property(tries = 2000)
    void polygonCircle_agreesWithExactReference(@ForAll("polygons") float[] xy,
                                                @ForAll @IntRange(min = -3, max = 9) int cx, @ForAll @IntRange(min = -3, max = 9) int cy,
                                                @ForAll @IntRange(min = 0, max = 5) int r) {
        assertEquals(ExactReference.polygonCircle(xy, cx, cy, r), Collide.polygonCircle(xy, cx, cy, r));
    }

    /** An independent one-way check: a grid point inside both shapes proves they overlap. */
    @Property(tries = 300)
    void polygonCircle_sharedGridPointMeansOverlap(@ForAll("polygons") float[] xy,
                                                   @ForAll @IntRange(min = -2, max = 8) int cx, @ForAll @IntRange(min = -2, max = 8) int cy,
                                                   @ForAll @IntRange(min = 1, max = 4) int r) {
        boolean shared = false;
        for (int i = -20; i <= 48 && !shared; i++) {
            for (int j = -20; j <= 48 && !shared; j++) {
                float x = i / 4f, y = j / 4f;
                shared = Collide.circlePoint(cx, cy, r, x, y) && ExactReference.polygonPoint(xy, x, y);
            }
        }
        if (shared) {
            assertTrue(Collide.polygonCircle(xy, cx, cy, r));
        }
    }

    @Property(tries = 1000)
    void polygonCircle_sameForAnyWindingStartOrPlace(@ForAll("polygons") float[] xy,
                                                     @ForAll @IntRange(min = -3, max = 9) int cx, @ForAll @IntRange(min = -3, max = 9) int cy,
                                                     @ForAll @IntRange(min = 0, max = 5) int r, @ForAll @IntRange(min = 0, max = 6) int start,
                                                     @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
                                                     @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        boolean here = Collide.polygonCircle(xy, cx, cy, r);
        assertEquals(here, Collide.polygonCircle(ExactReference.reversed(xy), cx, cy, r), "other winding");
        assertEquals(here, Collide.polygonCircle(ExactReference.rotated(xy, start % (xy.length / 2)), cx, cy, r), "other start");
        assertEquals(here, Collide.polygonCircle(ExactReference.translated(xy, dx, dy), cx + dx, cy + dy, r), "moved");
    }
}
