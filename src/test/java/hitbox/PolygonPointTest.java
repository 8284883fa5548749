package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Collide.polygonPoint and Polygon.contains: strictly inside, exact, any simple polygon. */
class PolygonPointTest {

    /** One case, every way: both windings, every starting vertex, moved by a million, as a shape. */
    static void assertPolygonPoint(boolean expected, float[] xy, float px, float py) {
        int n = xy.length / 2;
        for (float shift : new float[] {0, 1_000_000, -1_000_000}) {
            float[] moved = ExactReference.translated(xy, shift, -shift);
            for (float[] wound : new float[][] {moved, ExactReference.reversed(moved)}) {
                for (int start = 0; start < n; start++) {
                    float[] v = ExactReference.rotated(wound, start);
                    assertEquals(expected, Collide.polygonPoint(v, px + shift, py - shift),
                            "from vertex " + start + " shifted by " + shift);
                }
            }
            assertEquals(expected, Polygon.of(moved).contains(px + shift, py - shift), "shape, shifted by " + shift);
        }
        assertEquals(expected, ExactReference.polygonPoint(xy, px, py), "the reference agrees");
    }

    @ParameterizedTest(name = "{0} ({1}, {2})")
    @CsvSource({
            "square,  5,  5, true",
            "square,  1,  9, true",
            "square,  0,  5, false",   // left edge
            "square, 10,  5, false",   // right edge
            "square,  5,  0, false",   // top edge
            "square,  5, 10, false",   // bottom edge
            "square,  0,  0, false",   // corners
            "square, 10, 10, false",
            "square, 10,  0, false",
            "square,  0, 10, false",
            "square, -1,  5, false",
            "square, 11,  5, false",
            "square,  5, -1, false",
            "square,  5, 11, false",
            "triangle, 4, 5, true",
            "triangle, 5, 5, false",   // on the slanted edge
            "triangle, 6, 5, false",
    })
    void polygonPoint_insideEdgesAndCorners(String shape, float px, float py, boolean expected) {
        assertPolygonPoint(expected, TestShapes.named(shape), px, py);
    }

    /** Rays through vertices and along edges: decided by the half-open rule, not by luck. */
    @ParameterizedTest(name = "{0} ({1}, {2})")
    @CsvSource({
            "diamond,  2,  5, true",     // the ray passes the right corner (10, 5)
            "diamond,  5,  5, true",
            "diamond, -1,  5, false",    // the ray passes both side corners
            "diamond,  0,  5, false",    // at a corner
            "diamond, 11,  5, false",
            "diamond,  5,  0, false",
            "crown,    2,  5, true",     // the ray touches the notch's bottom corner (5, 5)
            "crown,    7,  5, true",
            "crown,    5,  5, false",    // at that corner
            "crown,    5,  4, false",    // in the notch
            "crown,    5,  6, true",
            "crown,   -1,  5, false",
            "crown,   -1,  0, false",    // the ray passes the two top corners
            "crown,    2,  0, false",    // the ray along y = 0 touches (10, 0) but starts in the notch
            "ell,      2,  5, true",     // the ray runs along the edge (5, 5)-(10, 5)
            "ell,      7,  5, false",    // on that edge
            "ell,      5,  5, false",    // at the inner corner
            "ell,      7,  4, true",
            "ell,      7,  6, false",
            "ell,     -1,  5, false",
            "ell,     12,  5, false",
            "cup,      5,  4, false",    // in the notch
            "cup,      5,  9, true",
            "cup,      2,  8, true",     // level with the notch bottom
            "cup,     -1,  8, false",
            "cup,      5,  8, false",    // on the notch bottom
            "doubleV,  1,  6, true",     // the ray passes both notch bottoms
            "doubleV,  3,  6, false",
            "doubleV,  6,  6, true",
            "doubleV, -1,  6, false",
            "doubleV,  6,  1, true",     // just under the middle peak (6, 0)
            "doubleV,  3,  3, false",    // in the left notch
            "doubleV,  6,  0, false",    // at the middle peak
            "squareWithMidpoint, 5, 5, true",
            "squareWithMidpoint, 5, 0, false",
    })
    void polygonPoint_rayThroughVertex(String shape, float px, float py, boolean expected) {
        assertPolygonPoint(expected, TestShapes.named(shape), px, py);
    }

