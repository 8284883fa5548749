package hitbox;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.junit.jupiter.api.Test;

/** Response.separate: out of b, exactly, and no further than touching. */
class ResponseSeparateTest {

    @Provide
    Arbitrary<Shape> shapes() {
        Arbitrary<Float> c = Arbitraries.floats().between(-100, 100);
        Arbitrary<Float> size = Arbitraries.floats().between(1, 50);
        Arbitrary<Float> angle = Arbitraries.floats().between(0, 6.3f);
        Arbitrary<Shape> circles = Combinators.combine(c, c, size).as(Circle::new);
        Arbitrary<Shape> rects = Combinators.combine(c, c, size, size).as(Rect::new);
        Arbitrary<Shape> turned = Combinators.combine(c, c, size, size, angle).as((x, y, w, h, a) -> Polygon.of(Rect.centered(x, y, w, h)).rotated(a, x, y));
        return Arbitraries.oneOf(circles, rects, turned);
    }

    @Property(tries = 3000)
    void separate_leavesThemApart_andJustTouching(@ForAll("shapes") Shape a, @ForAll("shapes") Shape b) {
        Shape moved = Response.separate(a, b);
        assertFalse(moved.overlaps(b), () -> a + " moved to " + moved + " still overlaps " + b);
        Contact contact = a.contact(b);
        if (contact != null) {
            // Touching: a thousandth of a pixel back towards b overlaps again.
            float back = 1e-3f;
            assertTrue(moved.translated(contact.nx() * back, contact.ny() * back).overlaps(b),
                    () -> a + " was pushed further than touching " + b);
        } else {
            assertSame(a, moved, "apart: unchanged");
        }
    }

    @Test
    void separate_apartOrTouching_returnsTheSameShape() {
        Circle a = new Circle(0, 0, 5);
        assertSame(a, Response.separate(a, new Circle(20, 0, 5)));
        assertSame(a, Response.separate(a, new Circle(10, 0, 5)), "touching is not overlapping");
    }

    @Test
    void separate_segment_isRefusedWithTheContactsMessage() {
        assertThrows(IllegalArgumentException.class,
                () -> Response.separate(new Circle(0, 0, 5), new Segment(0, 0, 10, 0)));
    }
}
