package hitbox;

import net.jqwik.api.Arbitrary;
import net.jqwik.api.Assume;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import static hitbox.ContactFixtures.assertNoShorterMove;
import static hitbox.ContactFixtures.assertPushOutTouches;
import static hitbox.ContactFixtures.assertReversed;
import static hitbox.ContactFixtures.assertReversedOrSymmetricTie;
import static hitbox.ContactFixtures.assertUnit;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class CircleRectContactTest {

    @ParameterizedTest
    @CsvSource({
        // cx, cy, r, rx, ry, rw, rh, nx, ny, depth
        "-3, 5, 5, 0, 0, 10, 10, 1, 0, 2",        // centre left of the rect, reaching in
        "5, 13, 5, 0, 0, 10, 10, 0, -1, 2",       // centre below
        "5, -4, 5, 0, 0, 10, 10, 0, 1, 1",        // centre above: the circle sits on top
        "-3, -4, 10, 0, 0, 10, 10, 0.6, 0.8, 5",  // near the top-left corner
        "13, 14, 10, 0, 0, 10, 10, -0.6, -0.8, 5",// near the bottom-right corner
        "10, 25, 5, 0, 0, 100, 50, 1, 0, 15",     // centre inside, left edge nearest: out to the left
        "90, 25, 5, 0, 0, 100, 50, -1, 0, 15",    // right edge nearest
        "50, 47, 5, 0, 0, 100, 50, 0, -1, 8",     // bottom edge nearest: out downwards
        "50, 4, 5, 0, 0, 100, 50, 0, 1, 9",       // top edge nearest: out upwards
        "5, 5, 1, 0, 0, 10, 10, 0, 1, 6",         // centre in the middle of a square: tie, out the top
        "0, 0, 100, -1, -1, 2, 2, 0, 1, 101",     // the rect inside the circle
        "0, 5, 3, 0, 0, 10, 10, 1, 0, 3",         // centre on the left edge: out left by r
        "0, 0, 10, 3, 4, 0, 0, 0.6, 0.8, 5",      // a zero-size rect (a point) inside the circle
        "0, 0, 10, 3, -20, 0, 40, 1, 0, 7",       // a zero-width rect (a segment) through the circle
        "5, 5, 0, 0, 0, 10, 20, 0, 1, 5",         // radius 0: a point inside, top/left/right tie
        "3, 5, 0, 0, 0, 10, 20, 1, 0, 3",         // radius 0: left edge nearest
    })
    void circleRect_overlapping(float cx, float cy, float r, float rx, float ry, float rw, float rh,
                                float nx, float ny, float depth) {
        Contact c = Raw.contactCircleRect(cx, cy, r, rx, ry, rw, rh);
        assertNotNull(c);
        assertEquals(nx, c.nx(), 1e-6, "nx");
        assertEquals(ny, c.ny(), 1e-6, "ny");
        assertEquals(depth, c.depth(), 1e-5, "depth");
        Circle circle = new Circle(cx, cy, r);
        Rect rect = new Rect(rx, ry, rw, rh);
        assertEquals(c, circle.contact(rect));
        assertEquals(rect.contact(circle), Raw.contactRectCircle(rx, ry, rw, rh, cx, cy, r));
        assertReversedOrSymmetricTie(circle, rect, c, rect.contact(circle));
        assertPushOutTouches(circle, rect, c);
    }

    @ParameterizedTest
    @CsvSource({
        "-5, 5, 5, 0, 0, 10, 10",     // touching the left edge
        "5, 15, 5, 0, 0, 10, 10",     // touching the bottom edge
        "-3, -4, 5, 0, 0, 10, 10",    // touching the corner on a 3-4-5 diagonal
        "-30, 5, 5, 0, 0, 10, 10",    // apart
        "0, 5, 0, 0, 0, 10, 10",      // a point on the edge
        "0, 0, 0, 0, 0, 10, 10",      // a point on the corner
        "5, 5, 0, 5, 5, 0, 0",        // a point and a zero-size rect at the same place
        "5, 5, 0, 0, 0, 10, 0",       // a point and a zero-height rect: no insides
        "20, 5, 10, 30, 0, 0, 10",    // circle touching a zero-width rect
    })
    void circleRect_touchingOrApart_isNull(float cx, float cy, float r, float rx, float ry, float rw, float rh) {
        assertNull(Raw.contactCircleRect(cx, cy, r, rx, ry, rw, rh));
        assertNull(Raw.contactRectCircle(rx, ry, rw, rh, cx, cy, r));
    }

    @ParameterizedTest
    @CsvSource({"1000000, 0", "0, -1000000", "999999, 999999", "-123456, 654321"})
    void circleRect_hugeCoordinates_sameContact(float dx, float dy) {
        assertEquals(Raw.contactCircleRect(-3, -4, 10, 0, 0, 10, 10), Raw.contactCircleRect(-3 + dx, -4 + dy, 10, dx, dy, 10, 10));
        assertEquals(Raw.contactCircleRect(10, 25, 5, 0, 0, 100, 50), Raw.contactCircleRect(10 + dx, 25 + dy, 5, dx, dy, 100, 50));
        assertNull(Raw.contactCircleRect(-3 + dx, -4 + dy, 5, dx, dy, 10, 10), "touching stays touching far away");
    }

    @ParameterizedTest
    @CsvSource({
        "0, 0, -1, 0, 0, 1, 1, 'r must be >= 0, was -1.0'",
        "0, 0, 1, 0, 0, -1, 1, 'rw must be >= 0, was -1.0'",
        "0, NaN, 1, 0, 0, 1, 1, 'cy must be a finite number, was NaN'",
        "0, 0, 1, 0, -Infinity, 1, 1, 'ry must be a finite number, was -Infinity'",
    })
    void circleRect_badArguments_areRefusedByTheShapes(float cx, float cy, float r, float rx, float ry, float rw, float rh, String what) {
        // The raw-float forms went (issue 30): such values make no shape, so no contact is asked.
        assertThrows(IllegalArgumentException.class, () -> Raw.contactCircleRect(cx, cy, r, rx, ry, rw, rh), what);
        assertThrows(IllegalArgumentException.class, () -> Raw.contactRectCircle(rx, ry, rw, rh, cx, cy, r), what);
    }

    // ------------------------------------------------------------------------ properties

    @Provide
    Arbitrary<Circle> circle() {
        return ContactFixtures.circles();
    }

    @Provide
    Arbitrary<Rect> rect() {
        return ContactFixtures.rects();
    }

    @Property
    void contactExistsExactlyWhenOverlapping(@ForAll("circle") Circle a, @ForAll("rect") Rect b) {
        assertEquals(a.overlaps(b), a.contact(b) != null);
        assertEquals(b.overlaps(a), b.contact(a) != null);
    }

    @Property
    void reversedOrder_flipsNormal_keepsDepth(@ForAll("circle") Circle a, @ForAll("rect") Rect b) {
        assertReversedOrSymmetricTie(a, b, a.contact(b), b.contact(a));
    }

    @Property(maxDiscardRatio = 20)
    void normalIsUnit_depthPositive(@ForAll("circle") Circle a, @ForAll("rect") Rect b) {
        Contact c = a.contact(b);
        Assume.that(c != null);
        assertUnit(c);
        assertTrue(c.depth() > 0);
    }

    @Property
    void translationInvariant(@ForAll("circle") Circle a, @ForAll("rect") Rect b,
                              @ForAll @IntRange(min = -1000000, max = 1000000) int dx,
                              @ForAll @IntRange(min = -1000000, max = 1000000) int dy) {
        assertEquals(a.contact(b), a.translated(dx, dy).contact(b.translated(dx, dy)));
    }

    @Property(maxDiscardRatio = 20)
    void pushingOut_leavesThemTouching(@ForAll("circle") Circle a, @ForAll("rect") Rect b) {
        Contact c = a.contact(b);
        Assume.that(c != null);
        assertPushOutTouches(a, b, c);
        assertPushOutTouches(b, a, b.contact(a));
    }

    @Property(tries = 300, maxDiscardRatio = 20)
    void depthIsTheMinimumTranslation(@ForAll("circle") Circle a, @ForAll("rect") Rect b) {
        Contact c = a.contact(b);
        Assume.that(c != null);
        assertNoShorterMove(a, b, c);
        double slow = ContactFixtures.slowDepth(a, b);
        assertEquals(slow, c.depth(), 1e-4 + 1e-5 * c.depth());
    }
}
