package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.statistics.StatisticsReport;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.statistics.Statistics;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Collide.polygonLine and Segment-Polygon overlaps: the closed segment must reach the open polygon. */
class PolygonLineTest {

    /**
     * One case, every way: both shape orders, the segment either way round, the polygon in
     * both windings from every start, moved by a million; and the reference agrees.
     */
    static void assertPolygonLine(boolean expected, float[] xy, float x1, float y1, float x2, float y2) {
        int n = xy.length / 2;
        for (float shift : new float[] {0, 1_000_000, -1_000_000}) {
            float[] moved = ExactReference.translated(xy, shift, shift);
            float a = x1 + shift, b = y1 + shift, c = x2 + shift, d = y2 + shift;
            String where = " (shifted by " + shift + ")";
            for (float[] wound : new float[][] {moved, ExactReference.reversed(moved)}) {
                for (int start = 0; start < n; start++) {
                    float[] v = ExactReference.rotated(wound, start);
                    assertEquals(expected, Collide.polygonLine(v, a, b, c, d), "from vertex " + start + where);
                    assertEquals(expected, Collide.polygonLine(v, c, d, a, b), "segment reversed, from vertex " + start + where);
                }
            }
            assertEquals(expected, Polygon.of(moved).overlaps(new Segment(a, b, c, d)), "polygon first" + where);
            assertEquals(expected, new Segment(a, b, c, d).overlaps(Polygon.of(moved)), "segment first" + where);
        }
        assertEquals(expected, ExactReference.segmentPolygon(xy, x1, y1, x2, y2), "the reference agrees");
    }

    @ParameterizedTest(name = "{0}: {1}")
    @CsvSource({
            // shape, scenario,                            x1,  y1,  x2,  y2, expected
            "square, straight through,                     -5,   5,  15,   5, true",
            "square, wholly inside (regression),            2,   2,   8,   8, true",
            "square, along the top edge,                    0,   0,  10,   0, false",
            "square, along the top edge and beyond,        -5,   0,  15,   0, false",
            "square, along part of the bottom edge,         2,  10,   8,  10, false",
            "square, ends on an edge from outside,         15,   5,  10,   5, false",
            "square, ends on an edge from inside,           5,   5,  10,   5, true",
            "square, from edge to edge,                     0,   5,  10,   5, true",
            "square, through a corner only,                -5,   5,   5,  -5, false",
            "square, ends at a corner from outside,        15,  15,  10,  10, false",
            "square, corner to corner,                      0,   0,  10,  10, true",
            "square, from a corner inwards,                 0,   0,   5,   5, true",
            "square, from a corner outwards,                0,   0,  -5,  -5, false",
            "square, from a corner along an edge,           0,   0,   5,   0, false",
            "square, cuts a corner,                        -1,   2,   2,  -1, true",
            "square, misses a corner,                      -2,   1,   1,  -2, false",
            "square, outside,                              11,   0,  20,  10, false",
            "square, vertical inside,                       5,  -5,   5,  15, true",
            "square, vertical along the left edge,          0,  -5,   0,  15, false",
    })
    void polygonLine_convex(String shape, String scenario, float x1, float y1, float x2, float y2, boolean expected) {
        assertPolygonLine(expected, TestShapes.get(shape), x1, y1, x2, y2);
    }

    /** Concave polygons: notches, reflex corners, segments that only touch corners. */
    @ParameterizedTest(name = "{0}: {1}")
    @CsvSource({
            "cup,     across the notch's mouth,              4,   0,   6,   0, false",
            "cup,     along the whole top,                   0,   0,  10,   0, false",
            "cup,     down the notch to its bottom,          5,   0,   5,   8, false",
            "cup,     down the notch and into the bottom,    5,   0,   5,   9, true",
            "cup,     along a notch wall,                    4,   0,   4,   8, false",
            "cup,     across the notch wall to wall,         4,   4,   6,   4, false",
            "cup,     across the notch into both walls,      3,   4,   7,   4, true",
            "cup,     along the notch bottom,                4,   8,   6,   8, false",
            "cup,     along the notch bottom and beyond,     3,   8,   7,   8, true",
            "crown,   across the top corners,                0,   0,  10,   0, false",
            "crown,   across the top corners and beyond,    -5,   0,  15,   0, false",
            "crown,   along a side of the V,                 0,   0,   5,   5, false",
            "crown,   along a side of the V and on,          0,   0,   7,   7, true",
            "crown,   down through the V's bottom corner,    5,   0,   5,  10, true",
            "crown,   down to the V's bottom corner,         5,   0,   5,   5, false",
            "crown,   steeply up from the bottom corner,     5,   5,   4,   0, false",
            "crown,   level through the bottom corner,       2,   5,   8,   5, true",
            "crown,   inside the V without touching,         4,   3,   6,   3, false",
            "doubleV, along the top touching three corners,  0,   0,  12,   0, false",
            "doubleV, through both notch bottoms,            0,   6,  12,   6, true",
            "doubleV, from notch bottom to notch bottom,     3,   6,   9,   6, true",
            "doubleV, touching only the middle peak,         4,   0,   8,   0, false",
            "doubleV, down through the middle peak,          6,  -2,   6,   3, true",
            "ell,     along the inner edge,                  5,   5,  10,   5, false",
            "ell,     along the inner edge from inside,      2,   5,  10,   5, true",
            "ell,     along the inner vertical edge,         5,   5,   5,  10, false",
            "ell,     from outside to the inner corner,     10,  10,   5,   5, false",
            "ell,     through the inner corner,             10,  10,   2,   2, true",
            "ell,     diagonal past the inner corner,        4,   6,   6,   4, true",
            "squareWithMidpoint, along the top through the straight corner, -5, 0, 15, 0, false",
            "squareWithMidpoint, down through the straight corner,           5, -5,  5, 5, true",
            "squareWithMidpoint, up from the straight corner,                5,  0,  5, -5, false",
    })
    void polygonLine_concave(String shape, String scenario, float x1, float y1, float x2, float y2, boolean expected) {
        assertPolygonLine(expected, TestShapes.get(shape), x1, y1, x2, y2);
    }

