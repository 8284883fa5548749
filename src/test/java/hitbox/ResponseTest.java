package hitbox;

import net.jqwik.api.Arbitrary;
import net.jqwik.api.Assume;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.FloatRange;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class ResponseTest {

    /** b is below a and 3 deep: a must go up 3, or b down 3. */
    static final Contact DOWN_3 = new Contact(0, 1, 3);

    // ------------------------------------------------------------------------ push out

    @ParameterizedTest
    @CsvSource({
        // share, a's new y, b's new y (a at y = 10, b at y = 20)
        "1, 7, 20",
        "0, 10, 23",
        "0.5, 8.5, 21.5",
        "0.25, 9.25, 22.25",
    })
    void pushOut_sharesAddUp_toTheDepth(float shareA, float ay, float by) {
        assertEquals(new Circle(5, ay, 1), Response.pushOut(new Circle(5, 10, 1), DOWN_3, shareA));
        assertEquals(new Circle(5, by, 1), Response.pushOut(new Circle(5, 20, 1), DOWN_3.flipped(), 1 - shareA));
    }

    @Test
    void pushOut_wholeWay_withShareOne() {
        assertEquals(new Rect(5, 7, 2, 2), Response.pushOut(new Rect(5, 10, 2, 2), DOWN_3, 1));
        assertEquals(new Rect(5, 23, 2, 2), Response.pushOut(new Rect(5, 20, 2, 2), DOWN_3.flipped(), 1));
    }

    @Test
    void pushOut_shapes_keepTheirKind_andEndTouching() {
        Circle a = new Circle(0, 0, 10);
        Circle b = new Circle(15, 0, 10);
        Contact c = a.contact(b);
        Circle movedA = Response.pushOut(a, c, 1);
        assertEquals(new Circle(-5, 0, 10), movedA);
        assertNull(movedA.contact(b), "touching after the push");
        assertEquals(new Circle(20, 0, 10), Response.pushOut(b, c.flipped(), 1));
        Circle halfA = Response.pushOut(a, c, 0.5f);
        Circle halfB = Response.pushOut(b, c.flipped(), 0.5f);
        assertEquals(new Circle(-2.5f, 0, 10), halfA);
        assertEquals(new Circle(17.5f, 0, 10), halfB);
        assertFalse(halfA.overlaps(halfB));
        Rect r = Response.pushOut(new Rect(0, 0, 10, 10), new Contact(1, 0, 4), 1);
        assertEquals(new Rect(-4, 0, 10, 10), r);
        Polygon p = Response.pushOut(Polygon.of(0, 0, 4, 0, 0, 3), new Contact(0, -1, 2).flipped(), 1);
        assertEquals(Polygon.of(0, -2, 4, -2, 0, 1), p);
    }

    @ParameterizedTest
    @CsvSource({"-0.1", "1.5", "NaN", "Infinity"})
    void pushOut_shareOutsideZeroToOne_throws(float share) {
        String message = Float.isNaN(share) || Float.isInfinite(share)
                ? "share must be a finite number, was " + share
                : "share must be between 0 and 1, was " + share;
        assertEquals(message, assertThrows(IllegalArgumentException.class, () -> Response.pushOut(new Rect(0, 0, 1, 1), DOWN_3.flipped(), share)).getMessage());
        assertEquals(message, assertThrows(IllegalArgumentException.class,
                () -> Response.pushOut(new Circle(0, 0, 1), DOWN_3, share)).getMessage());
    }

    @Test
    void pushOut_badArguments_throwNamingThem() {
        assertEquals("contact must not be null",
                assertThrows(IllegalArgumentException.class, () -> Response.pushOut(new Circle(0, 0, 1), null, 1)).getMessage());
        assertEquals("shape must not be null",
                assertThrows(IllegalArgumentException.class, () -> Response.pushOut((Circle) null, DOWN_3, 1)).getMessage());
    }

    // ------------------------------------------------------------------------ bounce and slide

    @ParameterizedTest
    @CsvSource({
        // vx, vy, nx, ny, restitution, new vx, new vy
        "3, 4, 0, 1, 1, 3, -4",           // falling onto a floor: vertical part reversed
        "3, 4, 0, 1, 0.5, 3, -2",         // half the speed comes back
        "3, 4, 0, 1, 0, 3, 0",            // no bounce: slides along
        "5, 0, 1, 0, 1, -5, 0",           // straight into a wall
        "3, -4, 0, 1, 1, 3, -4",          // already moving up, away from the floor: unchanged
        "3, 0, 0, 1, 1, 3, 0",            // moving along the surface: unchanged
        "1, 1, 0.70710678, 0.70710678, 1, -1, -1",   // head-on into a 45 degree surface
        "2, 0, 0.70710678, 0.70710678, 1, 0, -2",    // along x into a 45 degree surface: turned up
        "3, 4, 0, 10, 1, 3, -4",          // the normal need not have length 1
    })
    void bounce_floats(float vx, float vy, float nx, float ny, float e, float wx, float wy) {
        Vec v = Response.bounce(vx, vy, nx, ny, e);
        assertEquals(wx, v.x(), 1e-6, "vx");
        assertEquals(wy, v.y(), 1e-6, "vy");
    }

    @Test
    void bounce_withAContactsNormal_andSlide() {
        assertEquals(new Vec(3, -4), Response.bounce(3, 4, DOWN_3.nx(), DOWN_3.ny(), 1));
        assertEquals(new Vec(3, -2), Response.bounce(3, 4, DOWN_3.nx(), DOWN_3.ny(), 0.5f));
        assertEquals(new Vec(3, 0), Response.slide(3, 4, DOWN_3.nx(), DOWN_3.ny()));
        assertEquals(new Vec(3, 0), Response.slide(3, 4, 0, 7));
        assertEquals(new Vec(3, -4), Response.slide(3, -4, DOWN_3.nx(), DOWN_3.ny()), "moving away: unchanged");
    }

    @Test
    void bounce_ballDroppedOnAFloor_comesBackUp_andNotBackIn() {
        Circle ball = new Circle(50, 95, 10);
        Rect floor = new Rect(0, 100, 200, 20);
        Contact c = ball.contact(floor);
        assertEquals(Side.TOP, c.side());
        Vec v = Response.bounce(2, 6, c.nx(), c.ny(), 0.8f);
        assertEquals(2, v.x(), 1e-6);
        assertEquals(-4.8, v.y(), 1e-6);
        // Next frame it still overlaps (it went 5 deep): bouncing again must not send it back down.
        assertEquals(v, Response.bounce(v.x(), v.y(), c.nx(), c.ny(), 0.8f));
    }

    @ParameterizedTest
    @CsvSource({"-0.01", "1.01", "2", "NaN"})
    void bounce_restitutionOutsideZeroToOne_throws_oneRule(float e) {
        // A restitution is a number the sketch chooses: one rule, refused wherever it is taken
        // (issue 30: the Contact overload threw, the float one clamped).
        String message = Float.isNaN(e) ? "restitution must be a finite number, was NaN" : "restitution must be between 0 and 1, was " + e;
        assertEquals(message, assertThrows(IllegalArgumentException.class, () -> Response.bounce(1, 1, 0, 1, e)).getMessage());
        assertEquals(message, assertThrows(IllegalArgumentException.class,
                () -> Response.bounce(1, 1, DOWN_3.nx(), DOWN_3.ny(), e)).getMessage());
        assertEquals(message, assertThrows(IllegalArgumentException.class, () -> Response.bounce(Float.NaN, 1, 0, 0, e)).getMessage(),
                "refused before the velocity is looked at");
    }

    @Test
    void bounce_badArguments_throwNamingThem() {
        // On plain floats a (0, 0) normal is no bounce (the NaN rule: never throw).
        assertEquals(new Vec(1, 1), Response.bounce(1, 1, 0, 0, 1));
        // A velocity or normal the sketch computed: NaN or infinite gives the velocity back.
        assertEquals(new Vec(Float.NaN, 1), Response.bounce(Float.NaN, 1, 0, 1, 1));
        assertEquals(new Vec(1, 1), Response.bounce(1, 1, Float.NaN, 1, 1));
        assertEquals(new Vec(1, 1), Response.slide(1, 1, 0, Float.POSITIVE_INFINITY));
    }

    // ------------------------------------------------------------------------ properties

    @Provide
    Arbitrary<Contact> contact() {
        return net.jqwik.api.Arbitraries.integers().between(0, 359)
                .map(deg -> new Contact((float) Math.cos(Math.toRadians(deg)), (float) Math.sin(Math.toRadians(deg)), 1));
    }

    @Property
    void bounce_intoTheSurface_reversesTheNormalPart_scaledByRestitution_keepsTheRest(
            @ForAll @FloatRange(min = -100, max = 100) float vx, @ForAll @FloatRange(min = -100, max = 100) float vy,
            @ForAll("contact") Contact c, @ForAll @FloatRange(min = 0, max = 1) float e) {
        double into = vx * c.nx() + vy * c.ny();
        double along = -vx * c.ny() + vy * c.nx();
        Vec w = Response.bounce(vx, vy, c.nx(), c.ny(), e);
        double intoAfter = w.x() * c.nx() + w.y() * c.ny();
        double alongAfter = -w.x() * c.ny() + w.y() * c.nx();
        assertEquals(along, alongAfter, 1e-4, "the part along the surface is kept");
        if (into > 0) {
            assertEquals(-e * into, intoAfter, 1e-4, "the part into b comes back out, times e");
        } else {
            assertEquals(new Vec(vx, vy), w, "moving away or along: unchanged");
        }
    }

    @Property
    void bounce_neverLeavesAMoveIntoB_andBouncingAgainChangesNothing(
            @ForAll @FloatRange(min = -100, max = 100) float vx, @ForAll @FloatRange(min = -100, max = 100) float vy,
            @ForAll("contact") Contact c, @ForAll @FloatRange(min = 0, max = 1) float e) {
        Vec w = Response.bounce(vx, vy, c.nx(), c.ny(), e);
        assertTrue(w.x() * c.nx() + w.y() * c.ny() <= 1e-4);
        Vec again = Response.bounce(w.x(), w.y(), c.nx(), c.ny(), e);
        assertEquals(w.x(), again.x(), 1e-4);
        assertEquals(w.y(), again.y(), 1e-4);
    }

    @Property
    void slide_isBounceWithRestitutionZero(
            @ForAll @FloatRange(min = -100, max = 100) float vx, @ForAll @FloatRange(min = -100, max = 100) float vy,
            @ForAll("contact") Contact c) {
        assertEquals(Response.bounce(vx, vy, c.nx(), c.ny(), 0), Response.slide(vx, vy, c.nx(), c.ny()));
    }

    @Provide
    Arbitrary<Shape> shape() {
        return net.jqwik.api.Arbitraries.oneOf(ContactFixtures.circles(), ContactFixtures.rects(), ContactFixtures.convexPolygons());
    }

    @Property(maxDiscardRatio = 20)
    void pushOut_sharedAnyWay_leavesThemClear(@ForAll("shape") Shape a, @ForAll("shape") Shape b,
                                              @ForAll @IntRange(min = 0, max = 4) int quarters) {
        Contact c = a.contact(b);
        Assume.that(c != null);
        float share = quarters / 4f;
        Shape movedA = Response.pushOut(a, c, share);
        Shape movedB = Response.pushOut(b, c.flipped(), 1 - share);
        assertTrue(ContactFixtures.overlapMeasure(movedA, movedB) <= ContactFixtures.FREE_MEASURE,
                () -> movedA + " and " + movedB + " should only touch");
    }
}
