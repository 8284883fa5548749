package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class RectIntersectionTest {

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            // scenario,        rect a,         rect b,            overlap (x y w h)
            "cornerOverlap,     0 0 10 10,      5 5 10 10,         5 5 5 5",
            "containment,       0 0 10 10,      2 3 4 5,           2 3 4 5",
            "coincident,        0 0 10 10,      0 0 10 10,         0 0 10 10",
            "strip,             0 0 10 10,      -5 4 20 2,         0 4 10 2",
            "hugeCoordinates,   1000000 1000000 10 10, 1000005 1000005 10 10, 1000005 1000005 5 5",
    })
    void intersection_overlapping_isTheRegionInsideBoth(String scenario, String a, String b, String expected) {
        Rect ra = rect(a), rb = rect(b), want = rect(expected);
        assertEquals(want, ra.intersection(rb));
        assertEquals(want, rb.intersection(ra), "either order");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "sideBySide,        0 0 10 10,      10 0 10 10",
            "cornerToCorner,    0 0 10 10,      10 10 5 5",
            "apart,             0 0 10 10,      20 20 5 5",
            "zeroSizeOnEdge,    0 0 10 10,      10 5 0 0",
    })
    void intersection_touchingOrApart_isNull(String scenario, String a, String b) {
        assertNull(rect(a).intersection(rect(b)));
        assertNull(rect(b).intersection(rect(a)));
    }

    @Test
    void intersection_null_namesTheParameter() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Rect(0, 0, 1, 1).intersection(null));
        assertEquals("other must not be null", e.getMessage());
    }

    @Property(tries = 2000)
    void intersection_existsExactlyWhenTheyOverlap_andLiesInBoth(
            @ForAll @IntRange(min = -20, max = 20) int x1, @ForAll @IntRange(min = -20, max = 20) int y1,
            @ForAll @IntRange(min = 1, max = 20) int w1, @ForAll @IntRange(min = 1, max = 20) int h1,
            @ForAll @IntRange(min = -20, max = 20) int x2, @ForAll @IntRange(min = -20, max = 20) int y2,
            @ForAll @IntRange(min = 1, max = 20) int w2, @ForAll @IntRange(min = 1, max = 20) int h2) {
        Rect a = new Rect(x1, y1, w1, h1), b = new Rect(x2, y2, w2, h2);
        Rect overlap = a.intersection(b);
        assertEquals(a.overlaps(b), overlap != null);
        if (overlap != null) {
            // Its centre is inside both, and it reaches no further than either.
            assertEquals(true, a.contains(overlap.centerX(), overlap.centerY()) && b.contains(overlap.centerX(), overlap.centerY()));
            assertEquals(overlap, overlap.intersection(a));
            assertEquals(overlap, overlap.intersection(b));
        }
    }

    private static Rect rect(String xywh) {
        String[] v = xywh.trim().split("\\s+");
        return new Rect(Float.parseFloat(v[0]), Float.parseFloat(v[1]), Float.parseFloat(v[2]), Float.parseFloat(v[3]));
    }
}
