package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Collide.polygonRect and Rect-Polygon overlaps: two open shapes; touching is not overlapping. */
class PolygonRectTest {

    /** One case, every way: both shape orders, both windings, every start, moved by a million. */
    static void assertPolygonRect(boolean expected, float[] xy, float rx, float ry, float rw, float rh) {
        int n = xy.length / 2;
        for (float shift : new float[] {0, 1_000_000, -1_000_000}) {
            float[] moved = ExactReference.translated(xy, -shift, shift);
            float x = rx - shift, y = ry + shift;
            String where = " (shifted by " + shift + ")";
            for (float[] wound : new float[][] {moved, ExactReference.reversed(moved)}) {
                for (int start = 0; start < n; start++) {
                    assertEquals(expected, Collide.polygonRect(ExactReference.rotated(wound, start), x, y, rw, rh),
                            "from vertex " + start + where);
                }
            }
            assertEquals(expected, Polygon.of(moved).overlaps(new Rect(x, y, rw, rh)), "polygon first" + where);
            assertEquals(expected, new Rect(x, y, rw, rh).overlaps(Polygon.of(moved)), "rect first" + where);
        }
        assertEquals(expected, reference(xy, rx, ry, rw, rh), "the reference agrees");
    }

    /** A rectangle with area is a polygon; one of size 0 is the segment between its corners. */
    static boolean reference(float[] xy, float rx, float ry, float rw, float rh) {
        return rw > 0 && rh > 0
                ? ExactReference.polygonsMeet(xy, ExactReference.rectPolygon(rx, ry, rw, rh))
                : ExactReference.segmentPolygon(xy, rx, ry, rx + rw, ry + rh);
    }

    @ParameterizedTest(name = "{0}: {1}")
    @CsvSource({
            // shape,    scenario,                                  rx,  ry,  rw,  rh, expected
            "square,     the same outline,                           0,   0,  10,  10, true",
            "square,     rect inside,                                2,   2,   3,   3, true",
            "square,     polygon inside the rect,                   -5,  -5,  20,  20, true",
            "square,     sharing the right edge,                    10,   0,   5,  10, false",
            "square,     sharing part of the right edge,            10,   2,   5,   3, false",
            "square,     touching a corner,                         10,  10,   5,   5, false",
            "square,     overlapping a corner,                       8,   8,   5,   5, true",
            "square,     far away,                                  20,  20,   5,   5, false",
            "cup,        filling the notch exactly,                  4,   0,   2,   8, false",
            "cup,        filling the notch and one more row,         4,   0,   2,   9, true",
            "cup,        wider than the notch,                       3,   0,   4,   8, true",
            "cup,        above the notch,                            4,  -3,   2,   3, false",
            "cup,        lid across the whole top,                  -1,  -5,  12,   5, false",
            "triangle,   corner touching the long side,              5,   5,   5,   5, false",
            "triangle,   corner over the long side,                  4,   4,   5,   5, true",
            "triangle,   sharing the top side,                       0,  -5,  10,   5, false",
            "diamond,    corners touching all four sides,          2.5, 2.5,   5,   5, true",
            "diamond,    in a corner of the bounds,                  0,   0,   2,   2, false",
            "diamond,    corner touching a side,                     0,   0, 2.5, 2.5, false",
            "diamond,    corner over a side,                         0,   0,   3,   3, true",
            "diamond,    the bounds,                                 0,   0,  10,  10, true",
            "ell,        the missing corner,                         5,   5,   5,   5, false",
            "ell,        the missing corner moved in,                4,   4,   5,   5, true",
            "crown,      the V's bounding box,                       0,   0,  10,   5, true",
    })
    void polygonRect_table(String shape, String scenario, float rx, float ry, float rw, float rh, boolean expected) {
        assertPolygonRect(expected, TestShapes.get(shape), rx, ry, rw, rh);
    }

    /** A rectangle of size 0 behaves as a segment (or a point): it must reach the inside. */
    @ParameterizedTest(name = "{0}: {1}")
    @CsvSource({
            "square, segment inside,                    2,   2,   0,   5, true",
            "square, segment along the left edge,       0,   0,   0,  10, false",
            "square, segment along the bottom edge,     0,  10,  10,   0, false",
            "square, segment across,                   -5,   5,  20,   0, true",
            "square, point inside,                      5,   5,   0,   0, true",
            "square, point on an edge,                  0,   5,   0,   0, false",
            "square, point at a corner,                10,  10,   0,   0, false",
            "cup,    segment across the notch's mouth,  4,   0,   2,   0, false",
            "cup,    segment down the notch,            5,   0,   0,   9, true",
    })
    void polygonRect_zeroSize(String shape, String scenario, float rx, float ry, float rw, float rh, boolean expected) {
        assertPolygonRect(expected, TestShapes.get(shape), rx, ry, rw, rh);
    }