    /** A segment of length 0 is a point: it collides when strictly inside. */
    @ParameterizedTest(name = "{0}: ({1}, {2})")
    @CsvSource({
            "square, 5, 5, true",
            "square, 0, 5, false",
            "square, 0, 0, false",
            "square, 11, 5, false",
            "crown, 5, 5, false",
            "crown, 5, 4, false",
            "crown, 5, 6, true",
    })
    void polygonLine_zeroLength(String shape, float x, float y, boolean expected) {
        assertPolygonLine(expected, TestShapes.get(shape), x, y, x, y);
    }

    @ParameterizedTest(name = "NaN as argument {0}")
    @CsvSource({"0", "1", "2", "3"})
    void polygonLine_nanIsNoCollision(int slot) {
        float[] v = {5, 5, 20, 5}; // one end inside: NaN at the other must still give false
        v[slot] = Float.NaN;
        assertFalse(Collide.polygonLine(TestShapes.SQUARE, v[0], v[1], v[2], v[3]));
    }

    @Test
    void polygonLine_fewerThanThreeVerticesNeverCollide() {
        assertFalse(Collide.polygonLine(new float[0], 0, 0, 10, 10));
        assertFalse(Collide.polygonLine(new float[] {0, 0, 10, 10}, 0, 10, 10, 0));
        assertFalse(Collide.polygonLine(new float[] {0, 0, 10, 0, 5}, 5, -5, 5, 5));
    }

    @Provide
    Arbitrary<float[]> polygons() {
        return TestShapes.simplePolygons(6, 7);
    }

    @StatisticsReport(onFailureOnly = true)
    @Property(tries = 2000)
    void polygonLine_agreesWithExactReference(@ForAll("polygons") float[] xy,
                                              @ForAll @IntRange(min = -1, max = 7) int x1, @ForAll @IntRange(min = -1, max = 7) int y1,
                                              @ForAll @IntRange(min = -1, max = 7) int x2, @ForAll @IntRange(min = -1, max = 7) int y2) {
        boolean expected = ExactReference.segmentPolygon(xy, x1, y1, x2, y2);
        assertEquals(expected, Collide.polygonLine(xy, x1, y1, x2, y2));
        Statistics.collect(expected);
        Statistics.coverage(c -> {
            c.check(true).percentage(p -> p > 20);
            c.check(false).percentage(p -> p > 20);
        });
    }

    /** Segments between two vertices hit the corner cases of the vertex rules most often. */
    @Property(tries = 2000)
    void polygonLine_vertexToVertexAgreesWithReference(@ForAll("polygons") float[] xy,
                                                       @ForAll @IntRange(min = 0, max = 6) int i, @ForAll @IntRange(min = 0, max = 6) int j,
                                                       @ForAll @IntRange(min = 1, max = 3) int stretch) {
        int n = xy.length / 2;
        float x1 = xy[2 * (i % n)], y1 = xy[2 * (i % n) + 1];
        // the far end is the other vertex, or beyond it on the same line
        float x2 = x1 + stretch * (xy[2 * (j % n)] - x1), y2 = y1 + stretch * (xy[2 * (j % n) + 1] - y1);
        assertEquals(ExactReference.segmentPolygon(xy, x1, y1, x2, y2), Collide.polygonLine(xy, x1, y1, x2, y2));
    }

    @Property(tries = 1000)
    void polygonLine_sameForAnyWindingStartOrPlace(@ForAll("polygons") float[] xy,
                                                   @ForAll @IntRange(min = -1, max = 7) int x1, @ForAll @IntRange(min = -1, max = 7) int y1,
                                                   @ForAll @IntRange(min = -1, max = 7) int x2, @ForAll @IntRange(min = -1, max = 7) int y2,
                                                   @ForAll @IntRange(min = 0, max = 6) int start,
                                                   @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
                                                   @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        boolean here = Collide.polygonLine(xy, x1, y1, x2, y2);
        assertEquals(here, Collide.polygonLine(xy, x2, y2, x1, y1), "segment reversed");
        assertEquals(here, Collide.polygonLine(ExactReference.reversed(xy), x1, y1, x2, y2), "other winding");
        assertEquals(here, Collide.polygonLine(ExactReference.rotated(xy, start % (xy.length / 2)), x1, y1, x2, y2), "other start");
        assertEquals(here, Collide.polygonLine(ExactReference.translated(xy, dx, dy), x1 + dx, y1 + dy, x2 + dx, y2 + dy), "moved");
    }
}
