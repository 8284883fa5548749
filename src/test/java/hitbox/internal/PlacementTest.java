package hitbox.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import hitbox.Capsule;
import hitbox.Circle;
import hitbox.Ellipse;
import hitbox.Polygon;
import hitbox.Rect;
import hitbox.Segment;
import hitbox.Shape;
import java.util.EnumMap;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * A body's placed numbers ({@link Placement}) against the shape the same pose makes
 * ({@link Poses#place}, what {@code Body.shape()} answers): the same numbers to the bit, kept
 * for every case the class promises, left to the shape for the rest; and the table on them
 * ({@link PlacedOverlaps}) against {@code Shape.overlaps} on every pair of kinds (all six, an
 * ellipse aligned and turned, a polygon convex and a turned rectangle's), both ways
 * round, on shapes that often touch exactly. (Seeded loops: see the build's note on jqwik.)
 */
class PlacementTest {

    private static float[] quad(Random r, float lo, float hi) {
        // a corner in each quadrant, convex for these ranges, counter-clockwise in y-up terms
        return new float[] {
            -between(r, lo, hi), -between(r, lo, hi), between(r, lo, hi), -between(r, lo, hi),
            between(r, lo, hi), between(r, lo, hi), -between(r, lo, hi), between(r, lo, hi),
        };
    }

    private static float between(Random r, float lo, float hi) {
        return lo + r.nextFloat() * (hi - lo);
    }

    /** A home shape of every kind, sizes 0.5 to 40, about the origin or off it. */
    private static Shape home(Random r, int kind) {
        float x = r.nextBoolean() ? 0 : between(r, -30, 30), y = r.nextBoolean() ? 0 : between(r, -30, 30);
        float s = between(r, 0.5f, 40), t = between(r, 0.5f, 40);
        return switch (kind) {
            case 0 -> new Circle(x, y, s);
            case 1 -> new Rect(x - s / 2, y - t / 2, s, t);
            case 2 -> new Segment(x - s, y + t, x + s, y - t);
            case 3 -> new Ellipse(x, y, s, t, 0);
            case 4 -> new Ellipse(x, y, s, t, between(r, -3, 3));
            case 5 -> Polygon.of(quad(r, 0.5f, 20)).translated(x, y);
            case 6 -> Polygon.of(0, 0, 20, 0, 20, 20, 10, 5, 0, 20).translated(x, y);  // concave
            case 7 -> new Capsule(x, y, x + s, y + t, 3);
            case 8 -> new Rect(x, y, s, 0);  // flat
            default -> new Ellipse(x, y, s, 0, between(r, -3, 3));  // flat
        };
    }

    private static float angle(Random r) {
        return switch (r.nextInt(6)) {
            case 0 -> 0;
            case 1 -> (float) (Math.PI / 2 * (1 + r.nextInt(3)));
            case 2 -> between(r, -1e-6f, 1e-6f);
            default -> between(r, (float) -Math.PI, (float) Math.PI);
        };
    }

    private static double translation(Random r) {
        return switch (r.nextInt(4)) {
            case 0 -> r.nextInt(2000) - 1000;  // a float
            case 1 -> between(r, -1000, 1000);  // a float
            case 2 -> r.nextDouble() * 2000 - 1000;  // not a float
            default -> (r.nextDouble() - 0.5) * 4e7;  // far: rounding moves the corners
        };
    }

    @Test
    void placedNumbers_areThoseOfThePlacedShape_keptForEveryPromisedCase() {
        Random r = new Random(29);
        Map<ShapeKind, Integer> kept = new EnumMap<>(ShapeKind.class);
        for (int i = 0; i < 60_000; i++) {
            Shape home = home(r, i % 10);
            Placement placed = new Placement(home), fromShape = new Placement(home);
            double px = r.nextBoolean() ? 0 : r.nextInt(50) - 25, py = r.nextBoolean() ? 0 : r.nextInt(50) - 25;
            double tx = translation(r), ty = translation(r);
            float angle = angle(r);
            double cos = angle == 0 ? 1 : StrictMath.cos(angle), sin = angle == 0 ? 0 : StrictMath.sin(angle);
            Shape shape;
            try {
                shape = Poses.place(home, px, py, tx, ty, angle, cos, sin);
            } catch (IllegalArgumentException refused) {
                assertEquals(false, placed.place(home, px, py, tx, ty, angle, cos, sin),
                        "kept numbers for a pose that has no shape: " + home + " at " + angle);
                continue;
            }
            boolean keeps = placed.place(home, px, py, tx, ty, angle, cos, sin);
            String what = home + " turned " + angle + " moved " + tx + ", " + ty + " is " + shape;
            if (keeps) {
                assertTrue(fromShape.of(shape), what);
                assertEquals(fromShape.kind, placed.kind, what);
                assertEquals(fromShape.a, placed.a, 0, what);
                assertEquals(fromShape.b, placed.b, 0, what);
                assertEquals(fromShape.c, placed.c, 0, what);
                assertEquals(fromShape.d, placed.d, 0, what);
                assertEquals(fromShape.e, placed.e, 0, what);
                if (placed.kind == ShapeKind.POLYGON) {
                    assertArrayEquals(fromShape.xy, placed.xy, what);
                    assertEquals(fromShape.winding, placed.winding, what);
                }
                kept.merge(placed.kind, 1, Integer::sum);
            } else if (promised(home, shape, angle, cos, sin)) {
                fail("left to the shape, though the class keeps it: " + what);
            }
        }
        for (ShapeKind k : ShapeKind.values()) {
            assertTrue(kept.getOrDefault(k, 0) > 1000, "placed as numbers: " + kept);
        }
    }

    /** The cases the class doc promises to keep as numbers. */
    private static boolean promised(Shape home, Shape placedShape, float angle, double cos, double sin) {
        if (angle != 0 && (cos == 0 || sin == 0)) {
            return false;
        }
        if (home instanceof Polygon p && HiddenParts.convexWinding(p) == 0) {
            return false;  // a concave home, even where rounding far out makes it convex
        }
        return switch (ShapeKind.of(placedShape)) {
            case CIRCLE, RECT, SEGMENT, CAPSULE -> true;
            case ELLIPSE -> ((Ellipse) placedShape).rx() > 0 && ((Ellipse) placedShape).ry() > 0;
            case POLYGON -> Polygons.convexWinding(HiddenParts.raw((Polygon) placedShape)) != 0
                    && !Polygons.repeatsNeighbour(HiddenParts.raw((Polygon) placedShape));  // not bent by rounding
        };
    }

    /** A shape of a placeable kind, on a coarse grid of small whole numbers so that pairs often touch exactly. */
    private static Shape near(Random r, int kind) {
        boolean coarse = r.nextBoolean();
        float x = coarse ? r.nextInt(9) : between(r, 0, 8), y = coarse ? r.nextInt(9) : between(r, 0, 8);
        float s = coarse ? 1 + r.nextInt(4) : between(r, 0.5f, 4), t = coarse ? 1 + r.nextInt(4) : between(r, 0.5f, 4);
        return switch (kind) {
            case 0 -> new Circle(x, y, s);
            case 1 -> new Rect(x, y, s, r.nextInt(8) == 0 ? 0 : t);
            case 2 -> new Segment(x, y, x + (coarse ? r.nextInt(7) - 3 : s), y + (coarse ? r.nextInt(7) - 3 : t));
            case 3 -> new Ellipse(x, y, s, t, 0);
            case 4 -> new Ellipse(x, y, s, t, coarse ? 0.5f * (1 + r.nextInt(6)) : between(r, -3, 3));
            case 5 -> Polygon.of(x, y, x + s, y, x, y + t);  // a right triangle
            case 6 -> new Capsule(x, y, x + (coarse ? r.nextInt(7) - 3 : s), y + (coarse ? r.nextInt(5) - 2 : t),
                    coarse ? r.nextInt(3) : between(r, 0, 2));
            default -> new Rect(x, y, s, t).rotated(between(r, -3, 3), x, y);  // a turned rectangle: a polygon
        };
    }

    @Test
    void thePlacedTable_answersAsShapesDo_onEveryPairOfKinds() {
        Random r = new Random(2029);
        int[][] hits = new int[8][8];
        int[][] misses = new int[8][8];
        for (int i = 0; i < 250_000; i++) {
            int ka = r.nextInt(8), kb = r.nextInt(8);
            Shape a = near(r, ka), b = near(r, kb);
            Placement p = new Placement(a), q = new Placement(b);
            assertTrue(p.of(a) && q.of(b), a + " and " + b + " as numbers");
            boolean expected = a.overlaps(b);
            assertEquals(expected, PlacedOverlaps.test(p, q), a + " with " + b);
            assertEquals(expected, PlacedOverlaps.test(q, p), b + " with " + a);
            (expected ? hits : misses)[ka][kb]++;
        }
        for (int ka = 0; ka < 8; ka++) {
            for (int kb = 0; kb < 8; kb++) {
                assertTrue(hits[ka][kb] > 100 && misses[ka][kb] > 100,
                        "kinds " + ka + " and " + kb + ": " + hits[ka][kb] + " overlapping, " + misses[ka][kb] + " apart");
            }
        }
    }
}
