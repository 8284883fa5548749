package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Collide.trianglePoint: strictly inside, either winding, the same answer as polygonPoint. */
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
        assertEquals(GeometryReference.polygonPoint(xy, px, py), t, "reference");
    }
}
