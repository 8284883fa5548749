package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;

/**
 * The Collide polygon methods take raw, unchecked float[]s: repeated vertices (the first one
 * repeated at the end, as a learner might write it) change nothing, and no array, however
 * broken, makes them throw.
 */
class PolygonRawArrayTest {

    /** The square written with its first corner again at the end. */
    static final float[] CLOSED_SQUARE = {0, 0, 10, 0, 10, 10, 0, 10, 0, 0};

    /**
     * A shape inside the square, in the corner that is written twice: when no edge reaches
     * across, the corner itself decides, and it must not be misread as a corner of no width.
     */
    @Test
    void firstVertexRepeatedAtTheEnd_insideShapeInThatCorner() {
        float[] corner = {0, 0, 4, 0, 4, 4, 0, 4};
        assertTrue(Collide.polygonPolygon(CLOSED_SQUARE, corner));
        assertTrue(Collide.polygonPolygon(corner, CLOSED_SQUARE));
        assertTrue(Collide.polygonPolygon(ExactReference.reversed(CLOSED_SQUARE), corner));
        assertTrue(Collide.polygonRect(CLOSED_SQUARE, 0, 0, 4, 4));
        assertTrue(Collide.polygonRect(CLOSED_SQUARE, 0, 0, 10, 10));
        assertTrue(Collide.polygonLine(CLOSED_SQUARE, 0, 0, 4, 4));
    }

    @Provide
    Arbitrary<float[]> polygons() {
        return TestShapes.simplePolygons(6, 6);
    }

    /** The polygon with vertex {@code k} written twice in a row (k = n repeats vertex 0 at the end). */
    static float[] withRepeat(float[] xy, int k) {
        int n = xy.length / 2;
        float[] r = new float[xy.length + 2];
        for (int i = 0, j = 0; i <= n; i++) {
            if (i < n) {
                r[j++] = xy[2 * i];
                r[j++] = xy[2 * i + 1];
            }
            if (i == k) {
                r[j++] = xy[2 * (k % n)];
                r[j++] = xy[2 * (k % n) + 1];
            }
        }
        return r;
    }

    @Property(tries = 2000)
    void repeatedVertices_changeNoAnswer(@ForAll("polygons") float[] xy, @ForAll("polygons") float[] other,
                                         @ForAll @IntRange(min = 0, max = 6) int k,
                                         @ForAll @IntRange(min = -1, max = 7) int x1, @ForAll @IntRange(min = -1, max = 7) int y1,
                                         @ForAll @IntRange(min = -1, max = 7) int x2, @ForAll @IntRange(min = -1, max = 7) int y2,
                                         @ForAll @IntRange(min = 0, max = 3) int size) {
        float[] rep = withRepeat(xy, k % (xy.length / 2 + 1));
        assertEquals(Collide.polygonPoint(xy, x1, y1), Collide.polygonPoint(rep, x1, y1), "point");
        assertEquals(Collide.polygonLine(xy, x1, y1, x2, y2), Collide.polygonLine(rep, x1, y1, x2, y2), "line");
        assertEquals(Collide.polygonCircle(xy, x1, y1, size), Collide.polygonCircle(rep, x1, y1, size), "circle");
        assertEquals(Collide.polygonRect(xy, x1, y1, size, x2 % 4), Collide.polygonRect(rep, x1, y1, size, x2 % 4), "rect");
        float[] moved = ExactReference.translated(other, x2 - 3, y2 - 3);
        assertEquals(Collide.polygonPolygon(xy, moved), Collide.polygonPolygon(rep, moved), "polygon, repeats first");
        assertEquals(Collide.polygonPolygon(moved, xy), Collide.polygonPolygon(moved, rep), "polygon, repeats second");
    }

    @Provide
    Arbitrary<float[]> anyArrays() {
        return Arbitraries.integers().between(0, 4).list().ofMaxSize(13).map(PolygonRawArrayTest::toFloats);
    }

    private static float[] toFloats(List<Integer> l) {
        float[] xy = new float[l.size()];
        for (int i = 0; i < xy.length; i++) {
            xy[i] = l.get(i);
        }
        return xy;
    }

    /** Short, odd, crossing, flat or repeating: every method answers, none throws. */
    @Property(tries = 3000)
    void brokenArrays_neverThrow(@ForAll("anyArrays") float[] xy, @ForAll("anyArrays") float[] other,
                                 @ForAll @IntRange(min = -1, max = 5) int x1, @ForAll @IntRange(min = -1, max = 5) int y1,
                                 @ForAll @IntRange(min = -1, max = 5) int x2, @ForAll @IntRange(min = -1, max = 5) int y2) {
        Collide.polygonPoint(xy, x1, y1);
        Collide.polygonLine(xy, x1, y1, x2, y2);
        Collide.polygonCircle(xy, x1, y1, x2);
        Collide.polygonRect(xy, x1, y1, Math.abs(x2), Math.abs(y2));
        Collide.polygonRect(xy, x1, y1, 0, Math.abs(y2));
        Collide.polygonPolygon(xy, other);
        Collide.polygonPolygon(other, xy);
    }
}
