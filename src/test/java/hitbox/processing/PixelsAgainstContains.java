package hitbox.processing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import hitbox.Circle;
import hitbox.Shape;
import hitbox.internal.ShapeKind;
import java.util.ArrayList;
import java.util.List;
import processing.core.PGraphics;

/**
 * The drawing tests' one oracle: what a {@code PGraphics} drew, white on black, against the
 * shape's own {@code contains}, pixel centre by pixel centre, away from a thin band at the
 * outline where a pixel may go either way.
 */
final class PixelsAgainstContains {
    /** How far from the outline a pixel centre may be drawn either way. */
    static final float BAND = 1.5f;

    private PixelsAgainstContains() {
    }

    /**
     * Compares every pixel of {@code g} (drawn and with its pixels loaded) outside the band.
     *
     * @param g       what was drawn, white on black
     * @param shape   what it should show
     * @param density pixels per unit of the shape's coordinates
     * @param minLit  fewer lit pixels than this, or as many, is "nothing drawn"
     */
    static void check(PGraphics g, Shape shape, int density, int minLit) {
        boolean area = ShapeKind.of(shape).hasArea();
        int pw = g.pixelWidth, ph = g.pixelHeight;
        int checked = 0, lit = 0;
        List<String> wrong = new ArrayList<>();
        for (int py = 0; py < ph; py++) {
            for (int px = 0; px < pw; px++) {
                float x = (px + 0.5f) / density, y = (py + 0.5f) / density;
                boolean on = (g.pixels[py * pw + px] & 0xff) > 127;
                lit += on ? 1 : 0;
                if (nearOutline(shape, x, y, area)) {
                    continue;
                }
                checked++;
                if (on != shape.contains(x, y)) {
                    wrong.add("(" + x + ", " + y + ") " + (on ? "drawn" : "not drawn"));
                }
            }
        }
        assertTrue(checked > pw * ph / 2, shape + ": too few pixels outside the band: " + checked);
        assertTrue(lit > minLit, shape + ": nothing drawn");
        assertEquals(List.of(), wrong.size() > 10 ? wrong.subList(0, 10) : wrong,
                shape + ": " + wrong.size() + " pixels differ from contains");
    }

    /**
     * Is the point within {@link #BAND} of the outline? For a shape with area: do points on a
     * ring of that radius about it (and the point) disagree about being inside? For a
     * segment: does a disc of that radius reach it?
     */
    private static boolean nearOutline(Shape shape, float x, float y, boolean area) {
        if (!area) {
            return shape.overlaps(new Circle(x, y, BAND));
        }
        boolean in = shape.contains(x, y);
        for (int i = 0; i < 24; i++) {
            double t = 2 * Math.PI * i / 24;
            for (float r : new float[] {BAND / 2, BAND}) {
                if (shape.contains(x + r * (float) Math.cos(t), y + r * (float) Math.sin(t)) != in) {
                    return true;
                }
            }
        }
        return false;
    }
}
