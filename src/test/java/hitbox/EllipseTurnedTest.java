package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A turned {@link Ellipse} (an angle, radians, clockwise on screen) against every shape, both
 * orders: dense sampling as the oracle ({@link Sampled}), tables where a quarter turn swaps the
 * radii, bounds that hold the sampled outline, contains, translated, contacts, rays.
 */
class EllipseTurnedTest {

    private static final float QUARTER = (float) (Math.PI / 2);

    /** Random turned ellipses against every kind of shape and other turned ellipses, both orders. */
    @Test
    void agreesWithTheSampledOracle_everyKind() {
        Sampled.assertAgreesWithOracle(20261124L, 3000, Sampled::turnedEllipse,
                r -> r.nextInt(4) == 0 ? Sampled.turnedEllipse(r) : Sampled.any(r));
    }

    /** A quarter turn (clockwise on screen) lays rx along y: it answers as the swapped ellipse, away from touching. */
    // x, y, rx, ry, px, py, inside
    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = """
            alongTurnedX,    0, 0, 10, 2,   0,   9.5, true
            oldXIsOut,       0, 0, 10, 2,   9.5,  0,  false
            nearTopEnd,      0, 0, 10, 2,   0,  -9.9, true
            besideTurnedX,   0, 0, 10, 2,   1.9,  0,  true
            pastTurnedY,     0, 0, 10, 2,   2.1,  0,  false
            """)
    void quarterTurn_swapsTheRadii(String scenario, float x, float y, float rx, float ry, float px, float py, boolean inside) {
        Ellipse turned = new Ellipse(x, y, rx, ry, QUARTER);
        assertEquals(inside, turned.contains(px, py));
        assertEquals(inside, new Ellipse(x, y, ry, rx).contains(px, py));
        Circle dot = new Circle(px, py, 0.01f);
        assertEquals(inside, turned.overlaps(dot));
        assertEquals(inside, dot.overlaps(turned));
    }

    /** Clockwise on screen, as rotate(): an eighth turn puts rx's end down and to the right. */
    @Test
    void positiveAngle_turnsClockwiseOnScreen() {
        Ellipse e = new Ellipse(0, 0, 10, 1, (float) (Math.PI / 4));
        assertTrue(e.contains(6, 6));
        assertFalse(e.contains(6, -6));
    }

    /** Pairs worth naming, with the swapped-radii ellipse (a quarter turn) as a second answer. */
    @Test
    void turnedPairs_namedCases() {
        Ellipse stick = new Ellipse(0, 0, 20, 2, QUARTER); // tall and thin after the turn
        Shape[] hits = {new Circle(0, 19, 1), new Rect(-1, 15, 2, 2), new Segment(-5, 10, 5, 10),
            Polygon.of(-1, -15, 1, -15, 0, -25), new Capsule(-10, 0, 10, 0, 1), new Ellipse(0, -18, 4, 1),
            new Ellipse(0, 0, 20, 2)};
        Shape[] misses = {new Circle(19, 0, 1), new Rect(3, -5, 2, 10), new Segment(5, -20, 5, 20),
            Polygon.of(3, -15, 6, -15, 5, 15), new Capsule(-10, 22, 10, 22, 1), new Ellipse(0, -25, 4, 2.9f)};
        for (Shape s : hits) {
            assertTrue(stick.overlaps(s), "hits " + s);
            assertTrue(s.overlaps(stick), "hits (reversed) " + s);
        }
        for (Shape s : misses) {
            assertFalse(stick.overlaps(s), "misses " + s);
            assertFalse(s.overlaps(stick), "misses (reversed) " + s);
        }
    }

    /** Equal radii are a circle at any angle, both radii 0 a point: decided exactly, as without the angle. */
    @Test
    void circleAndPoint_ignoreTheAngle() {
        Ellipse round = new Ellipse(0, 0, 5, 5, 1.234f);
        assertFalse(round.overlaps(new Circle(3, 4, 0)));   // on the outline: not inside
        assertFalse(new Circle(8, 0, 3).overlaps(round));    // touching
        assertTrue(new Circle(8, 0, 3.0001f).overlaps(round));
        Ellipse point = new Ellipse(1, 1, 0, 0, 0.5f);
        assertTrue(point.overlaps(new Rect(0, 0, 2, 2)));
        assertFalse(point.overlaps(new Segment(0, 1, 2, 1)));
    }

    /** A flat turned ellipse is an open segment: reaches into shapes with area, crosses flat ones like a plus sign. */
    @Test
    void flatTurned_isItsOpenSegment() {
        Ellipse flat = new Ellipse(0, 0, 10, 0, QUARTER); // from (0, -10) to (0, 10)
        assertTrue(flat.overlaps(new Circle(1, 0, 2)));
        assertTrue(new Circle(1, 0, 2).overlaps(flat));
        assertFalse(flat.overlaps(new Circle(3, 0, 2)));
        assertTrue(flat.overlaps(new Rect(-5, 0, 10, 0)));   // a flat rectangle crossing it
        assertTrue(new Rect(-5, 0, 10, 0).overlaps(flat));
        assertTrue(flat.overlaps(new Segment(-5, 1, 5, 1)));
        assertFalse(flat.overlaps(new Circle(0, 0, 0)));      // a point has no inside, nor does it
        assertFalse(flat.contains(0, 0));
        assertTrue(flat.overlaps(new Ellipse(0, 0, 3, 3, 0.3f)));
        assertTrue(new Ellipse(0, 0, 3, 1, 0.3f).overlaps(flat));
    }

    /** The box holds every sampled outline point, and is no more than a float step or so too big. */
    @Test
    void bounds_holdTheSampledOutline() {
        Random rnd = new Random(5);
        for (int i = 0; i < 500; i++) {
            Ellipse e = Sampled.turnedEllipse(rnd);
            Rect b = e.bounds();
            double minX = Double.POSITIVE_INFINITY, maxX = Double.NEGATIVE_INFINITY;
            double minY = Double.POSITIVE_INFINITY, maxY = Double.NEGATIVE_INFINITY;
            for (double[] p : Sampled.outline(e)) {
                minX = Math.min(minX, p[0]);
                maxX = Math.max(maxX, p[0]);
                minY = Math.min(minY, p[1]);
                maxY = Math.max(maxY, p[1]);
            }
            assertTrue(b.x() <= minX && b.y() <= minY, e + " " + b);
            assertTrue((double) b.x() + b.w() >= maxX && (double) b.y() + b.h() >= maxY, e + " " + b);
            assertTrue(minX - b.x() < 1e-3 && (double) b.x() + b.w() - maxX < 1e-3, "tight " + e + " " + b);
        }
        // An eighth turn of a circle-like box, exactly: half size hypot(rx, ry) / sqrt(2).
        Rect b = new Ellipse(0, 0, 4, 3, QUARTER).bounds();
        assertEquals(-3, b.x(), 1e-5);
        assertEquals(-4, b.y(), 1e-5);
    }

    /** Keeps the angle when moved; refuses a NaN or infinite angle with a message naming it. */
    @Test
    void translated_keepsTheAngle_andTheAngleIsChecked() {
        assertEquals(new Ellipse(3, 4, 5, 6, 0.5f), new Ellipse(1, 1, 5, 6, 0.5f).translated(2, 3));
        IllegalArgumentException ex = assertThrows(IllegalArgumentException.class, () -> new Ellipse(0, 0, 1, 1, Float.NaN));
        assertTrue(ex.getMessage().contains("angle"), ex.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new Ellipse(0, 0, 1, 1, Float.POSITIVE_INFINITY));
        assertEquals(new Ellipse(0, 0, 1, 2), new Ellipse(0, 0, 1, 2, 0));
    }

    /**
     * Contacts with a turned ellipse: null exactly when apart, normal from the first shape to
     * the second (reversed for the reversed pair), and moving the second by the depth along
     * the normal (plus a hair) separates them, while a little less than the depth does not.
     */
    @Test
    void contact_separatesAndReverses() {
        Random rnd = new Random(21);
        int found = 0;
        for (int i = 0; i < 600; i++) {
            Ellipse e = Sampled.turnedEllipse(rnd);
            Shape other = rnd.nextInt(3) == 0 ? Sampled.turnedEllipse(rnd) : convex(rnd);
            Contact c = e.contact(other);
            Contact back = other.contact(e);
            assertEquals(e.overlaps(other), c != null, e + " " + other);
            if (c == null) {
                assertNull(back);
                continue;
            }
            found++;
            assertNotNull(back);
            assertEquals(c.depth(), back.depth(), 1e-4 * Math.max(1, c.depth()));
            double push = c.depth() + 1e-3;
            Shape moved = other.translated((float) (c.nx() * push), (float) (c.ny() * push));
            assertFalse(Sampled.overlap(Sampled.scaled(e, 0.999), moved), "still overlapping after the push: " + e + " " + other + " " + c);
            if (c.depth() > 0.05) {
                double less = c.depth() * 0.9;
                Shape part = other.translated((float) (c.nx() * less), (float) (c.ny() * less));
                assertTrue(e.overlaps(part), "a shorter push already clears: " + e + " " + other + " " + c);
            }
        }
        assertTrue(found > 100, found + " contacts");
    }

    private static Shape convex(Random rnd) {
        Shape s;
        do {
            s = Sampled.any(rnd);
        } while (s instanceof Segment || s instanceof Polygon p && !p.isConvex());
        return s;
    }

    /** Rays against a turned ellipse: the hit point is on the outline, the normal faces the ray, a miss really misses. */
    @Test
    void ray_hitsTheTurnedOutline() {
        Random rnd = new Random(8);
        int hits = 0;
        for (int i = 0; i < 1000; i++) {
            Ellipse e = Sampled.turnedEllipse(rnd);
            float ox = Sampled.coord(rnd) - 60, oy = Sampled.coord(rnd) - 60;
            if (e.contains(ox, oy)) {
                continue;
            }
            Ray ray = Ray.between(ox, oy, e.x() + rnd.nextInt(40) - 20, e.y() + rnd.nextInt(40) - 20);
            RayHit h = ray.cast(e);
            if (h == null) {
                continue;
            }
            hits++;
            double c = Math.cos(e.angle()), s = Math.sin(e.angle());
            double dx = h.x() - e.x(), dy = h.y() - e.y();
            double u = (dx * c + dy * s) / e.rx(), v = (-dx * s + dy * c) / e.ry();
            assertEquals(1, Math.hypot(u, v), 1e-4, "on the outline: " + e + " " + h);
            // The normal points into the ellipse: a step along it from the hit is inside.
            assertTrue(e.contains(h.x() + 0.01f * h.nx() * Math.max(e.rx(), e.ry()) / 10, h.y() + 0.01f * h.ny() * Math.max(e.rx(), e.ry()) / 10)
                    || Math.min(e.rx(), e.ry()) < 3, "normal into the shape: " + e + " " + h);
        }
        assertTrue(hits > 300, hits + " hits");
    }
}