    @ParameterizedTest(name = "{0} as argument {1}")
    @CsvSource({"NaN, 0", "NaN, 1", "NaN, 2", "NaN, 3", "-1, 2", "-1, 3"})
    void polygonRect_nanOrNegativeSizeIsNoCollision(float bad, int slot) {
        float[] v = {2, 2, 3, 3};
        v[slot] = bad;
        assertFalse(Collide.polygonRect(TestShapes.SQUARE, v[0], v[1], v[2], v[3]));
    }

    @Provide
    Arbitrary<float[]> polygons() {
        return TestShapes.simplePolygons(6, 6);
    }

    @Property(tries = 1500)
    void polygonRect_agreesWithExactReference(@ForAll("polygons") float[] xy,
                                              @ForAll @IntRange(min = -1, max = 6) int rx, @ForAll @IntRange(min = -1, max = 6) int ry,
                                              @ForAll @IntRange(min = 0, max = 4) int rw, @ForAll @IntRange(min = 0, max = 4) int rh) {
        assertEquals(reference(xy, rx, ry, rw, rh), Collide.polygonRect(xy, rx, ry, rw, rh));
    }

    /** Rectangles as polygons: polygonRect must agree with polygonPolygon on the four corners. */
    @Property(tries = 1000)
    void polygonRect_agreesWithPolygonPolygonOnTheCorners(@ForAll("polygons") float[] xy,
                                                          @ForAll @IntRange(min = -1, max = 6) int rx, @ForAll @IntRange(min = -1, max = 6) int ry,
                                                          @ForAll @IntRange(min = 1, max = 4) int rw, @ForAll @IntRange(min = 1, max = 4) int rh) {
        float[] rect = ExactReference.rectPolygon(rx, ry, rw, rh);
        assertEquals(Collide.polygonPolygon(xy, rect), Collide.polygonRect(xy, rx, ry, rw, rh));
    }

    @Property(tries = 1000)
    void polygonRect_sameForAnyWindingStartOrPlace(@ForAll("polygons") float[] xy,
                                                   @ForAll @IntRange(min = -1, max = 6) int rx, @ForAll @IntRange(min = -1, max = 6) int ry,
                                                   @ForAll @IntRange(min = 0, max = 4) int rw, @ForAll @IntRange(min = 0, max = 4) int rh,
                                                   @ForAll @IntRange(min = 0, max = 6) int start,
                                                   @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
                                                   @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        boolean here = Collide.polygonRect(xy, rx, ry, rw, rh);
        assertEquals(here, Collide.polygonRect(ExactReference.reversed(xy), rx, ry, rw, rh), "other winding");
        assertEquals(here, Collide.polygonRect(ExactReference.rotated(xy, start % (xy.length / 2)), rx, ry, rw, rh), "other start");
        assertEquals(here, Collide.polygonRect(ExactReference.translated(xy, dx, dy), rx + dx, ry + dy, rw, rh), "moved");
    }

    /**
     * A convex {@code Polygon} goes the separating-edge way ({@code Polygons.convexRectOverlap}),
     * the raw call the general way; the exact reference knows nothing of either. Convex rings
     * on half pixels and rectangles on whole ones (so that they touch), moved by fractions and
     * far out where every corner is still a float (the reference takes the rectangle as a
     * polygon of float corners). A seeded loop, not a jqwik property: since 1.10
     * jqwik's maintainers ask AI coding agents not to use it (its Anti-AI Usage Clause), and
     * this test was written by one.
     */
    @org.junit.jupiter.api.Test
    void convexPolygonRect_agreesWithExactReference() {
        java.util.SplittableRandom rnd = new java.util.SplittableRandom(2911);
        int meeting = 0, total = 3_000;
        for (int i = 0; i < total; i++) {
            float[] xy = TestShapes.convexRing(rnd, 3 + rnd.nextInt(6), 20, 20, true).raw();
            float shift = new float[] {0, 0.25f, -1000.75f, 1_000_000}[rnd.nextInt(4)];
            float[] moved = new float[xy.length];
            for (int k = 0; k < xy.length; k++) {
                moved[k] = xy[k] + shift;
            }
            float x = rnd.nextInt(70) - 25 + shift, y = rnd.nextInt(70) - 25 + shift;
            float w = 1 + rnd.nextInt(30), h = 1 + rnd.nextInt(30);
            boolean expected = ExactReference.polygonsMeet(moved, ExactReference.rectPolygon(x, y, w, h));
            String where = Polygon.of(moved) + " and " + new Rect(x, y, w, h);
            assertEquals(expected, Collide.polygonRect(moved, x, y, w, h), "raw: " + where);
            assertEquals(expected, Polygon.of(moved).overlaps(new Rect(x, y, w, h)), "polygon first: " + where);
            assertEquals(expected, new Rect(x, y, w, h).overlaps(Polygon.of(moved)), "rect first: " + where);
            meeting += expected ? 1 : 0;
        }
        org.junit.jupiter.api.Assertions.assertTrue(meeting > total / 5 && meeting < total * 4 / 5, meeting + " of " + total + " meet");
    }
}
