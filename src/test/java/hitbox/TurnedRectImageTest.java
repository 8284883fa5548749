package hitbox;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import hitbox.internal.Affine;
import hitbox.internal.HiddenParts;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * A turned rectangle becomes a polygon without the full outline check when its rounded
 * corners are still convex (a world's turned box is placed that way every frame). The oracle
 * is {@link Polygon#of(float...)}, which checks the same corners in full: it must accept
 * exactly the outlines the turn accepts, and give the same polygon, winding and concave vertex.
 * Sizes from a thousandth of a pixel to hundreds, far from the origin and near it, any angle,
 * so that rounding bends or collapses some images.
 */
class TurnedRectImageTest {

    @Test
    void aTurnedRectangle_isThePolygonOfItsCornersCheckedInFull() {
        SplittableRandom rnd = new SplittableRandom(29);
        int polygons = 0, refused = 0;
        for (int i = 0; i < 20_000; i++) {
            float far = (float) Math.pow(10, rnd.nextInt(-1, 7));
            float x = (float) (rnd.nextDouble(-1, 1) * far), y = (float) (rnd.nextDouble(-1, 1) * far);
            float w = (float) Math.pow(10, rnd.nextDouble(-3, 2.5)), h = (float) Math.pow(10, rnd.nextDouble(-3, 2.5));
            float angle = (float) rnd.nextDouble(-7, 7);
            Rect r = new Rect(x, y, w, h);
            float px = x + (float) rnd.nextDouble(-1, 1) * w, py = y + (float) rnd.nextDouble(-1, 1) * h;
            Shape turned;
            try {
                turned = r.rotated(angle, px, py);
            } catch (IllegalArgumentException e) {
                turned = null;
            }
            if (turned instanceof Rect) {
                continue;  // a quarter turn keeps the axes: a rectangle
            }
            float[] corners = cornersOf(r, angle, px, py);
            Polygon checked;
            try {
                checked = Polygon.of(corners);
            } catch (IllegalArgumentException e) {
                checked = null;
            }
            String what = r + " turned by " + angle + " about (" + px + ", " + py + ")";
            if (checked == null) {
                assertEquals(null, turned, what + ": Polygon.of refuses its corners");
                refused++;
                continue;
            }
            assertNotNull(turned, what + ": Polygon.of accepts its corners");
            Polygon p = (Polygon) turned;
            assertArrayEquals(corners, HiddenParts.raw(p), what);
            assertEquals(HiddenParts.convexWinding(checked), HiddenParts.convexWinding(p), what + ": winding");
            assertEquals(HiddenParts.concaveVertex(checked), HiddenParts.concaveVertex(p), what + ": concave vertex");
            polygons++;
        }
        // Both ways taken, many times: rounding far out refuses the smallest.
        assertEquals(true, polygons > 15_000 && refused > 100, polygons + " polygons, " + refused + " refused");
    }

    /**
     * The corners as the turn places them: each through the turn's own matrix in double
     * (Transform.rotation's), rounded once to float, top-left, top-right, bottom-right,
     * bottom-left.
     */
    private static float[] cornersOf(Rect r, float angle, float px, float py) {
        Affine a = HiddenParts.affine(Transform.rotation(angle, px, py));
        double x0 = r.x(), y0 = r.y(), x1 = (double) r.x() + r.w(), y1 = (double) r.y() + r.h();
        float[] xy = new float[8];
        for (int i = 0; i < 4; i++) {
            double x = i == 1 || i == 2 ? x1 : x0, y = i >= 2 ? y1 : y0;
            xy[2 * i] = (float) a.x(x, y);
            xy[2 * i + 1] = (float) a.y(x, y);
        }
        return xy;
    }
}