    @Test
    void polygonPoint_fewerThanThreeVerticesContainNothing() {
        assertFalse(Collide.polygonPoint(new float[0], 0, 0));
        assertFalse(Collide.polygonPoint(new float[] {0, 0}, 0, 0));
        assertFalse(Collide.polygonPoint(new float[] {0, 0, 10, 10}, 5, 5));
        assertFalse(Collide.polygonPoint(new float[] {0, 0, 10, 10, 5}, 5, 5));
    }

    @Test
    void polygonPoint_oddLastCoordinateIsIgnored() {
        float[] squarePlusOne = {0, 0, 10, 0, 10, 10, 0, 10, 99};
        assertEquals(true, Collide.polygonPoint(squarePlusOne, 5, 5));
        assertEquals(false, Collide.polygonPoint(squarePlusOne, 0, 5));
    }

    @ParameterizedTest
    @CsvSource({"NaN, 5", "5, NaN", "NaN, NaN"})
    void polygonPoint_nanIsNoCollision(float px, float py) {
        for (float[] xy : TestShapes.NAMED.values()) {
            assertFalse(Collide.polygonPoint(xy, px, py));
        }
    }

    @Provide
    Arbitrary<float[]> polygons() {
        return TestShapes.simplePolygons(6, 7);
    }

    /** Points on the half-grid too, so edges and vertices are hit often, and between them. */
    @Property(tries = 2000)
    void polygonPoint_agreesWithWindingNumber(@ForAll("polygons") float[] xy,
                                              @ForAll @IntRange(min = -2, max = 14) int hx,
                                              @ForAll @IntRange(min = -2, max = 14) int hy) {
        float px = hx / 2f, py = hy / 2f;
        assertEquals(ExactReference.polygonPoint(xy, px, py), Collide.polygonPoint(xy, px, py));
    }

    @Property(tries = 1000)
    void polygonPoint_sameForAnyWindingStartOrPlace(@ForAll("polygons") float[] xy,
                                                    @ForAll @IntRange(min = -1, max = 7) int px, @ForAll @IntRange(min = -1, max = 7) int py,
                                                    @ForAll @IntRange(min = 0, max = 6) int start,
                                                    @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
                                                    @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        boolean here = Collide.polygonPoint(xy, px, py);
        assertEquals(here, Collide.polygonPoint(ExactReference.reversed(xy), px, py), "reversed");
        assertEquals(here, Collide.polygonPoint(ExactReference.rotated(xy, start % (xy.length / 2)), px, py), "rotated");
        assertEquals(here, Collide.polygonPoint(ExactReference.translated(xy, dx, dy), px + dx, py + dy), "moved");
    }

    /** A rectangle's four corners as a polygon answer exactly as rectPoint, zero sizes included. */
    @Property(tries = 3000)
    void polygonPoint_rectCornersAgreeWithRectPoint(@ForAll @IntRange(min = -5, max = 5) int rx, @ForAll @IntRange(min = -5, max = 5) int ry,
                                                    @ForAll @IntRange(min = 0, max = 5) int rw, @ForAll @IntRange(min = 0, max = 5) int rh,
                                                    @ForAll @IntRange(min = -7, max = 11) int px, @ForAll @IntRange(min = -7, max = 11) int py,
                                                    @ForAll boolean reverse) {
        float[] corners = ExactReference.rectPolygon(rx, ry, rw, rh);
        float[] xy = reverse ? ExactReference.reversed(corners) : corners;
        assertEquals(Collide.rectPoint(rx, ry, rw, rh, px, py), Collide.polygonPoint(xy, px, py));
    }
}
