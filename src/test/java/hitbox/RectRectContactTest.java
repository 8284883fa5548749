package hitbox;

import net.jqwik.api.Arbitrary;
import net.jqwik.api.Assume;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import static hitbox.ContactFixtures.assertNoShorterMove;
import static hitbox.ContactFixtures.assertPushOutTouches;
import static hitbox.ContactFixtures.assertReversed;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

class RectRectContactTest {

    @ParameterizedTest
    @CsvSource({
        // x1, y1, w1, h1, x2, y2, w2, h2, nx, ny, depth
        "0, 0, 10, 10, 8, 2, 10, 6, 1, 0, 2",        // b overlaps a's right edge: b goes right
        "0, 0, 10, 10, -8, 2, 10, 6, -1, 0, 2",      // a's left edge
        "0, 0, 10, 10, 2, 7, 6, 10, 0, 1, 3",        // b below: a stands on b
        "0, 0, 10, 10, 2, -9, 6, 10, 0, -1, 1",      // b above
        "0, 0, 100, 100, 10, 40, 5, 5, -1, 0, 15",   // small b inside a, near a's left edge: out to the left
        "0, 0, 100, 100, 90, 40, 5, 5, 1, 0, 10",    // near the right edge: out to the right
        "0, 0, 100, 100, 40, 96, 5, 2, 0, 1, 4",     // near the bottom: out downwards
        "40, 40, 5, 5, 0, 0, 100, 100, 0, 1, 45",    // small a inside big b: down and right tie at 45, down wins
        "0, 0, 10, 10, 5, 5, 10, 10, 0, 1, 5",       // corner overlap with equal depths: vertical wins
        "0, 0, 10, 10, 4, -20, 0, 50, -1, 0, 4",     // a zero-width rect (a segment) through a
        "0, 0, 10, 10, 3, 4, 0, 0, -1, 0, 3",        // a zero-size rect (a point) inside a
        "0, 0, 10, 0, 4, -4, 2, 10, 0, 1, 4",        // a zero-height a through b
    })
    void rectRect_overlapping(float x1, float y1, float w1, float h1, float x2, float y2, float w2, float h2,
                              float nx, float ny, float depth) {
        Contact c = Raw.contactRectRect(x1, y1, w1, h1, x2, y2, w2, h2);
        assertNotNull(c);
        assertEquals(nx, c.nx(), "nx");
        assertEquals(ny, c.ny(), "ny");
        assertEquals(depth, c.depth(), "depth");
        Rect a = new Rect(x1, y1, w1, h1), b = new Rect(x2, y2, w2, h2);
        assertEquals(c, a.contact(b));
        // None of these is placed symmetrically, so the reverse is the exact flip.
        assertEquals(c.flipped(), b.contact(a));
        assertPushOutTouches(a, b, c);
        assertPushOutTouches(b, a, c.flipped());
    }

    @Test
    void rectRect_sameRectangle_tieGoesUp_inBothOrders() {
        // Symmetric placement: no rule can give opposite normals, documented as (0, 1).
        Rect a = new Rect(0, 0, 10, 10);
        assertEquals(new Contact(0, 1, 10), a.contact(a));
        assertEquals(new Contact(0, 1, 4), new Rect(0, 0, 10, 4).contact(new Rect(3, 0, 4, 4)));
        assertEquals(new Contact(0, 1, 4), new Rect(3, 0, 4, 4).contact(new Rect(0, 0, 10, 4)));
    }

    @ParameterizedTest
    @CsvSource({
        "0, 0, 10, 10, 10, 0, 10, 10",   // side by side
        "0, 0, 10, 10, 0, 10, 10, 10",   // stacked
        "0, 0, 10, 10, 10, 10, 5, 5",    // corner to corner
        "0, 0, 10, 10, 20, 0, 5, 5",     // apart
        "0, 0, 10, 10, 0, 3, 0, 4",      // a zero-width rect along a's left edge
        "0, 0, 10, 10, 10, 10, 0, 0",    // a point on a's corner
    })
    void rectRect_touchingOrApart_isNull(float x1, float y1, float w1, float h1, float x2, float y2, float w2, float h2) {
        assertNull(Raw.contactRectRect(x1, y1, w1, h1, x2, y2, w2, h2));
        assertNull(Raw.contactRectRect(x2, y2, w2, h2, x1, y1, w1, h1));
    }

