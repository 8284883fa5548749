package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The package's one contract, pinned: one normal direction (from the first shape to the
 * second, from the mover into what it hit) that every response takes as it comes; one
 * {@link Side} and one bit scheme for every "which side"; the oracle findings of issue 10.
 */
class ContractTest {

    // ------------------------------------------------------------------ one normal, straight to Response

    @Test
    void bounce_takesAHitsNormalAsItComes() {
        // A ball falling onto a floor: the hit's normal points from the ball into the floor.
        Hit hit = Raw.sweepCircleRectHit(50, 0, 5, 3, 20, 0, 10, 100, 10);
        assertNotNull(hit);
        assertEquals(Side.TOP, hit.side());
        assertEquals(0f, hit.nx());
        assertEquals(1f, hit.ny());
        assertEquals(new Vec(3, -20), Response.bounce(3, 20, hit.nx(), hit.ny(), 1));
        assertEquals(new Vec(3, 0), Response.slide(3, 20, hit.nx(), hit.ny()));
    }

    @Test
    void bounce_takesAContactsNormalAsItComes() {
        Circle ball = new Circle(50, 8, 5);
        Contact c = ball.contact(new Rect(0, 10, 100, 10));
        assertEquals(Side.TOP, c.side());
        assertEquals(new Vec(3, -20), Response.bounce(3, 20, c.nx(), c.ny(), 1));
    }

    @Test
    void bounce_takesARayHitsNormalAsItComes() {
        // A bullet fired right at a wall bounces straight back.
        RayHit hit = new Ray(0, 5, 10, 0).cast(new Rect(50, 0, 10, 10));
        assertEquals(1f, hit.nx());
        assertEquals(Side.LEFT, hit.side());
        assertEquals(new Vec(-10, 0), Response.bounce(10, 0, hit.nx(), hit.ny(), 1));
    }

    @Test
    void normals_sideRuleIsOneRule() {
        // The same normal gives the same side whichever result carries it.
        for (float[] n : new float[][] {{0, 1}, {0, -1}, {1, 0}, {-1, 0}, {0.6f, 0.8f}, {-0.8f, 0.6f}}) {
            Side side = Side.ofNormal(n[0], n[1]);
            assertEquals(side, new Contact(n[0], n[1], 1).side());
            assertEquals(side, new Hit(0.5f, n[0], n[1], side).side());
            assertEquals(side, new RayHit(1, 0, 0, n[0], n[1]).side());
        }
        float d = (float) Math.sqrt(0.5);
        assertEquals(Side.TOP, Side.ofNormal(d, d), "45 degrees: the vertical side wins, landing");
        assertEquals(Side.NONE, Side.ofNormal(0, 0));
        assertEquals(Side.NONE, Side.ofNormal(Float.NaN, 1));
    }

    // ------------------------------------------------------------------ one Side, one set of sides

    @Test
    void severalSides_sameAnswerFromEdgesMotionAndSweep() {
        // A box crossing the window's left edge, blocked by a wall on its left, sliding into it.
        Set<Side> crossed = Edges.crossed(new Rect(-1, 10, 5, 5), 100, 100);
        assertEquals(EnumSet.of(Side.LEFT), crossed);
        Set<Side> blocked = Motion.blocked(new Rect(10, 10, 5, 5), -4, 0, List.of(new Rect(0, 0, 8, 100)));
        assertTrue(blocked.contains(Side.LEFT) && blocked.contains(Side.RIGHT), "an axis names both its sides");
        Sweep.Move m = Sweep.move(new Rect(10, 10, 5, 5), -4, 0, List.of(new Rect(0, 0, 8, 100)));
        assertEquals(EnumSet.of(Side.RIGHT), m.sides(), "the box hit the wall's right side");
    }

    // ------------------------------------------------------------------ the oracle findings

