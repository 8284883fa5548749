package hitbox.processing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import hitbox.Capsule;
import hitbox.Circle;
import hitbox.Ellipse;
import hitbox.Polygon;
import hitbox.Rect;
import hitbox.Segment;
import hitbox.Shape;
import hitbox.Transform;
import java.util.List;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;
import processing.awt.PGraphicsJava2D;
import processing.core.PConstants;
import processing.core.PGraphics;

/**
 * {@link Drawn#shape} gives the shape as the current matrix draws it: each sample is drawn
 * with Processing's own calls under {@code translate}, {@code rotate} and {@code scale} into
 * an off-screen Java2D {@code PGraphics}, and every pixel more than 1.5 pixels from the
 * outline must be lit exactly when the returned shape {@code contains} its centre.
 */
class DrawnTest {

    private static final int W = 200, H = 160;

    /** The issue's own case: a rect at (-20, -10, 40, 20) under translate and rotate. */
    @Test
    void aRectUnderTranslateAndRotate_isThePolygonOnScreen() {
        for (float angle : new float[] {0, 0.5f, PConstants.HALF_PI, 2.4f, -1}) {
            Shape[] drawn = new Shape[1];
            compare(g -> {
                g.pushMatrix();
                g.translate(100, 80);
                g.rotate(angle);
                g.rect(-20, -10, 40, 20);
                drawn[0] = Drawn.shape(g, new Rect(-20, -10, 40, 20));
                g.popMatrix();
            }, drawn, 1);
            if (angle == 0) {
                assertEquals(new Rect(80, 70, 40, 20), drawn[0]);
            }
        }
    }

    @Test
    void everyKind_underTurnsScalesAndMirrors_drawsWhatContainsSays() {
        List<Shape> shapes = List.of(
                new Circle(0, 0, 30),
                new Rect(-40, -15, 80, 30),
                new Segment(-50, -20, 45, 25),
                Polygon.of(-40, -30, -10, -30, 0, 0, 10, -30, 40, -30, 40, 30, -40, 30),
                new Ellipse(5, 0, 45, 20, 0.4f),
                new Capsule(-30, -5, 30, 10, 14));
        for (Shape s : shapes) {
            for (int k = 0; k < 3; k++) {
                int variant = k;
                Shape[] drawn = new Shape[1];
                compare(g -> {
                    g.pushMatrix();
                    g.translate(95.5f, 82);
                    g.rotate(0.7f + variant);
                    if (variant == 1) {
                        g.scale(1.4f);
                    } else if (variant == 2) {
                        g.scale(-1, 1);
                    }
                    Draw.shape(g, s);
                    drawn[0] = Drawn.shape(g, s);
                    g.popMatrix();
                }, drawn, 1);
            }
        }
    }

    @Test
    void anUnevenScale_turnsACircleIntoATurnedEllipse() {
        Shape[] drawn = new Shape[1];
        compare(g -> {
            g.pushMatrix();
            g.translate(100, 80);
            g.rotate(0.6f);
            g.scale(2, 0.8f);
            g.circle(0, 0, 60);
            drawn[0] = Drawn.shape(g, new Circle(0, 0, 30));
            g.popMatrix();
        }, drawn, 1);
        Ellipse e = assertInstanceOf(Ellipse.class, drawn[0]);
        assertEquals(60, e.rx(), 1e-3);
        assertEquals(24, e.ry(), 1e-3);
    }

    @Test
    void pixelDensityTwo_givesTheShapeInSketchUnits() {
        Shape[] drawn = new Shape[1];
        compare(g -> {
            g.pushMatrix();
            g.translate(50, 40);
            g.rotate(0.3f);
            g.rect(-20, -10, 40, 20);
            drawn[0] = Drawn.shape(g, new Rect(-20, -10, 40, 20));
            g.popMatrix();
        }, drawn, 2);
        assertEquals(Transform.IDENTITY, identityAt(2));
    }

    private static Transform identityAt(int density) {
        PGraphicsJava2D g = graphics(density);
        g.beginDraw();
        Transform t = Drawn.transform(g);
        g.endDraw();
        return t;
    }

    @Test
    void badInput() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Drawn.transform(null));
        assertTrue(e.getMessage().contains("g"), e.getMessage());
        PGraphicsJava2D g = graphics(1);
        g.beginDraw();
        e = assertThrows(IllegalArgumentException.class, () -> Drawn.shape(g, null));
        assertTrue(e.getMessage().contains("shape"), e.getMessage());
        g.scale(2, 1);
        e = assertThrows(IllegalArgumentException.class, () -> Drawn.shape(g, new Capsule(0, 0, 10, 0, 3)));
        assertTrue(e.getMessage().contains("capsule"), e.getMessage());
        g.endDraw();
    }

    // ---------------------------------------------------------------- drawing and comparing

    private static PGraphicsJava2D graphics(int density) {
        PGraphicsJava2D g = new PGraphicsJava2D();
        g.setPrimary(false);
        g.setSize(W, H);
        if (density != 1) {
            g.pixelDensity = density;
            g.setSize(W, H); // recomputes the pixel size for the density
        }
        return g;
    }

    /**
     * Draws with {@code draw} (white on black, no smoothing), which stores the shape it says
     * it drew in {@code drawn[0]}, and compares every pixel's centre outside the band.
     */
    private static void compare(Consumer<PGraphics> draw, Shape[] drawn, int density) {
        PGraphicsJava2D g = graphics(density);
        g.beginDraw();
        g.noSmooth();
        g.background(0);
        g.fill(255);
        g.stroke(255);
        g.strokeWeight(1);
        g.ellipseMode(PConstants.CENTER);
        draw.accept(g);
        g.endDraw();
        g.loadPixels();
        assertEquals(W * density, g.pixelWidth, "the pixel width at density " + density);
        PixelsAgainstContains.check(g, drawn[0], density, 50 * density * density);
    }
}
