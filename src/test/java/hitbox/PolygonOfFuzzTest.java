package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * Fuzzing Polygon.of, which checks an outline a user hands it. In a normal test run this
 * replays the inputs kept in src/test/resources/hitbox/PolygonOfFuzzTestInputs/of/; with
 * {@code JAZZER_FUZZ=1} Jazzer looks for new ones. Only the documented exception is allowed;
 * a polygon that is made must then answer every question without throwing: area, centroid,
 * bounds that hold it, contact and overlap with itself and a circle, a ray, a sweep of its
 * bounds.
 */
class PolygonOfFuzzTest {

    @FuzzTest(maxDuration = "5m")
    void of(FuzzedDataProvider data) {
        boolean small = data.consumeBoolean();
        int n = data.consumeInt(0, 24);
        float[] xy = new float[n];
        for (int i = 0; i < n; i++) {
            xy[i] = small ? data.consumeInt(-50, 50) : data.consumeFloat();
        }
        Polygon p;
        try {
            p = Polygon.of(xy);
        } catch (IllegalArgumentException expected) {
            assertTrue(expected.getMessage() != null && !expected.getMessage().isBlank());
            return;
        }
        float area = p.area();
        assertTrue(area > 0, "area " + area);
        Vec c = p.centroid();
        assertFalse(Float.isNaN(c.x()) || Float.isNaN(c.y()), "centroid " + c);
        Rect b = p.bounds();
        // Bounds hold every vertex, unless the polygon spans more than the float range, where
        // they are documented to be held back at it (found by fuzzing: +-Float.MAX_VALUE).
        boolean wide = spanX(p) >= Float.MAX_VALUE || spanY(p) >= Float.MAX_VALUE;
        for (int i = 0; i < p.size() && !wide; i++) {
            assertTrue(b.x() <= p.x(i) && (double) b.x() + b.w() >= p.x(i), "bounds " + b + " miss x" + i);
            assertTrue(b.y() <= p.y(i) && (double) b.y() + b.h() >= p.y(i), "bounds " + b + " miss y" + i);
        }
        assertTrue(p.overlaps(p), () -> "a polygon overlaps itself: " + p);
        Contact self = p.contact(p);
        assertTrue(self != null && self.depth() > 0, () -> "contact with itself: " + p);
        Circle probe = new Circle(p.x(0), p.y(0), Math.max(1, b.w() / 4));
        assertEquals(p.overlaps(probe), p.contact(probe) != null, () -> "contact exactly when overlapping: " + p + ", " + probe);
        assertEquals(probe.overlaps(p), p.overlaps(probe), () -> "symmetric: " + p + ", " + probe);
        Edges.crossed(p, b.w(), b.h());
        Hybrid.check(p, probe);
        if (b.w() > 0) {
            new Ray(b.x() - 1, b.centerY(), 1, 0).cast(p);
        }
    }

    private static double spanX(Polygon p) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < p.size(); i++) {
            lo = Math.min(lo, p.x(i));
            hi = Math.max(hi, p.x(i));
        }
        return hi - lo;
    }

    private static double spanY(Polygon p) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < p.size(); i++) {
            lo = Math.min(lo, p.y(i));
            hi = Math.max(hi, p.y(i));
        }
        return hi - lo;
    }
}