    @Test
    void contact_tieRuleHoldsWhenTheCircleIsSecond() {
        Rect square = new Rect(0, 0, 10, 10);
        Circle middle = new Circle(5, 5, 2);
        Contact circleFirst = middle.contact(square);
        Contact rectFirst = square.contact(middle);
        assertEquals(new Contact(0, 1, 7), circleFirst);
        assertEquals(circleFirst, rectFirst, "a symmetric placement gives the same normal in both orders");
        assertEquals(rectFirst, Raw.contactRectCircle(0, 0, 10, 10, 5, 5, 2));
        // The same for a polygon with the circle second.
        Polygon box = Polygon.of(square);
        assertEquals(new Contact(0, 1, 7), box.contact(middle));
    }

    @Test
    void contact_tiesByRoundingGoToTheRule() {
        // Five edges exactly D from the circle's centre (directions 3-4-5 and 5-12-13 keep the
        // distances rational), with coordinates big enough that each squared distance rounds
        // differently. The tie rule, not the rounding, must pick: the most vertical normal.
        float d = 2_730_000;
        Polygon p = Polygon.of(-d, -d, d, -d, d, d / 2, d / 7, 8 * d / 7, -d, 2 * d / 3);
        Contact c = new Circle(0, 0, 1).contact(p);
        assertEquals(new Contact(0, 1, d + 1), c);
        Contact back = p.contact(new Circle(0, 0, 1));
        assertEquals(new Contact(0, -1, d + 1), back, "the circle second: the same push, seen from the polygon");
    }

    @ParameterizedTest
    @CsvSource({
            "false", // convex: the closest-feature answer
            "true",  // concave: the clearance search
    })
    void contact_circleOnACornerGetsTheCornersCone(boolean concave) {
        // A peak at (5, 0): straight up lies inside its cone of equally short pushes, and it is
        // the most vertical, so the circle leaves straight up, depth r.
        Polygon p = concave
                ? Polygon.of(0, 10, 5, 0, 10, 10, 10, 20, 7, 15, 3, 15, 0, 20)
                : Polygon.of(0, 10, 5, 0, 10, 10);
        assertEquals(concave, !p.isConvex());
        Contact c = new Circle(5, 0, 1).contact(p);
        assertEquals(0, c.nx(), 1e-6);
        assertEquals(1, c.ny(), 1e-6);
        assertEquals(1, c.depth(), 1e-6);
        Contact back = p.contact(new Circle(5, 0, 1));
        assertEquals(0, back.nx(), 1e-6);
        assertEquals(-1, back.ny(), 1e-6);
    }

    @Test
    void separate_farFromTheOrigin_stopsTouching() {
        // Far from the origin a float step is 1/16 px: a push that grew by whole steps of that
        // size would carry a thin shape well past touching.
        Rect a = new Rect(1_000_000, 1_000_000, 10, 10);
        Rect thin = new Rect(1_000_009.5f, 999_990, 0.5f, 40);
        Rect moved = Response.separate(a, thin);
        assertFalse(moved.overlaps(thin));
        assertTrue(moved.translated(0.125f, 0).overlaps(thin), "no further than touching: " + moved);
        // And the same for a circle pushed out of a slanted thin polygon.
        Circle ball = new Circle(1_000_000, 1_000_000, 5);
        Polygon slab = Polygon.of(Rect.centered(1_000_004, 1_000_000, 1, 40)).rotated(0.001f, 1_000_004, 1_000_000);
        Circle out = Response.separate(ball, slab);
        assertFalse(out.overlaps(slab));
        Contact c = ball.contact(slab);
        assertTrue(out.translated(c.nx() * 0.25f, c.ny() * 0.25f).overlaps(slab), "touching: " + out);
        assertTrue(out.x() < ball.x(), "pushed back out, not through to the far side: " + out);
    }

    @Test
    void ray_zeroLengthOnACirclesOutline_misses() {
        assertNull(new Ray(8, 0, 1, 0, 0).cast(new Circle(10, 0, 2)));
        assertEquals(Float.POSITIVE_INFINITY, Ray.distanceToCircle(8, 0, 1, 0, 0, 10, 0, 2));
        // Like a rectangle and a polygon.
        assertNull(new Ray(10, 5, 1, 0, 0).cast(new Rect(10, 0, 10, 10)));
        assertNull(new Ray(10, 5, 1, 0, 0).cast(Polygon.of(10, 0, 20, 0, 20, 10, 10, 10)));
        // Any length at all goes in.
        assertNotNull(new Ray(8, 0, 1, 0, 0.001f).cast(new Circle(10, 0, 2)));
    }

