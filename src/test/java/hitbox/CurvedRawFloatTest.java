package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Ellipses and capsules asked through the calls that replaced their raw-float forms (issue 30):
 * {@code Contact.between} answers as {@code a.contact(b)}, a ray's distance has the values
 * worked by hand below, and bad values are refused by the shapes and the ray themselves (the raw
 * forms answered "no result" instead; that rule went with them).
 */
class CurvedRawFloatTest {

    @Test
    void contacts_matchTheShapes() {
        Random rnd = new Random(3);
        int found = 0;
        for (int i = 0; i < 400; i++) {
            Ellipse e = Sampled.ellipse(rnd), f = Sampled.ellipse(rnd);
            Capsule k = Sampled.capsule(rnd), m = Sampled.capsule(rnd);
            Circle c = new Circle(Sampled.coord(rnd), Sampled.coord(rnd), 1 + rnd.nextInt(30));
            Rect r = new Rect(Sampled.coord(rnd), Sampled.coord(rnd), rnd.nextInt(40), rnd.nextInt(40));
            Contact[][] pairs = {
                {Raw.contactEllipseCircle(e.x(), e.y(), e.rx(), e.ry(), c.x(), c.y(), c.r()), e.contact(c)},
                {Raw.contactEllipseRect(e.x(), e.y(), e.rx(), e.ry(), r.x(), r.y(), r.w(), r.h()), e.contact(r)},
                {Raw.contactEllipseEllipse(e.x(), e.y(), e.rx(), e.ry(), f.x(), f.y(), f.rx(), f.ry()), e.contact(f)},
                {Raw.contactEllipseCapsule(e.x(), e.y(), e.rx(), e.ry(), k.x1(), k.y1(), k.x2(), k.y2(), k.r()), e.contact(k)},
                {Raw.contactCapsuleCircle(k.x1(), k.y1(), k.x2(), k.y2(), k.r(), c.x(), c.y(), c.r()), k.contact(c)},
                {Raw.contactCapsuleRect(k.x1(), k.y1(), k.x2(), k.y2(), k.r(), r.x(), r.y(), r.w(), r.h()), k.contact(r)},
                {Raw.contactCapsuleCapsule(k.x1(), k.y1(), k.x2(), k.y2(), k.r(), m.x1(), m.y1(), m.x2(), m.y2(), m.r()), k.contact(m)},
            };
            for (Contact[] p : pairs) {
                assertEquals(p[1], p[0]);
                found += p[0] == null ? 0 : 1;
            }
        }
        assertEquals(true, found > 300, found + " contacts");
    }

    @Test
    void badInput_isRefusedByTheShapes() {
        assertThrows(IllegalArgumentException.class, () -> Raw.contactEllipseCircle(Float.NaN, 0, 5, 5, 0, 0, 5));
        assertThrows(IllegalArgumentException.class, () -> Raw.contactEllipseCircle(0, 0, -1, 5, 0, 0, 5));
        assertThrows(IllegalArgumentException.class, () -> Raw.contactEllipseRect(0, 0, 5, 5, 0, 0, -1, 5));
        assertThrows(IllegalArgumentException.class, () -> Raw.contactEllipseEllipse(0, 0, 5, 5, 0, Float.POSITIVE_INFINITY, 5, 5));
        assertThrows(IllegalArgumentException.class, () -> Raw.contactCapsuleCircle(0, 0, 10, 0, -2, 0, 0, 5));
        assertThrows(IllegalArgumentException.class, () -> Raw.contactCapsuleRect(0, 0, 10, 0, 2, 0, 0, 5, Float.NaN));
        assertThrows(IllegalArgumentException.class, () -> Raw.contactCapsuleCapsule(0, 0, 10, 0, 2, 0, 0, 10, 0, -2));
        assertThrows(IllegalArgumentException.class, () -> Raw.contactEllipseCapsule(0, 0, 5, 5, 0, 0, 10, 0, Float.NaN));
        assertThrows(IllegalArgumentException.class, () -> Raw.rayDistanceToEllipse(Float.NaN, 0, 1, 0, 10, 0, 0, 5, 3));
        assertThrows(IllegalArgumentException.class, () -> Raw.rayDistanceToEllipse(-7, 0, 0, 0, 10, 0, 0, 5, 3));
        assertThrows(IllegalArgumentException.class, () -> Raw.rayDistanceToCapsule(0, -10, 0, 1, -1, -5, 0, 5, 0, 4));
        assertThrows(IllegalArgumentException.class, () -> Raw.rayDistanceToCapsule(0, -10, 0, 1, 100, -5, 0, 5, 0, -4));
    }

    @Test
    void rayDistances_workedByHand() {
        // Inside: 0. A flat ellipse or a capsule of radius 0: never entered.
        assertEquals(0f, Raw.rayDistanceToEllipse(0, 0, 1, 0, 10, 0, 0, 5, 3));
        assertEquals(0f, Raw.rayDistanceToCapsule(0, 0, 1, 0, 10, -5, 0, 5, 0, 1));
        assertEquals(2f, Raw.rayDistanceToEllipse(-7, 0, 1, 0, 10, 0, 0, 5, 3));
        assertEquals(6f, Raw.rayDistanceToCapsule(0, -10, 0, 1, 100, -5, 0, 5, 0, 4));
        assertEquals(Float.POSITIVE_INFINITY, Raw.rayDistanceToEllipse(-7, 0, 1, 0, 10, 0, 0, 5, 0));
        assertEquals(Float.POSITIVE_INFINITY, Raw.rayDistanceToCapsule(0, -10, 0, 1, 100, -5, 0, 5, 0, 0));
    }
}
