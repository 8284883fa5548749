package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import processing.awt.PGraphicsJava2D;
import processing.core.PConstants;
import processing.core.PGraphics;

/**
 * {@link Collide#arcPoint} against Processing itself: each arc is drawn with {@code arc()} into
 * an off-screen JAVA2D {@link PGraphics} (no window needed), white on black without stroke
 * and without smoothing, and every pixel centre is asked of {@code arcPoint}. They must agree
 * everywhere but a band of {@link #BAND} pixels round the outline (the ellipse, the slice's
 * two radii, the chord), where the rasteriser's pixel rule, not the shape, decides.
 */
class ArcPointTest {

    static final double BAND = 1.5;
    private static final float PI = PConstants.PI, TWO_PI = PConstants.TWO_PI, HALF_PI = PConstants.HALF_PI;

    // start, stop (as multiples of pi, or raw radians when a word)
    @ParameterizedTest(name = "{0}: {1}..{2}, mode {3}")
    @CsvSource(textBlock = """
            quarter,             0,      0.5,   3
            quarterOpen,         0,      0.5,   1
            quarterChord,        0,      0.5,   2
            quarterNoMode,       0,      0.5,   0
            threeQuarterPie,     0.25,   1.75,  3
            threeQuarterChord,   0.25,   1.75,  2
            threeQuarterOpen,    0.25,   1.75,  1
            negativeStart,      -0.5,    0.25,  3
            negativeBoth,       -1.5,   -0.75,  3
            beyondTwoPi,         2.25,   2.9,   3
            beyondTwoPiChord,    2.25,   2.9,   2
            moreThanATurn,       0.3,    5.0,   3
            moreThanATurnChord,  0.3,    5.0,   2
            exactlyATurn,        0,      2,     3
            halfChord,           0,      1,     2
            tinyPie,             1,      1.05,  3
            """)
    void arcPoint_matchesTheDrawnPixels(String name, float startPi, float stopPi, int mode) {
        float start = startPi * PI, stop = stopPi * PI;
        comparePixels(200, 140, 90, 60, start, stop, mode);
        comparePixels(150, 150, 80, 80, start, stop, mode);
    }

    @Test
    void nothingIsDrawnOrContained_whenStopIsNotAfterStart() {
        comparePixels(150, 150, 80, 60, 1, 1, PConstants.PIE);
        comparePixels(150, 150, 80, 60, 2, 1, PConstants.PIE);
        assertFalse(Collide.arcPoint(150, 150, 80, 60, 1, 1, PConstants.PIE, 160, 160));
        assertFalse(Collide.arcPoint(150, 150, 80, 60, Float.NaN, 1, PConstants.PIE, 160, 160));
        assertFalse(Collide.arcPoint(150, 150, 80, 60, 0, Float.POSITIVE_INFINITY, PConstants.PIE, 160, 160));
        assertFalse(Collide.arcPoint(150, 150, 80, 60, -1e30f, 1, PConstants.PIE, 160, 160), "Processing's loop would not end");
        assertFalse(Collide.arcPoint(150, 150, 0, 60, 0, 1, PConstants.PIE, 151, 151), "no width, no inside");
    }

    @Test
    void exactPoints() {
        // Quarter pie, clockwise on screen from the right: the lower right quarter.
        assertTrue(Collide.arcPoint(0, 0, 10, 10, 0, HALF_PI, PConstants.PIE, 3, 3));
        assertFalse(Collide.arcPoint(0, 0, 10, 10, 0, HALF_PI, PConstants.PIE, 3, -3));
        assertFalse(Collide.arcPoint(0, 0, 10, 10, 0, HALF_PI, PConstants.PIE, 0, 0), "the slice's corner");
        assertFalse(Collide.arcPoint(0, 0, 10, 10, 0, HALF_PI, PConstants.PIE, 5, 0), "on the start radius");
        assertTrue(Collide.arcPoint(0, 0, 10, 10, 0, TWO_PI, PConstants.PIE, 0, 0), "a whole turn holds its centre");
        // The chord of the quarter runs from (10, 0) to (0, 10): (3, 3) is on the centre's side.
        assertFalse(Collide.arcPoint(0, 0, 10, 10, 0, HALF_PI, PConstants.CHORD, 3, 3));
        assertTrue(Collide.arcPoint(0, 0, 10, 10, 0, HALF_PI, PConstants.CHORD, 6, 6));
        assertTrue(Collide.arcPoint(0, 0, 10, 10, 0, HALF_PI, PConstants.OPEN, 6, 6));
        assertFalse(Collide.arcPoint(0, 0, 10, 10, 0, HALF_PI, PConstants.OPEN, 7.5f, 7.5f), "outside the circle");
    }