    @Test
    void sweep_tIsTheLastFloatBeforeTheSketchsPositionOverlaps() {
        // A case where the exact time of impact, rounded to a float, leaves the moved box a
        // hair inside (about a third of hits did before).
        float x = 0.1f, w = 10, vx = 13.7f, ox = 17.3f;
        float t = Sweep.rectRect(x, 0, w, 10, vx, 0, ox, 0, 10, 10);
        assertFalse(Collide.rectRect(x + t * vx, 0, w, 10, ox, 0, 10, 10), "clear at t");
        assertTrue(Collide.rectRect(x + Math.nextUp(t) * vx, 0, w, 10, ox, 0, 10, 10), "overlapping just after");
        Hit hit = Raw.sweepRectRectHit(x, 0, w, 10, vx, 0, ox, 0, 10, 10);
        assertEquals(t, hit.t());
    }

    // ------------------------------------------------------------------ bounds and big coordinates

    @Test
    void bounds_holdTheShape() {
        Polygon p = Polygon.of(-1.0000001f, 0, 1, 0, 0, 1);
        Rect b = p.bounds();
        assertTrue((double) b.x() + b.w() >= 1, "the right vertex is inside the bounds: " + b);
        assertTrue(Edges.crossed(p, 0.99999994f, 10).contains(Side.RIGHT));
        Circle c = new Circle(0.1f, 0.3f, 0.7f);
        Rect cb = c.bounds();
        assertTrue(cb.x() <= (double) c.x() - c.r() && (double) cb.x() + cb.w() >= (double) c.x() + c.r());
        assertTrue(cb.y() <= (double) c.y() - c.r() && (double) cb.y() + cb.h() >= (double) c.y() + c.r());
    }

    @Test
    void polygon_hugeCoordinates_areaCentroidAndContactStayRight() {
        // Exact arithmetic: 1e16 next to 1 does not cancel.
        Polygon p = Polygon.of(-1e16f, 0, 1e16f, 0, 0, 1);
        assertEquals(1.0000000272564224e16, p.area(), 1e9);
        assertEquals(0, p.centroid().x(), 1e-3);
        assertEquals(1 / 3f, p.centroid().y(), 1e-6);
        Polygon notch = Polygon.of(-1e16f, 0, 1e16f, 0, 1e16f, 4, 1, 2, -1e16f, 4);
        assertFalse(notch.isConvex());
        assertTrue(notch.area() > 0 && Float.isFinite(notch.centroid().x()));
        assertNotNull(notch.contact(new Circle(0, 1, 0.5f)));
    }

    @Test
    void wrap_staysInItsRange_atEveryScale() {
        // Far positions and shapes much wider than the window: the documented ranges hold.
        java.util.Random random = new java.util.Random(3);
        for (int i = 0; i < 200_000; i++) {
            float width = random.nextInt(4) == 0 ? random.nextFloat() * 1000 : Math.scalb(random.nextFloat(), random.nextInt(60) - 30);
            float w = width * (1 + random.nextFloat() * 10) + (random.nextBoolean() ? 0 : random.nextFloat());
            float x = (float) ((random.nextDouble() - 0.5) * Math.scalb(1.0, random.nextInt(80) - 20));
            float rect = Edges.rectWrapX(x, w, width);
            assertTrue(rect >= -w && rect <= width, "rectWrapX(" + x + ", " + w + ", " + width + ") = " + rect);
            float r = w / 2;
            float circle = Edges.circleWrapY(x, r, width);
            assertTrue(circle >= -r && circle <= (double) width + r, "circleWrapY(" + x + ", " + r + ", " + width + ") = " + circle);
        }
    }
}
