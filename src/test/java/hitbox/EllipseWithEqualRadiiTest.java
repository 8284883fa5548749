package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;

/**
 * An ellipse whose radii are equal is a circle, and is held to the circle's touching rule:
 * two round shapes overlap exactly when the distance between their centres (or from the
 * centre to a capsule's segment) is less than the sum of the radii. The oracle is integer
 * arithmetic on whole-number placements, where the touching cases are the Pythagorean ones
 * (a circle touching at a point off the axes, which the general ellipse search used to call
 * an overlap: 7 of 400,000 random ellipse-ellipse pairs, 5 ellipse-capsule).
 */
class EllipseWithEqualRadiiTest {

    /** Touching at a point off the axes: the centres (m^2 - n^2, 2mn) * k apart, radii summing to (m^2 + n^2) * k. */
    @Property(tries = 2000)
    void touchingOffTheAxes_isNotAnOverlap(@ForAll @IntRange(min = 2, max = 9) int m, @ForAll @IntRange(min = 1, max = 8) int n,
                                           @ForAll @IntRange(min = 1, max = 3) int k, @ForAll @IntRange(min = 1, max = 99) int share,
                                           @ForAll @IntRange(min = 0, max = 3) int quadrant, @ForAll @IntRange(min = -50, max = 50) int ex,
                                           @ForAll @IntRange(min = -50, max = 50) int ey, @ForAll @IntRange(min = 0, max = 359) int angle) {
        if (n >= m) {
            return;
        }
        int dx = (m * m - n * n) * k, dy = 2 * m * n * k, sum = (m * m + n * n) * k;
        int big = Math.max(1, sum * share / 100);
        int small = sum - big;
        if (small < 1) {
            return;
        }
        int sx = (quadrant & 1) == 0 ? 1 : -1, sy = (quadrant & 2) == 0 ? 1 : -1;
        check(ex, ey, big, ex + sx * dx, ey + sy * dy, small, angle);
        check(ex, ey, big, ex + sx * dy, ey + sy * dx, small, angle);
    }

    /** Any whole-number placement, near touching or not: the integer answer. */
    @Property(tries = 3000)
    void anyPlacement_answersAsCircles(@ForAll @IntRange(min = -60, max = 60) int ex, @ForAll @IntRange(min = -60, max = 60) int ey,
                                       @ForAll @IntRange(min = 1, max = 60) int big, @ForAll @IntRange(min = -130, max = 130) int cx,
                                       @ForAll @IntRange(min = -130, max = 130) int cy, @ForAll @IntRange(min = 1, max = 60) int small,
                                       @ForAll @IntRange(min = 0, max = 359) int angle) {
        check(ex, ey, big, cx, cy, small, angle);
    }

    private static void check(int ex, int ey, int big, int cx, int cy, int small, int angle) {
        long ddx = cx - ex, ddy = cy - ey, reach = big + small;
        boolean want = ddx * ddx + ddy * ddy < reach * reach;
        String where = "ellipse (" + ex + ", " + ey + ") radius " + big + " and (" + cx + ", " + cy + ") radius " + small;
        Ellipse e = new Ellipse(ex, ey, big, big, (float) Math.toRadians(angle));
        Ellipse aligned = new Ellipse(ex, ey, big, big);
        assertEquals(want, aligned.overlaps(new Circle(cx, cy, small)), "unturned, Ellipse.overlaps(Circle), " + where);
        assertEquals(want, aligned.overlaps(new Ellipse(cx, cy, small, small)), "unturned, Ellipse.overlaps(Ellipse), " + where);
        assertEquals(want, new Ellipse(cx, cy, small, small).overlaps(aligned), "unturned, swapped, " + where);
        assertEquals(want, e.overlaps(new Circle(cx, cy, small)), "Ellipse.overlaps(Circle), " + where);
        assertEquals(want, new Circle(cx, cy, small).overlaps(e), "Circle.overlaps(Ellipse), " + where);
        assertEquals(want, e.overlaps(new Ellipse(cx, cy, small, small)), "Ellipse.overlaps(Ellipse), " + where);
        // A capsule whose segment heads away from the ellipse's centre (a positive dot product
        // with the centres' difference): its nearest point to that centre is the end at
        // (cx, cy), so it reaches exactly as the circle there does.
        float awayX = cx + 3 * Long.signum(ddx), awayY = cy + 3 * Long.signum(ddy);
        if (ddx == 0 && ddy == 0) {
            awayX = cx + 3;
        }
        assertEquals(want, aligned.overlaps(new Capsule(cx, cy, awayX, awayY, small)), "unturned, Ellipse.overlaps(Capsule), " + where);
        assertEquals(want, e.overlaps(new Capsule(cx, cy, awayX, awayY, small)), "Ellipse.overlaps(Capsule), " + where);
    }
}
