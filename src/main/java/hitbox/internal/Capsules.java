package hitbox.internal;

/**
 * The capsule maths behind {@link Collide}'s {@code capsule...} methods and {@link Capsule}:
 * distances from a segment, compared with a reach, valid values only. A capsule is the set
 * of points closer than r to its segment (open, as every shape with area), so every pair is
 * "is the distance between the capsule's segment and the other shape less than r?"; each
 * distance is compared squared, as a sign of products ({@link Lines#signOfProductDifference}),
 * so a touching case between whole numbers of modest size is decided exactly.
 */
public final class Capsules {
    private Capsules() {
    }

    /**
     * Is the segment PQ closer to the origin than {@code reach} (or, if {@code closed}, at most
     * that far)? A reach of 0 is never "closer than".
     */
    public static boolean nearOrigin(double px, double py, double qx, double qy, double reach, boolean closed) {
        double r2 = reach * reach;
        double ex = qx - px, ey = qy - py;
        double len2 = ex * ex + ey * ey;
        double along = -(px * ex + py * ey);
        double sign;
        if (len2 == 0 || along <= 0) {
            sign = compareSquares(px, py, reach);
        } else if (along >= len2) {
            sign = compareSquares(qx, qy, reach);
        } else {
            double cross = px * ey - py * ex; // distance to the line times the length
            sign = Lines.signOfProductDifference(cross, cross, r2, len2);
        }
        return closed ? sign <= 0 : sign < 0;
    }

    /** The sign of x^2 + y^2 - reach^2, exact when the products are. */
    private static double compareSquares(double x, double y, double reach) {
        // Squares, not Math.hypot (several times dearer): the coordinates are floats, their
        // differences, or products of two such, so the squares neither overflow nor underflow
        // in double, and the sum is off by a few units of 2^-53 of itself; far inside the band.
        double d2 = x * x + y * y, r2 = reach * reach;
        if (Math.abs(d2 - r2) > Tolerance.NEAR_TIE * (d2 + r2)) {
            return d2 - r2;
        }
        // Near the tie: x^2 - (reach - y)(reach + y), each product's sign exact.
        return Lines.signOfProductDifference(x, x, reach - y, reach + y);
    }

    /** Is the point closer than reach to the closed segment AB? */
    public static boolean pointWithin(double ax, double ay, double bx, double by, double px, double py, double reach) {
        return nearOrigin(ax - px, ay - py, bx - px, by - py, reach, false);
    }

    /** Are the closed segments AB and CD closer than reach (reach > 0 for a meeting to count)? */
    public static boolean segmentsWithin(double ax, double ay, double bx, double by,
                                  double cx, double cy, double dx, double dy, double reach) {
        if (!(reach > 0)) {
            return false;
        }
        return Lines.segmentsMeet(ax, ay, bx, by, cx, cy, dx, dy)
                || pointWithin(ax, ay, bx, by, cx, cy, reach) || pointWithin(ax, ay, bx, by, dx, dy, reach)
                || pointWithin(cx, cy, dx, dy, ax, ay, reach) || pointWithin(cx, cy, dx, dy, bx, by, reach);
    }

    /** A capsule (radius r > 0) and a rectangle of any size, valid values. */
    public static boolean rect(float x1, float y1, float x2, float y2, float r, float rx, float ry, float rw, float rh) {
        double right = (double) rx + rw, bottom = (double) ry + rh;
        if (rw == 0 || rh == 0) {
            // A flat rectangle is a segment without its ends: the distance is the closed one's.
            return segmentsWithin(x1, y1, x2, y2, rx, ry, right, bottom, r);
        }
        if (Lines.inBox(rx, ry, right, bottom, x1, y1)) {
            return true;
        }
        return segmentsWithin(x1, y1, x2, y2, rx, ry, right, ry, r)
                || segmentsWithin(x1, y1, x2, y2, right, ry, right, bottom, r)
                || segmentsWithin(x1, y1, x2, y2, right, bottom, rx, bottom, r)
                || segmentsWithin(x1, y1, x2, y2, rx, bottom, rx, ry, r);
    }

    /** A capsule (radius r > 0) and a polygon's raw outline (at least 3 vertices, no NaN). */
    public static boolean polygon(float[] xy, float x1, float y1, float x2, float y2, float r) {
        int n = xy.length / 2;
        float loX = Math.min(x1, x2), hiX = Math.max(x1, x2), loY = Math.min(y1, y2), hiY = Math.max(y1, y2);
        for (int i = 0, h = n - 1; i < n; h = i++) {
            float ax = xy[2 * h], ay = xy[2 * h + 1], bx = xy[2 * i], by = xy[2 * i + 1];
            // An edge whose box is r or more from the segment's box is r or more from the
            // segment: most edges are turned away by four comparisons.
            if (boxesApart(Math.min(ax, bx), Math.max(ax, bx), loX, hiX, r)
                    || boxesApart(Math.min(ay, by), Math.max(ay, by), loY, hiY, r)) {
                continue;
            }
            if (segmentsWithin(x1, y1, x2, y2, ax, ay, bx, by, r)) {
                return true;
            }
        }
        return Polygons.contains(xy, x1, y1);
    }

    /**
     * Are the intervals [lo1, hi1] and [lo2, hi2] at least r > 0 apart? Only yes when sure: a
     * difference of floats in double is off by at most a unit of 2^-53 of itself, so a gap
     * above r by more than that is above it exactly.
     */
    private static boolean boxesApart(float lo1, float hi1, float lo2, float hi2, float r) {
        double gap = Math.max((double) lo1 - hi2, (double) lo2 - hi1);
        return gap > r * (1 + Tolerance.DIFFERENCE_ROUNDING);
    }
}
