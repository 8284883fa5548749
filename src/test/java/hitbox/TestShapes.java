package hitbox;

import java.util.List;
import java.util.Map;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;

/**
 * Named polygons for the table tests (y grows down, as on screen), and a generator of small
 * simple polygons for the property tests.
 */
final class TestShapes {
    private TestShapes() {
    }

    /** 10 by 10, clockwise on screen. */
    static final float[] SQUARE = {0, 0, 10, 0, 10, 10, 0, 10};
    /** Corners left, top, right, bottom: a ray from inside at y = 5 passes two vertices. */
    static final float[] DIAMOND = {0, 5, 5, 0, 10, 5, 5, 10};
    /** A V cut into the top: vertex (5, 5) is a reflex corner with both neighbours above it. */
    static final float[] CROWN = {0, 0, 5, 5, 10, 0, 10, 10, 0, 10};
    /** An L: the horizontal edge from (10, 5) to (5, 5) lies on the ray from (2, 5). */
    static final float[] ELL = {0, 0, 10, 0, 10, 5, 5, 5, 5, 10, 0, 10};
    /** A U opening upwards: the notch is x in (4, 6), y in (0, 8). */
    static final float[] CUP = {0, 0, 4, 0, 4, 8, 6, 8, 6, 0, 10, 0, 10, 12, 0, 12};
    /** A W top: notches with corners at (0, 0), (6, 0), (12, 0) and bottoms (3, 6), (9, 6). */
    static final float[] DOUBLE_V = {0, 0, 3, 6, 6, 0, 9, 6, 12, 0, 12, 10, 0, 10};
    /** The square with an extra vertex in the middle of its top edge (a straight corner). */
    static final float[] SQUARE_WITH_MIDPOINT = {0, 0, 5, 0, 10, 0, 10, 10, 0, 10};
    /** A 6-8-10 right triangle: the hypotenuse 3x + 4y = 24 has whole-number tangent circles. */
    static final float[] TRIANGLE_345 = {0, 0, 8, 0, 0, 6};
    /** A right triangle, legs along the axes. */
    static final float[] TRIANGLE = {0, 0, 10, 0, 0, 10};

    static final Map<String, float[]> NAMED = Map.of(
            "square", SQUARE, "diamond", DIAMOND, "crown", CROWN, "ell", ELL, "cup", CUP,
            "doubleV", DOUBLE_V, "squareWithMidpoint", SQUARE_WITH_MIDPOINT, "triangle", TRIANGLE,
            "triangle345", TRIANGLE_345);

    /** A named shape, or coordinates written out with spaces: {@code "0 0 10 0 0 10"}. */
    static float[] get(String nameOrCoordinates) {
        String s = nameOrCoordinates.trim();
        if (Character.isLetter(s.charAt(0))) {
            return named(s);
        }
        String[] parts = s.split("\\s+");
        float[] xy = new float[parts.length];
        for (int i = 0; i < parts.length; i++) {
            xy[i] = Float.parseFloat(parts[i]);
        }
        return xy;
    }

    static float[] named(String name) {
        float[] xy = NAMED.get(name);
        if (xy == null) {
            throw new IllegalArgumentException("no test shape called " + name);
        }
        return xy.clone();
    }

    /**
     * Simple polygons with whole-number vertices in [0, max], 3 to {@code maxVertices}
     * vertices, in both windings, convex and concave.
     */
    static Arbitrary<float[]> simplePolygons(int max, int maxVertices) {
        Arbitrary<int[]> point = Combinators.combine(Arbitraries.integers().between(0, max), Arbitraries.integers().between(0, max))
                .as((x, y) -> new int[] {x, y});
        Arbitrary<List<int[]>> points = point.list().ofMinSize(3).ofMaxSize(maxVertices);
        return Combinators.combine(points, Arbitraries.of(true, false), Arbitraries.integers().between(0, maxVertices))
                .as((pts, reverse, start) -> {
                    float[] xy = ExactReference.starPolygon(pts, reverse);
                    return xy.length < 6 ? xy : ExactReference.rotated(xy, start % (xy.length / 2));
                })
                .filter(ExactReference::isSimple);
    }

    /**
     * A random convex polygon: {@code sides} corners at sorted random angles on a circle of
     * random radius around (cx, cy), rounded to half pixels or not, in either turning
     * direction. Drawn again when rounding puts corners onto each other or makes it concave.
     */
    static Polygon convexRing(java.util.SplittableRandom rnd, int sides, double cx, double cy, boolean half) {
        while (true) {
            double r = 3 + rnd.nextInt(40);
            double[] angles = new double[sides];
            for (int k = 0; k < sides; k++) {
                angles[k] = rnd.nextDouble() * 2 * Math.PI;
            }
            java.util.Arrays.sort(angles);
            float[] xy = new float[2 * sides];
            for (int k = 0; k < sides; k++) {
                double x = cx + r * Math.cos(angles[k]), y = cy + r * Math.sin(angles[k]);
                xy[2 * k] = half ? Math.round(2 * x) / 2f : (float) x;
                xy[2 * k + 1] = half ? Math.round(2 * y) / 2f : (float) y;
            }
            try {
                Polygon p = Polygon.of(xy);
                if (p.isConvex()) {
                    return rnd.nextBoolean() ? p : reversed(p);
                }
            } catch (IllegalArgumentException e) {
                // corners rounded onto each other: draw again
            }
        }
    }

    /**
     * A random star-shaped polygon, usually concave: {@code sides} corners at sorted random
     * angles around (cx, cy), each at its own random distance, rounded to half pixels or not,
     * in either turning direction. Drawn again when rounding makes it not simple.
     */
    static Polygon starRing(java.util.SplittableRandom rnd, int sides, double cx, double cy, boolean half) {
        while (true) {
            float[] xy = new float[2 * sides];
            double[] angles = rnd.doubles(sides, 0, 2 * Math.PI).sorted().toArray();
            for (int k = 0; k < sides; k++) {
                double r = 4 + rnd.nextInt(40) + rnd.nextDouble();
                double x = cx + r * Math.cos(angles[k]), y = cy + r * Math.sin(angles[k]);
                xy[2 * k] = half ? Math.round(2 * x) / 2f : (float) x;
                xy[2 * k + 1] = half ? Math.round(2 * y) / 2f : (float) y;
            }
            if (ExactReference.isSimple(xy)) {
                Polygon p = Polygon.of(xy);
                return rnd.nextBoolean() ? p : reversed(p);
            }
        }
    }

    /** The same polygon with its corners in the other order. */
    static Polygon reversed(Polygon p) {
        float[] xy = p.coordinates(), back = new float[xy.length];
        for (int k = 0; k < xy.length / 2; k++) {
            back[2 * k] = xy[xy.length - 2 - 2 * k];
            back[2 * k + 1] = xy[xy.length - 1 - 2 * k];
        }
        return Polygon.of(back);
    }
}
