package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Contact, ray casts and Response for {@link Ellipse} and {@link Capsule}: exact cases both
 * orders, and random pairs against the {@link Sampled} oracle (the push clears them, and no
 * direction clears them with 3% less), rays against sampled insides along the ray.
 */
class EllipseAndCapsuleContactTest {

    private static void assertContact(float nx, float ny, float depth, Contact c) {
        assertNotNull(c);
        assertEquals(nx, c.nx(), 1e-6, "nx of " + c);
        assertEquals(ny, c.ny(), 1e-6, "ny of " + c);
        assertEquals(depth, c.depth(), 1e-5, "depth of " + c);
    }

    @Test
    void exactCases_bothOrders() {
        Ellipse e = new Ellipse(0, 0, 4, 2);
        assertContact(1, 0, 1, e.contact(new Circle(5, 0, 2)));
        assertContact(-1, 0, 1, new Circle(5, 0, 2).contact(e));
        assertContact(0, 1, 0.5f, e.contact(new Rect(-1, 1.5f, 2, 2)));
        assertContact(0, -1, 0.5f, new Rect(-1, 1.5f, 2, 2).contact(e));
        assertContact(1, 0, 1, e.contact(new Ellipse(7, 0, 4, 2)));
        Capsule k = new Capsule(0, 0, 10, 0, 2);
        assertContact(0, 1, 1, k.contact(new Circle(5, 3, 2)));
        assertContact(0, -1, 1, new Circle(5, 3, 2).contact(k));
        assertContact(1, 0, 1, k.contact(new Circle(14, 0, 3)));
        assertContact(0, 1, 0.5f, k.contact(new Capsule(0, 3.5f, 10, 3.5f, 2)));
        assertContact(0, -1, 1, k.contact(new Rect(0, -10, 10, 9)));
        assertNull(e.contact(new Circle(6, 0, 2)), "touching");
        assertNull(k.contact(new Circle(5, 4, 2)), "touching");
        // A concave polygon (a notch in its right side) no longer throws: the ellipse on its
        // corner is pushed out of the whole polygon (CurvedConcaveContactTest checks more).
        Polygon notched = Polygon.of(0, 0, 10, 0, 5, 2, 10, 10, 0, 10);
        Contact c = e.contact(notched);
        assertNotNull(c);
        assertFalse(notched.overlaps(e.translated(-c.nx() * (c.depth() + 1e-3f), -c.ny() * (c.depth() + 1e-3f))));
        assertThrows(IllegalArgumentException.class, () -> new Segment(0, 0, 1, 1).contact(k));
    }

    @Test
    void randomContacts_clearAndAreShortest() {
        Random rnd = new Random(99);
        int checked = 0;
        for (int i = 0; i < 400; i++) {
            Shape a = rnd.nextBoolean() ? Sampled.ellipse(rnd) : Sampled.capsule(rnd);
            Shape b = convex(rnd);
            if (rnd.nextBoolean()) {
                Shape t = a;
                a = b;
                b = t;
            }
            Contact c = a.contact(b);
            if (c == null) {
                continue;
            }
            checked++;
            float d = c.depth();
            Shape cleared = b.translated(c.nx() * (d * 1.03f + 0.01f), c.ny() * (d * 1.03f + 0.01f));
            assertFalse(Sampled.overlap(a, cleared), "the push does not clear " + a + " and " + b + ": " + c);
            for (int k = 0; k < 48; k++) {
                double t = 2 * Math.PI * k / 48;
                Shape shorter = b.translated((float) (Math.cos(t) * d * 0.97), (float) (Math.sin(t) * d * 0.97));
                assertTrue(d < 0.05 || Sampled.overlap(a, shorter), "a shorter push clears " + a + " and " + b + ": " + c + " at angle " + t);
            }
            // Response.separate leaves them touching, not overlapping.
            Shape apart = Response.separate(b, a);
            assertFalse(apart.overlaps(a), "separate " + b + " from " + a);
        }
        assertTrue(checked > 100, checked + " contacts checked");
    }

    private static Shape convex(Random rnd) {
        float x = Sampled.coord(rnd), y = Sampled.coord(rnd);
        switch (rnd.nextInt(5)) {
            case 0:
                return new Circle(x, y, 2 + rnd.nextInt(30));
            case 1:
                return new Rect(x, y, 2 + rnd.nextInt(40), 2 + rnd.nextInt(40));
            case 2:
                return Polygon.of(x, y, x + 30 + rnd.nextInt(20), y + rnd.nextInt(10), x + rnd.nextInt(10), y + 25 + rnd.nextInt(20));
            case 3:
                return Sampled.ellipse(rnd);
            default:
                return Sampled.capsule(rnd);
        }
    }

    @Test
    void rays_exactCases() {
        RayHit h = new Ray(-10, 0, 1, 0).cast(new Ellipse(0, 0, 4, 2));
        assertEquals(6, h.distance(), 1e-5);
        assertEquals(1, h.nx(), 1e-6);
        assertEquals(-4, h.x(), 1e-5);
        assertEquals(0, new Ray(1, 0, 1, 0).cast(new Ellipse(0, 0, 4, 2)).distance());
        assertNull(new Ray(-10, 2, 1, 0).cast(new Ellipse(0, 0, 4, 2)), "grazing the top");
        Capsule k = new Capsule(0, 0, 10, 0, 2);
        RayHit down = new Ray(5, -10, 0, 1).cast(k);
        assertEquals(8, down.distance(), 1e-5);
        assertEquals(1, down.ny(), 1e-6);
        RayHit end = new Ray(-10, 0, 1, 0).cast(k);
        assertEquals(8, end.distance(), 1e-5);
        assertEquals(1, end.nx(), 1e-6);
        assertNull(new Ray(-10, 2, 1, 0).cast(k), "along the side");
        assertNull(new Ray(-10, 0, 1, 0, 7.5f).cast(k), "short of it");
        assertEquals(0, new Ray(5, 1, 0, 1).cast(k).distance());
        assertEquals(3, new Ray(0, -5, 0, 1).cast(new Capsule(0, 0, 0, 0, 2)).distance(), 1e-5);
    }

    @Test
    void rays_random_againstSampledInsides() {
        Random rnd = new Random(123);
        int hits = 0;
        for (int i = 0; i < 2000; i++) {
            Shape s = rnd.nextBoolean() ? Sampled.ellipse(rnd) : Sampled.capsule(rnd);
            float ox = Sampled.coord(rnd) - 20, oy = Sampled.coord(rnd) - 20;
            double ang = rnd.nextDouble() * 2 * Math.PI;
            float dx = (float) Math.cos(ang), dy = (float) Math.sin(ang);
            RayHit h = new Ray(ox, oy, dx, dy, 300).cast(s);
            double end = h == null ? 300 : h.distance();
            for (int k = 0; k < 400; k++) {
                double t = end * k / 400 - 1e-4;
                assertFalse(t > 0 && Sampled.inside(s, ox + t * dx, oy + t * dy), "inside before the hit: " + s + " ray " + ox + "," + oy);
            }
            if (h != null && h.distance() > 0) {
                hits++;
                double t = h.distance() + 1e-3;
                assertTrue(Sampled.inside(s, ox + t * dx, oy + t * dy), "not inside just after the hit: " + s + " " + h);
                // The normal points into the shape: a step along it from the hit goes inside.
                assertTrue(Sampled.inside(s, h.x() + 1e-2 * h.nx(), h.y() + 1e-2 * h.ny()), "normal " + h + " " + s);
            }
        }
        assertTrue(hits > 200, hits + " hits");
    }
}
