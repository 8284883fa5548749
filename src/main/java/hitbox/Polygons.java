package hitbox;

/** Polygon maths behind {@link Collide} and {@link Polygon}; {@code xy} is x0, y0, x1, y1, .... */
final class Polygons {
    private Polygons() {
    }

    /** Throws with a learner's message if {@code xy} is not a valid simple polygon. */
    static void validate(float[] xy) {
        if (xy.length % 2 != 0) {
            throw new IllegalArgumentException("a polygon needs x, y pairs, but got an odd number of coordinates (" + xy.length + ")");
        }
        if (xy.length < 6) {
            throw new IllegalArgumentException("a polygon needs at least 3 vertices, got " + xy.length / 2);
        }
        for (int i = 0; i < xy.length; i++) {
            Check.finite((i % 2 == 0 ? "x" : "y") + (i / 2), xy[i]);
        }
    }

    /** The bounding rectangle of the vertices. */
    static Rect bounds(float[] xy) {
        float minX = xy[0], maxX = xy[0], minY = xy[1], maxY = xy[1];
        for (int i = 2; i < xy.length; i += 2) {
            minX = Math.min(minX, xy[i]);
            maxX = Math.max(maxX, xy[i]);
            minY = Math.min(minY, xy[i + 1]);
            maxY = Math.max(maxY, xy[i + 1]);
        }
        return new Rect(minX, minY, maxX - minX, maxY - minY);
    }

    /** Crossing-number point in polygon (placeholder until the exact version lands). */
    static boolean contains(float[] xy, float px, float py) {
        boolean inside = false;
        int n = xy.length / 2;
        for (int i = 0, j = n - 1; i < n; j = i++) {
            float xi = xy[2 * i], yi = xy[2 * i + 1], xj = xy[2 * j], yj = xy[2 * j + 1];
            if ((yi > py) != (yj > py) && px < (xj - xi) * (py - yi) / (yj - yi) + xi) {
                inside = !inside;
            }
        }
        return inside;
    }
}
