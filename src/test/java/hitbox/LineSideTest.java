package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class LineSideTest {

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            // scenario,                 x1, y1, x2, y2, px, py, side
            "eastThenBelowIsRight,        0,  0, 10,  0,  5,  3,  1",
            "eastThenAboveIsLeft,         0,  0, 10,  0,  5, -3, -1",
            "onTheLine,                   0,  0, 10,  0, 20,  0,  0",
            "onAnEnd,                     0,  0, 10, 10, 10, 10,  0",
            "verticalDownThenWestIsRight, 0,  0,  0, 10, -1,  5,  1",
            "zeroLengthLineHasNoSides,    3,  3,  3,  3,  7,  1,  0",
            "hugeWholeNumbers,            1000000, 1000000, 1000003, 1000001, 1000006, 1000003, 1",
            "hugeCollinear,               1000000, 1000000, 1000003, 1000001, 1000006, 1000002, 0",
            "nanGivesZero,                0,  0, 10,  0,  NaN, 3,  0",
    })
    void lineSide_table(String scenario, float x1, float y1, float x2, float y2, float px, float py, int expected) {
        assertEquals(expected, Collide.lineSide(x1, y1, x2, y2, px, py));
        if (!Float.isNaN(px)) {
            assertEquals(expected, new Segment(x1, y1, x2, y2).side(px, py), "through the segment");
            assertEquals(-expected, Collide.lineSide(x2, y2, x1, y1, px, py), "walking the other way swaps the sides");
        }
    }

    @Property(tries = 2000)
    void lineSide_agreesWithAnExactCrossProduct(@ForAll @IntRange(min = -3000, max = 3000) int x1, @ForAll @IntRange(min = -3000, max = 3000) int y1,
                                                @ForAll @IntRange(min = -3000, max = 3000) int x2, @ForAll @IntRange(min = -3000, max = 3000) int y2,
                                                @ForAll @IntRange(min = -3000, max = 3000) int px, @ForAll @IntRange(min = -3000, max = 3000) int py) {
        long cross = (long) (x2 - x1) * (py - y1) - (long) (y2 - y1) * (px - x1);
        assertEquals(Long.signum(cross), Collide.lineSide(x1, y1, x2, y2, px, py));
        assertEquals(Long.signum(cross), Collide.lineSide(x1 + 1_000_000, y1 - 1_000_000, x2 + 1_000_000, y2 - 1_000_000, px + 1_000_000, py - 1_000_000), "translated");
    }
}
