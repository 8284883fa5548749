package hitbox;

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

import static hitbox.ContactFixtures.assertPushOutTouches;
import static hitbox.ContactFixtures.assertReversed;
import static hitbox.ContactFixtures.assertUnit;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class CircleCircleContactTest {

    @ParameterizedTest
    @CsvSource({
        // x1, y1, r1, x2, y2, r2, nx, ny, depth
        "0, 0, 10, 15, 0, 10, 1, 0, 5",
        "0, 0, 10, -15, 0, 10, -1, 0, 5",
        "0, 0, 10, 0, 12, 5, 0, 1, 3",
        "0, 0, 5, 3, 4, 5, 0.6, 0.8, 5",          // 3-4-5: distance 5, reach 10
        "10, 20, 3, 10, 21, 1, 0, 1, 3",          // small circle almost centred in the big one
        "0, 0, 10, 1, 0, 0, 1, 0, 9",             // radius 0: a point inside
        "0, 0, 0, 0, -2, 10, 0, -1, 8",           // point first
    })
    void circleCircle_overlapping(float x1, float y1, float r1, float x2, float y2, float r2,
                                  float nx, float ny, float depth) {
        Contact c = Raw.contactCircleCircle(x1, y1, r1, x2, y2, r2);
        assertNotNull(c);
        assertEquals(nx, c.nx(), 1e-6);
        assertEquals(ny, c.ny(), 1e-6);
        assertEquals(depth, c.depth(), 1e-5);
        assertReversed(c, Raw.contactCircleCircle(x2, y2, r2, x1, y1, r1));
        assertEquals(c, new Circle(x1, y1, r1).contact(new Circle(x2, y2, r2)));
    }

    @ParameterizedTest
    @CsvSource({
        "0, 0, 10, 20, 0, 10",      // touching side by side
        "0, 0, 5, 6, 8, 5",         // touching on a 3-4-5 diagonal
        "0, 0, 10, 30, 0, 10",      // apart
        "0, 0, 10, 10, 0, 0",       // a point on the outline
        "0, 0, 0, 0, 0, 0",         // two points at the same place: no insides
        "0, 0, 0, 3, 4, 0",         // two points apart
    })
    void circleCircle_touchingOrApart_isNull(float x1, float y1, float r1, float x2, float y2, float r2) {
        assertNull(Raw.contactCircleCircle(x1, y1, r1, x2, y2, r2));
        assertNull(Raw.contactCircleCircle(x2, y2, r2, x1, y1, r1));
    }

    @ParameterizedTest
    @CsvSource({
        "0, 0, 10, 0, 0, 10, 20",
        "5, 5, 3, 5, 5, 1, 4",
        "0, 0, 0, 0, 0, 5, 5",
        "-7, 9, 2, -7, 9, 0, 2",
    })
    void circleCircle_coincidentCentres_pushB_down(float x1, float y1, float r1, float x2, float y2, float r2, float depth) {
        // Documented: normal (0, 1), so a goes up out of b; the same in both orders.
        for (Contact c : new Contact[] {Raw.contactCircleCircle(x1, y1, r1, x2, y2, r2), Raw.contactCircleCircle(x2, y2, r2, x1, y1, r1)}) {
            assertEquals(0, c.nx());
            assertEquals(1, c.ny());
            assertEquals(depth, c.depth());
            assertEquals(Side.TOP, c.side());
        }
    }

    @ParameterizedTest
    @CsvSource({
        "1000000, 0", "0, 1000000", "-1000000, 999999", "123456, -654321",
    })
    void circleCircle_hugeCoordinates_sameContact(float dx, float dy) {
        Contact near = Raw.contactCircleCircle(0, 0, 5, 3, 4, 5);
        Contact far = Raw.contactCircleCircle(dx, dy, 5, 3 + dx, 4 + dy, 5);
        assertEquals(near, far);
        assertNull(Raw.contactCircleCircle(dx, dy, 5, 6 + dx, 8 + dy, 5), "touching stays touching far away");
    }

    @Test
    void circleCircle_hairsWidthOverlap_hasPositiveDepth() {
        // Distance^2 = 10^12 - 1 against reach 10^6: depth about 5e-7, still > 0.
        Contact c = Raw.contactCircleCircle(0, 0, 500000, 999999, 1413, 500000);
        if (Collide.circleCircle(0, 0, 500000, 999999, 1413, 500000)) {
            assertNotNull(c);
            assertTrue(c.depth() > 0);
        } else {
            assertNull(c);
        }
    }

    @ParameterizedTest
    @CsvSource({
        "NaN, 0, 1, 0, 0, 1, 'x1 must be a finite number, was NaN'",
        "0, 0, -1, 0, 0, 1, 'r1 must be >= 0, was -1.0'",
        "0, 0, 1, 0, Infinity, 1, 'y2 must be a finite number, was Infinity'",
        "0, 0, 1, 0, 0, -2, 'r2 must be >= 0, was -2.0'",
    })
    void circleCircle_badArguments_areRefusedByTheShapes(float x1, float y1, float r1, float x2, float y2, float r2, String what) {
        // The raw-float form went (issue 30): such values make no circle, so no contact is asked.
        assertThrows(IllegalArgumentException.class, () -> Raw.contactCircleCircle(x1, y1, r1, x2, y2, r2), what);
    }

    // ------------------------------------------------------------------------ properties

    @Provide
    Arbitrary<Circle> circle() {
        return ContactFixtures.circles();
    }

    @Property
    void contactExistsExactlyWhenOverlapping(@ForAll("circle") Circle a, @ForAll("circle") Circle b) {
        assertEquals(a.overlaps(b), a.contact(b) != null);
    }

    @Property(maxDiscardRatio = 20)
    void reversedOrder_flipsNormal_keepsDepth(@ForAll("circle") Circle a, @ForAll("circle") Circle b) {
        Assume.that(a.x() != b.x() || a.y() != b.y());
        assertReversed(a.contact(b), b.contact(a));
    }

    @Property(maxDiscardRatio = 20)
    void depth_isReachMinusDistance_normalIsUnit(@ForAll("circle") Circle a, @ForAll("circle") Circle b) {
        Contact c = a.contact(b);
        Assume.that(c != null);
        assertUnit(c);
        double dist = Math.hypot(b.x() - a.x(), b.y() - a.y());
        assertEquals(a.r() + b.r() - dist, c.depth(), 1e-4);
    }

    @Property
    void translationInvariant(@ForAll("circle") Circle a, @ForAll("circle") Circle b,
                              @ForAll @IntRange(min = -1000000, max = 1000000) int dx,
                              @ForAll @IntRange(min = -1000000, max = 1000000) int dy) {
        assertEquals(a.contact(b), a.translated(dx, dy).contact(b.translated(dx, dy)));
    }

    @Property(maxDiscardRatio = 20)
    void pushingOut_leavesThemTouching(@ForAll("circle") Circle a, @ForAll("circle") Circle b) {
        Contact c = a.contact(b);
        Assume.that(c != null);
        assertPushOutTouches(a, b, c);
    }

    @Property(maxDiscardRatio = 20)
    void depthGoesToZeroAtTouching(@ForAll @IntRange(min = 1, max = 40) int r1, @ForAll @IntRange(min = 0, max = 40) int r2,
                                   @ForAll("pythagorean") int[] t, @ForAll @IntRange(min = 1, max = 1000) int k) {
        // The circles are moved apart along a 3-4-5 direction until they touch (null), and
        // 1/k of a unit short of touching the depth is 1/k.
        int scale = r1 + r2;
        Assume.that(scale % t[2] == 0);
        float x = (float) t[0] * scale / t[2], y = (float) t[1] * scale / t[2];
        assertNull(Raw.contactCircleCircle(0, 0, r1, x, y, r2));
        double shy = 1.0 - 1.0 / k / scale;
        Contact c = Raw.contactCircleCircle(0, 0, r1, (float) (x * shy), (float) (y * shy), r2);
        assertNotNull(c);
        assertEquals(1.0 / k, c.depth(), 1e-5);
    }

    @Provide
    Arbitrary<int[]> pythagorean() {
        return Arbitraries.of(new int[] {3, 4, 5}, new int[] {-4, 3, 5}, new int[] {5, -12, 13}, new int[] {-8, -15, 17},
                new int[] {1, 0, 1}, new int[] {0, -1, 1});
    }
}
