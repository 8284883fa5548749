package hitbox;

/** Segment maths behind {@link Collide} and {@link Segment}, built on exact orientation tests. */
final class Lines {
    private Lines() {
    }

    /**
     * The orientation of c seen from the line a to b: positive for one turn, negative for the
     * other, 0 when the three points are collinear. Exact for whole-number floats up to 2^24,
     * since each product fits a double's 53-bit mantissa.
     */
    static double orient(double ax, double ay, double bx, double by, double cx, double cy) {
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    }

    /** Does the point lie on the closed segment? */
    static boolean segmentPoint(float x1, float y1, float x2, float y2, float px, float py) {
        return orient(x1, y1, x2, y2, px, py) == 0
                && px >= Math.min(x1, x2) && px <= Math.max(x1, x2)
                && py >= Math.min(y1, y2) && py <= Math.max(y1, y2);
    }
}