    @ParameterizedTest
    @CsvSource({"1000000, 0", "0, 1000000", "-999999, 1000000", "654321, -123456"})
    void rectRect_hugeCoordinates_sameContact(float dx, float dy) {
        assertEquals(Raw.contactRectRect(0, 0, 10, 10, 8, 2, 10, 6), Raw.contactRectRect(dx, dy, 10, 10, 8 + dx, 2 + dy, 10, 6));
        assertEquals(Raw.contactRectRect(0, 0, 100, 100, 10, 40, 5, 5), Raw.contactRectRect(dx, dy, 100, 100, 10 + dx, 40 + dy, 5, 5));
        assertNull(Raw.contactRectRect(dx, dy, 10, 10, 10 + dx, dy, 10, 10), "touching stays touching far away");
    }

    @ParameterizedTest
    @CsvSource({
        "0, 0, -1, 1, 0, 0, 1, 1, 'w1 must be >= 0, was -1.0'",
        "0, 0, 1, 1, 0, 0, 1, -3, 'h2 must be >= 0, was -3.0'",
        "NaN, 0, 1, 1, 0, 0, 1, 1, 'x1 must be a finite number, was NaN'",
    })
    void rectRect_badArguments_areRefusedByTheShapes(float x1, float y1, float w1, float h1, float x2, float y2, float w2, float h2, String what) {
        // The raw-float form went (issue 30): such values make no rectangle, so no contact is asked.
        assertThrows(IllegalArgumentException.class, () -> Raw.contactRectRect(x1, y1, w1, h1, x2, y2, w2, h2), what);
    }

    // ------------------------------------------------------------------------ properties

    @Provide
    Arbitrary<Rect> rect() {
        return ContactFixtures.rects();
    }

    @Property
    void contactExistsExactlyWhenOverlapping(@ForAll("rect") Rect a, @ForAll("rect") Rect b) {
        assertEquals(a.overlaps(b), a.contact(b) != null);
    }

    @Property(maxDiscardRatio = 20)
    void reversedOrder_sameDepth_oppositeNormalUnlessSymmetric(@ForAll("rect") Rect a, @ForAll("rect") Rect b) {
        Contact ab = a.contact(b), ba = b.contact(a);
        Assume.that(ab != null);
        assertEquals(ab.depth(), ba.depth());
        // The only normals that can come out the same are a tie between exactly opposite
        // directions, which happens when the two are centred on the same line.
        boolean centredX = 2 * (double) a.x() + a.w() == 2 * (double) b.x() + b.w();
        boolean centredY = 2 * (double) a.y() + a.h() == 2 * (double) b.y() + b.h();
        boolean symmetricTie = (ab.nx() == 0 && centredY) || (ab.ny() == 0 && centredX);
        if (!symmetricTie) {
            assertReversed(ab, ba);
        }
    }

    @Property
    void translationInvariant(@ForAll("rect") Rect a, @ForAll("rect") Rect b,
                              @ForAll @IntRange(min = -1000000, max = 1000000) int dx,
                              @ForAll @IntRange(min = -1000000, max = 1000000) int dy) {
        assertEquals(a.contact(b), a.translated(dx, dy).contact(b.translated(dx, dy)));
    }

    @Property(maxDiscardRatio = 20)
    void pushingOut_leavesThemTouching(@ForAll("rect") Rect a, @ForAll("rect") Rect b) {
        Contact c = a.contact(b);
        Assume.that(c != null);
        assertPushOutTouches(a, b, c);
    }

    @Property(tries = 200, maxDiscardRatio = 20)
    void depthIsTheMinimumTranslation(@ForAll("rect") Rect a, @ForAll("rect") Rect b) {
        Contact c = a.contact(b);
        Assume.that(c != null);
        assertNoShorterMove(a, b, c);
        assertEquals(ContactFixtures.slowDepth(a, b), c.depth(), 1e-4 + 1e-5 * c.depth());
    }
}
