package hitbox.processing;

import hitbox.Capsule;
import hitbox.Circle;
import hitbox.Ellipse;
import hitbox.Manifold;
import hitbox.Polygon;
import hitbox.Rect;
import hitbox.Segment;
import hitbox.Shape;
import hitbox.internal.ShapeKind;
import processing.core.PConstants;
import processing.core.PGraphics;

/**
 * Draws library shapes with the current fill and stroke, the way Processing's own
 * {@code circle}, {@code rect}, {@code line} and {@code beginShape} would.
 */
public final class Draw {
    private Draw() {
    }

    /** An arrow shorter than this (pixels) is drawn as its line only: its head would have no direction. */
    private static final float SHORTEST_ARROW = 1e-3f;

    /**
     * Draws any shape: a circle or an ellipse by its radii (a turned ellipse turned about its
     * centre, as {@code rotate()} turns it), a rect in CORNER mode, a segment as a line, a
     * polygon as a closed shape, a capsule as its outline (two half circles joined).
     *
     * @param g     where to draw, e.g. the sketch's {@code g}
     * @param shape the shape
     * @throws IllegalArgumentException if {@code shape} is null
     */
    public static void shape(PGraphics g, Shape shape) {
        // A switch expression over the kinds, as every operation of the library: a new kind of
        // shape does not compile until it can be drawn.
        PGraphics drawn = switch (ShapeKind.of(shape)) {
            case ELLIPSE -> ellipse(g, (Ellipse) shape);
            case CAPSULE -> {
                capsule(g, (Capsule) shape);
                yield g;
            }
            case CIRCLE -> circle(g, (Circle) shape);
            case RECT -> rect(g, (Rect) shape);
            case SEGMENT -> segment(g, (Segment) shape);
            case POLYGON -> polygon(g, (Polygon) shape);
        };
        assert drawn == g;
    }

    private static PGraphics circle(PGraphics g, Circle c) {
        g.ellipseMode(PConstants.CENTER);
        g.ellipse(c.x(), c.y(), 2 * c.r(), 2 * c.r());
        return g;
    }

    private static PGraphics rect(PGraphics g, Rect r) {
        g.rectMode(PConstants.CORNER);
        g.rect(r.x(), r.y(), r.w(), r.h());
        return g;
    }

    private static PGraphics segment(PGraphics g, Segment s) {
        g.line(s.x1(), s.y1(), s.x2(), s.y2());
        return g;
    }

    /** An ellipse, turned about its centre by its angle (clockwise on screen, as {@code rotate()}). */
    private static PGraphics ellipse(PGraphics g, Ellipse e) {
        g.ellipseMode(PConstants.CENTER);
        if (e.angle() == 0) {
            g.ellipse(e.x(), e.y(), 2 * e.rx(), 2 * e.ry());
            return g;
        }
        g.pushMatrix();
        g.translate(e.x(), e.y());
        g.rotate(e.angle());
        g.ellipse(0, 0, 2 * e.rx(), 2 * e.ry());
        g.popMatrix();
        return g;
    }

    private static PGraphics polygon(PGraphics g, Polygon p) {
        g.beginShape();
        for (int i = 0; i < p.size(); i++) {
            g.vertex(p.x(i), p.y(i));
        }
        g.endShape(PConstants.CLOSE);
        return g;
    }

    /**
     * Draws a capsule: half a circle round each end, joined by straight sides, as one closed
     * shape (so fill and stroke look like any other shape's).
     *
     * @param g where to draw
     * @param k the capsule
     */
    public static void capsule(PGraphics g, Capsule k) {
        float dx = k.x2() - k.x1(), dy = k.y2() - k.y1();
        float a = dx == 0 && dy == 0 ? 0 : (float) Math.atan2(dy, dx);
        int steps = 24;
        g.beginShape();
        for (int i = 0; i <= steps; i++) {
            float t = a - PConstants.HALF_PI + PConstants.PI * i / steps;
            g.vertex(k.x2() + k.r() * (float) Math.cos(t), k.y2() + k.r() * (float) Math.sin(t));
        }
        for (int i = 0; i <= steps; i++) {
            float t = a + PConstants.HALF_PI + PConstants.PI * i / steps;
            g.vertex(k.x1() + k.r() * (float) Math.cos(t), k.y1() + k.r() * (float) Math.sin(t));
        }
        g.endShape(PConstants.CLOSE);
    }

    /**
     * Draws a manifold's contact points ({@link hitbox.Contact#manifold}) as dots, with the
     * current fill and stroke, as Processing's {@code circle} draws them: one dot where a
     * ball touches, two at the ends of a box lying on a face.
     *
     * <p>Nothing is checked but the manifold: a NaN diameter is handed to Processing as it is.
     *
     * @param g        where to draw
     * @param m        the manifold, not null
     * @param diameter each dot's diameter, in pixels
     * @throws IllegalArgumentException if {@code m} is null
     */
    public static void manifold(PGraphics g, Manifold m, float diameter) {
        if (m == null) {
            throw new IllegalArgumentException("the manifold m must not be null (Contact.manifold gives null when the shapes are apart: test it first)");
        }
        g.ellipseMode(PConstants.CENTER);
        for (int i = 0; i < m.pointCount(); i++) {
            g.ellipse(m.x(i), m.y(i), diameter, diameter);
        }
    }

    /**
     * Draws an arrow from (x, y) along (dx, dy), for normals and velocities.
     *
     * <p>Nothing is checked: a NaN coordinate is handed to Processing as it is.
     *
     * @param g  where to draw
     * @param x  the tail's x
     * @param y  the tail's y
     * @param dx the arrow's x extent
     * @param dy the arrow's y extent
     */
    public static void arrow(PGraphics g, float x, float y, float dx, float dy) {
        float len = (float) Math.hypot(dx, dy);
        g.line(x, y, x + dx, y + dy);
        if (len < SHORTEST_ARROW) {
            return;
        }
        float ux = dx / len;
        float uy = dy / len;
        float head = Math.min(10, len / 2);
        float tx = x + dx;
        float ty = y + dy;
        g.line(tx, ty, tx - head * (ux - uy * 0.5f), ty - head * (uy + ux * 0.5f));
        g.line(tx, ty, tx - head * (ux + uy * 0.5f), ty - head * (uy - ux * 0.5f));
    }
}
