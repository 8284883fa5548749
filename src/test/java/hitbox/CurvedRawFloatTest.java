package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The raw-float forms for ellipses and capsules ({@code Contact.ellipseCircle} and the rest,
 * {@code Ray.distanceToEllipse}, {@code Ray.distanceToCapsule}) answer exactly as the shape
 * methods do, and give no result for NaN, infinite or negative input without throwing.
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
    void contacts_badInputIsNoContact() {
        assertNull(Raw.contactEllipseCircle(Float.NaN, 0, 5, 5, 0, 0, 5));
        assertNull(Raw.contactEllipseCircle(0, 0, -1, 5, 0, 0, 5));
        assertNull(Raw.contactEllipseRect(0, 0, 5, 5, 0, 0, -1, 5));
        assertNull(Raw.contactEllipseEllipse(0, 0, 5, 5, 0, Float.POSITIVE_INFINITY, 5, 5));
        assertNull(Raw.contactCapsuleCircle(0, 0, 10, 0, -2, 0, 0, 5));
        assertNull(Raw.contactCapsuleRect(0, 0, 10, 0, 2, 0, 0, 5, Float.NaN));
        assertNull(Raw.contactCapsuleCapsule(0, 0, 10, 0, 2, 0, 0, 10, 0, -2));
        assertNull(Raw.contactEllipseCapsule(0, 0, 5, 5, 0, 0, 10, 0, Float.NaN));
    }

    @Test
    void rayDistances_matchTheShapes() {
        Random rnd = new Random(4);
        int hits = 0;
        for (int i = 0; i < 2000; i++) {
            float ox = Sampled.coord(rnd) - 40, oy = Sampled.coord(rnd) - 40;
            float dx = rnd.nextInt(21) - 10 + rnd.nextFloat(), dy = rnd.nextInt(21) - 10 + rnd.nextFloat();
            float max = rnd.nextBoolean() ? Float.POSITIVE_INFINITY : rnd.nextInt(200);
            Ray ray = new Ray(ox, oy, dx, dy, max);
            Ellipse e = Sampled.ellipse(rnd);
            Capsule k = Sampled.capsule(rnd);
            RayHit he = ray.cast(e), hk = ray.cast(k);
            assertEquals(he == null ? Float.POSITIVE_INFINITY : he.distance(),
                    Raw.rayDistanceToEllipse(ox, oy, dx, dy, max, e.x(), e.y(), e.rx(), e.ry()), ray + " " + e);
            assertEquals(hk == null ? Float.POSITIVE_INFINITY : hk.distance(),
                    Raw.rayDistanceToCapsule(ox, oy, dx, dy, max, k.x1(), k.y1(), k.x2(), k.y2(), k.r()), ray + " " + k);
            hits += (he == null ? 0 : 1) + (hk == null ? 0 : 1);
        }
        assertEquals(true, hits > 400, hits + " hits");
        // Inside: 0. A flat ellipse or a capsule of radius 0: never entered.
        assertEquals(0f, Raw.rayDistanceToEllipse(0, 0, 1, 0, 10, 0, 0, 5, 3));
        assertEquals(0f, Raw.rayDistanceToCapsule(0, 0, 1, 0, 10, -5, 0, 5, 0, 1));
        assertEquals(2f, Raw.rayDistanceToEllipse(-7, 0, 1, 0, 10, 0, 0, 5, 3));
        assertEquals(6f, Raw.rayDistanceToCapsule(0, -10, 0, 1, 100, -5, 0, 5, 0, 4));
        assertEquals(Float.POSITIVE_INFINITY, Raw.rayDistanceToEllipse(-7, 0, 1, 0, 10, 0, 0, 5, 0));
        assertEquals(Float.POSITIVE_INFINITY, Raw.rayDistanceToCapsule(0, -10, 0, 1, 100, -5, 0, 5, 0, 0));
        assertEquals(Float.POSITIVE_INFINITY, Raw.rayDistanceToEllipse(Float.NaN, 0, 1, 0, 10, 0, 0, 5, 3));
        assertEquals(Float.POSITIVE_INFINITY, Raw.rayDistanceToEllipse(-7, 0, 0, 0, 10, 0, 0, 5, 3));
        assertEquals(Float.POSITIVE_INFINITY, Raw.rayDistanceToCapsule(0, -10, 0, 1, -1, -5, 0, 5, 0, 4));
        assertEquals(Float.POSITIVE_INFINITY, Raw.rayDistanceToCapsule(0, -10, 0, 1, 100, -5, 0, 5, 0, -4));
    }
}