    /** Draws the arc and compares every pixel centre outside the outline's band. */
    static void comparePixels(float cx, float cy, float rx, float ry, float start, float stop, int mode) {
        int w = 320, h = 300;
        PGraphicsJava2D g = new PGraphicsJava2D();
        g.setPrimary(false);
        g.setSize(w, h);
        g.beginDraw();
        g.noSmooth();
        g.background(0);
        g.noStroke();
        g.fill(255);
        g.ellipseMode(PConstants.CENTER);
        if (mode == 0) {
            g.arc(cx, cy, 2 * rx, 2 * ry, start, stop);
        } else {
            g.arc(cx, cy, 2 * rx, 2 * ry, start, stop, mode);
        }
        g.endDraw();
        g.loadPixels();
        boolean[] band = band(outline(cx, cy, rx, ry, start, stop, mode), w, h);
        int checked = 0, drawnCount = 0;
        List<String> wrong = new ArrayList<>();
        for (int py = 0; py < h; py++) {
            for (int px = 0; px < w; px++) {
                float x = px + 0.5f, y = py + 0.5f;
                boolean drawn = (g.pixels[py * w + px] & 0xff) > 127;
                drawnCount += drawn ? 1 : 0;
                if (band[py * w + px]) {
                    continue;
                }
                checked++;
                if (drawn != Collide.arcPoint(cx, cy, rx, ry, start, stop, mode, x, y)) {
                    wrong.add("(" + px + ", " + py + ") drawn " + drawn);
                }
            }
        }
        assertTrue(checked > w * h / 2, "too few pixels outside the band: " + checked);
        assertEquals(stop > start, drawnCount > 0, "Processing drew " + drawnCount + " pixels");
        assertEquals(List.of(), wrong.size() > 10 ? wrong.subList(0, 10) : wrong, wrong.size() + " pixels differ");
    }

    /** The outline as many short pieces: the ellipse, and the two radii and the chord (all drawn or not, they only widen the band). */
    private static List<double[]> outline(float cx, float cy, float rx, float ry, float start, float stop, int mode) {
        List<double[]> pts = new ArrayList<>();
        for (int i = 0; i < 4000; i++) {
            double t = 2 * Math.PI * i / 4000;
            pts.add(new double[] {cx + rx * Math.cos(t), cy + ry * Math.sin(t)});
        }
        double[] ends = {start, stop, stop - start > TWO_PI ? start + TWO_PI : stop};
        for (double a : ends) {
            double ex = cx + rx * Math.cos(a), ey = cy + ry * Math.sin(a);
            for (int i = 0; i <= 400; i++) {
                double t = i / 400.0;
                pts.add(new double[] {cx + t * (ex - cx), cy + t * (ey - cy)});
                double fx = cx + rx * Math.cos(ends[0]), fy = cy + ry * Math.sin(ends[0]);
                pts.add(new double[] {fx + t * (ex - fx), fy + t * (ey - fy)});
            }
        }
        return pts;
    }

    /** The pixels whose centres are within BAND (on each axis) of an outline point. */
    private static boolean[] band(List<double[]> pts, int w, int h) {
        boolean[] out = new boolean[w * h];
        for (double[] p : pts) {
            for (int py = (int) Math.floor(p[1] - BAND - 1); py <= p[1] + BAND; py++) {
                for (int px = (int) Math.floor(p[0] - BAND - 1); px <= p[0] + BAND; px++) {
                    if (px >= 0 && py >= 0 && px < w && py < h
                            && Math.abs(px + 0.5 - p[0]) < BAND && Math.abs(py + 0.5 - p[1]) < BAND) {
                        out[py * w + px] = true;
                    }
                }
            }
        }
        return out;
    }
}
