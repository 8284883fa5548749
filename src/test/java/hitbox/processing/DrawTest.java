package hitbox.processing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import hitbox.Capsule;
import hitbox.Circle;
import hitbox.Contact;
import hitbox.Ellipse;
import hitbox.Manifold;
import hitbox.Polygon;
import hitbox.Rect;
import hitbox.Segment;
import hitbox.Shape;
import hitbox.internal.ShapeKind;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import processing.awt.PGraphicsJava2D;

/**
 * {@link Draw#shape} draws what {@code contains} means, for every kind of shape (read from
 * {@code Shape.class.getPermittedSubclasses()}, so a new kind fails here until it has
 * samples): each sample is drawn filled into an off-screen Java2D {@code PGraphics}, without
 * smoothing, and every pixel whose centre is more than 1.5 pixels from the outline must be
 * lit exactly when {@code shape.contains} holds at its centre. A segment, which contains no
 * area, must light pixels only within that band of it, and some.
 */
class DrawTest {

    private static final int W = 200, H = 160;
    /** How far from the outline a pixel may go either way: rasterising rules and the stroke. */
    private static final float BAND = PixelsAgainstContains.BAND;

    /** Samples per kind, turned ellipses, concave polygons and capsules at angles included. */
    private static final Map<Class<?>, List<Shape>> SAMPLES = new LinkedHashMap<>();

    static {
        SAMPLES.put(Circle.class, List.of(new Circle(100, 80, 50.5f), new Circle(30.25f, 40, 12)));
        SAMPLES.put(Rect.class, List.of(new Rect(20.5f, 30, 120, 70.25f)));
        SAMPLES.put(Segment.class, List.of(new Segment(10, 20, 180, 140), new Segment(30, 100.5f, 170, 100.5f)));
        SAMPLES.put(Polygon.class, List.of(
                Polygon.regular(100, 80, 60, 7, 0.3f),
                // concave: a star and a U
                Polygon.of(100, 10, 118, 60, 170, 60, 128, 92, 145, 145, 100, 112, 55, 145, 72, 92, 30, 60, 82, 60),
                Polygon.of(20, 20, 60, 20, 60, 110, 140, 110, 140, 20, 180, 20, 180, 150, 20, 150)));
        SAMPLES.put(Ellipse.class, List.of(
                new Ellipse(100, 80, 80, 40),
                new Ellipse(100, 80, 80, 30, 0.6f),
                new Ellipse(90, 70, 25, 60, -1.2f)));
        SAMPLES.put(Capsule.class, List.of(
                new Capsule(40, 40, 160, 120, 25),
                new Capsule(50, 80, 150, 80, 30.5f),
                new Capsule(100, 80, 100, 80, 20)));
    }

    @TestFactory
    Stream<DynamicTest> everyKind_drawsWhatContainsSays() {
        List<DynamicTest> tests = new ArrayList<>();
        for (Class<?> kind : Shape.class.getPermittedSubclasses()) {
            tests.add(DynamicTest.dynamicTest(kind.getSimpleName(), () -> {
                List<Shape> samples = SAMPLES.get(kind);
                if (samples == null || samples.isEmpty()) {
                    fail("no sample to draw for kind " + kind.getSimpleName() + ": add one to DrawTest.SAMPLES");
                }
                for (Shape s : samples) {
                    comparePixels(s);
                }
            }));
        }
        return tests.stream();
    }

    @Test
    void manifold_drawsADotAtEachContactPoint_andNothingElse() {
        // A box lying 2 into a floor: two points, at the box's bottom corners.
        Manifold m = Contact.manifold(new Rect(40, 60, 100, 42), new Rect(0, 100, 200, 60));
        assertEquals(2, m.pointCount());
        PGraphicsJava2D g = new PGraphicsJava2D();
        g.setPrimary(false);
        g.setSize(W, H);
        g.beginDraw();
        g.noSmooth();
        g.background(0);
        g.fill(255);
        g.noStroke();
        Draw.manifold(g, m, 6);
        g.endDraw();
        g.loadPixels();
        int lit = 0;
        for (int py = 0; py < H; py++) {
            for (int px = 0; px < W; px++) {
                boolean drawn = (g.pixels[py * W + px] & 0xff) > 127;
                double near = Math.min(Math.hypot(px + 0.5 - m.x(0), py + 0.5 - m.y(0)), Math.hypot(px + 0.5 - m.x(1), py + 0.5 - m.y(1)));
                assertTrue(!drawn || near <= 3 + BAND, "(" + px + ", " + py + ") drawn, " + near + " from the points");
                assertTrue(drawn || near >= 3 - BAND, "(" + px + ", " + py + ") not drawn, " + near + " from the points");
                lit += drawn ? 1 : 0;
            }
        }
        assertTrue(lit > 2 * 20, "two dots of diameter 6: " + lit);
    }

    /** Draws the shape filled and stroked in white on black, and compares every pixel outside the band. */
    private static void comparePixels(Shape shape) {
        PGraphicsJava2D g = new PGraphicsJava2D();
        g.setPrimary(false);
        g.setSize(W, H);
        g.beginDraw();
        g.noSmooth();
        g.background(0);
        g.fill(255);
        g.stroke(255);
        g.strokeWeight(1);
        Draw.shape(g, shape);
        g.endDraw();
        g.loadPixels();
        PixelsAgainstContains.check(g, shape, 1, 0);
    }

    /** The test's own kinds list agrees with ShapeKind's (a kind added to one and not the other fails). */
    @TestFactory
    Stream<DynamicTest> samples_coverEveryShapeKind() {
        return Arrays.stream(ShapeKind.values()).map(k -> DynamicTest.dynamicTest(k.name(), () -> assertTrue(
                SAMPLES.keySet().stream().anyMatch(c -> c.getSimpleName().toUpperCase().equals(k.name())),
                "no sample to draw for " + k)));
    }
}
