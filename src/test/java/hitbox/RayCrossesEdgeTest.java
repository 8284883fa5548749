package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;

import net.jqwik.api.Arbitrary;
import net.jqwik.api.Assume;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Collide.rayCrossesEdge: polygonPoint's counting rule, edge by edge. */
class RayCrossesEdgeTest {

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            // scenario,                       ax, ay, bx, by, px, py, crosses
            "edgeRightOfThePoint,              10,  0, 10, 10,  5,  5, true",
            "edgeLeftOfThePoint,                0,  0,  0, 10,  5,  5, false",
            "edgeAboveThePoint,                 0,  0, 10,  0,  5,  5, false",
            "lowerEndAtTheLevelCounts,         10,  5, 10, 10,  5,  5, true",
            "upperEndAtTheLevelDoesNot,        10,  0, 10,  5,  5,  5, false",
            "horizontalAtTheLevelDoesNot,      10,  5, 20,  5,  5,  5, false",
            "pointOnTheEdgeIsNotACrossing,     10,  0, 10, 10, 10,  5, false",
            "eitherDirectionOfTheEdge,         10, 10, 10,  0,  5,  5, true",
            "slantedCrossingRight,              0,  0, 20, 10,  5,  5, true",
            "slantedCrossingLeft,               0,  0, 20, 10, 15,  5, false",
            "hugeWholeNumbers,            1000010, 1000000, 1000010, 1000010, 1000005, 1000005, true",
    })
    void rayCrossesEdge_table(String scenario, float ax, float ay, float bx, float by, float px, float py, boolean expected) {
        assertEquals(expected, Collide.rayCrossesEdge(ax, ay, bx, by, px, py));
    }

    @Provide
    Arbitrary<float[]> polygons() {
        return TestShapes.simplePolygons(6, 7);
    }

    @Property(tries = 3000)
    void rayCrossesEdge_oddCountExactlyWhenPolygonPointSaysInside(@ForAll("polygons") float[] xy,
                                                                   @ForAll @IntRange(min = -1, max = 7) int px,
                                                                   @ForAll @IntRange(min = -1, max = 7) int py) {
        int n = xy.length / 2;
        int count = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            Assume.that(!Lines.segmentPoint(xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1], px, py));
            if (Collide.rayCrossesEdge(xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1], px, py)) {
                count++;
            }
        }
        assertEquals(Collide.polygonPoint(xy, px, py), count % 2 == 1);
    }
}
