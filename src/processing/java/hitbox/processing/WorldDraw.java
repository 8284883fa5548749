package hitbox.processing;

import java.util.List;

import hitbox.Body;
import hitbox.Collision;
import hitbox.Grid;
import hitbox.Reaction;
import hitbox.Rect;
import hitbox.Shape;
import hitbox.World;
import hitbox.internal.Supports;
import hitbox.internal.Extents;
import processing.core.PConstants;
import processing.core.PGraphics;

/**
 * Draws a {@link World}: its bodies as they stand, and for debugging what the world sees of
 * them: each body's box, the broad phase's cells, and the contacts of the frame with their
 * normals (detect-collisions' {@code draw()} and {@code drawBVH()}, Box2D's debug draw).
 * <pre>{@code
 * fill(Palette.OBSTACLE);
 * WorldDraw.bodies(g, world);          // with the current fill and stroke
 * if (showMaths) {
 *   WorldDraw.debug(g, world);         // cells, boxes, contacts
 * }
 * }</pre>
 *
 * <p>{@link #bodies} draws with the sketch's fill and stroke; the debug drawings use their own
 * colours ({@link #CELL}, {@link #BOX}, {@link #CONTACT}, {@link #CROSSED}). Every method saves
 * and restores the drawing style.
 */
public final class WorldDraw {
    /** The broad phase's cells: a dim blue-grey, so they stay behind everything else. */
    public static final int CELL = 0x885A6478;
    /** Each body's box: a light cyan. */
    public static final int BOX = 0xFF7FD4E8;
    /** A contact that blocked the mover (slide, touch, bounce): the overlay's guide yellow. */
    public static final int CONTACT = Overlay.GUIDE;
    /** A contact the mover crossed (a sensor, a coin): the overlay's lighter green. */
    public static final int CROSSED = Overlay.MISS;
    /** How long a contact's normal is drawn, in pixels. */
    public static final float NORMAL_LENGTH = 24;

    private WorldDraw() {
    }

    /**
     * Draws every body where it stands now ({@link Body#shape()}), with the current fill and
     * stroke, in the order added; a {@link Grid}'s body as its solid cells.
     *
     * @param g     where to draw, e.g. the sketch's {@code g}
     * @param world the world
     * @throws IllegalArgumentException if {@code world} is null
     */
    public static void bodies(PGraphics g, World world) {
        for (Body b : bodiesOf(world)) {
            body(g, b);
        }
    }

    /**
     * Draws one body where it stands now, with the current fill and stroke; a {@link Grid}'s
     * body as its solid cells.
     *
     * @param g    where to draw
     * @param body the body, removed or not
     * @throws IllegalArgumentException if {@code body} is null
     */
    public static void body(PGraphics g, Body body) {
        if (body == null) {
            throw new IllegalArgumentException("body must not be null");
        }
        g.pushStyle();
        Grid grid = body.grid();
        if (grid == null) {
            Draw.shape(g, body.shape());
        } else {
            for (int row = 0; row < grid.rows(); row++) {
                for (int col = 0; col < grid.cols(); col++) {
                    if (grid.isSolid(col, row)) {
                        Draw.shape(g, grid.cellRect(col, row));
                    }
                }
            }
        }
        g.popStyle();
    }

    /**
     * Outlines each body's box, {@link Body#bounds()}, in {@link #BOX}: the box around its
     * shape where it stands, which grows and shrinks as the body turns. (The broad phase files
     * it under that box grown by a margin; {@link #cells} shows the broad phase's side.)
     *
     * @param g     where to draw
     * @param world the world
     * @throws IllegalArgumentException if {@code world} is null
     */
    public static void boxes(PGraphics g, World world) {
        List<Body> bodies = bodiesOf(world);
        g.pushStyle();
        g.noFill();
        g.stroke(BOX);
        g.strokeWeight(1);
        g.rectMode(PConstants.CORNER);
        for (Body b : bodies) {
            Rect box = b.bounds();
            g.rect(box.x(), box.y(), box.w(), box.h());
        }
        g.popStyle();
    }

    /**
     * Outlines the broad phase's own regions in {@link #CELL} ({@link World#cells}): a grid's
     * occupied cells, a quadtree's squares, a dynamic tree's boxes; sweep and prune and brute
     * force have none, and draw nothing.
     *
     * @param g     where to draw
     * @param world the world
     * @throws IllegalArgumentException if {@code world} is null
     */
    public static void cells(PGraphics g, World world) {
        if (world == null) {
            throw new IllegalArgumentException("world must not be null");
        }
        g.pushStyle();
        g.noFill();
        g.stroke(CELL);
        g.strokeWeight(1);
        g.rectMode(PConstants.CORNER);
        world.cells((key, x, y, w, h) -> g.rect(x, y, w, h));
        g.popStyle();
    }

    /**
     * Draws the contacts of the frame, {@link World#collisions()}: see
     * {@link #contacts(PGraphics, List)}.
     *
     * @param g     where to draw
     * @param world the world
     * @throws IllegalArgumentException if {@code world} is null
     */
    public static void contacts(PGraphics g, World world) {
        if (world == null) {
            throw new IllegalArgumentException("world must not be null");
        }
        contacts(g, world.collisions());
    }

    /**
     * Draws collisions a move reported: for each, the mover's outline where it met the other,
     * and an arrow {@link #NORMAL_LENGTH} long along the normal (from the mover into the
     * other) from where the mover reaches furthest that way, with a dot at its foot; in
     * {@link #CONTACT} when the mover was stopped or turned back, in {@link #CROSSED} when it
     * passed through. A mover that already overlapped the other when its move began has no
     * normal: its outline is drawn with a ring at its position.
     *
     * <p>Where the mover met the other is its shape now moved back to the collision's
     * position, so a mover turned since the move is drawn turned.
     *
     * @param g          where to draw
     * @param collisions the collisions, e.g. what {@link World#move} returned
     * @throws IllegalArgumentException if {@code collisions} or one of them is null
     */
    public static void contacts(PGraphics g, List<Collision> collisions) {
        if (collisions == null) {
            throw new IllegalArgumentException("collisions must not be null");
        }
        for (Collision c : collisions) {
            if (c == null) {
                throw new IllegalArgumentException("collisions must not hold null");
            }
        }
        g.pushStyle();
        for (Collision c : collisions) {
            int colour = c.reaction() == Reaction.CROSS ? CROSSED : CONTACT;
            Body mover = c.mover();
            Shape where = mover.shape().translated(c.x() - mover.pivotX(), c.y() - mover.pivotY());
            g.noFill();
            g.stroke(colour, 170);
            g.strokeWeight(1);
            Draw.shape(g, where);
            float nx = c.nx(), ny = c.ny();
            g.stroke(colour);
            g.fill(colour);
            if (nx == 0 && ny == 0) {
                g.noFill();
                g.strokeWeight(1.5f);
                g.ellipseMode(PConstants.CENTER);
                g.ellipse(c.x(), c.y(), 12, 12);
                continue;
            }
            // The foot: on the line along the normal through the middle of the mover's box, as
            // far as the mover reaches that way (the middle of a side for a box met squarely).
            double cx = (Extents.minX(where) + Extents.maxX(where)) / 2, cy = (Extents.minY(where) + Extents.maxY(where)) / 2;
            double reach = Supports.support(where, nx, ny) - (cx * nx + cy * ny);
            float fx = (float) (cx + nx * reach), fy = (float) (cy + ny * reach);
            g.strokeWeight(2);
            Draw.arrow(g, fx, fy, nx * NORMAL_LENGTH, ny * NORMAL_LENGTH);
            g.noStroke();
            g.ellipseMode(PConstants.CENTER);
            g.ellipse(fx, fy, 5, 5);
        }
        g.popStyle();
    }

    /**
     * Draws everything {@link #cells}, {@link #boxes} and {@link #contacts(PGraphics, World)}
     * draw, in that order: the debug view of a world.
     *
     * @param g     where to draw
     * @param world the world
     * @throws IllegalArgumentException if {@code world} is null
     */
    public static void debug(PGraphics g, World world) {
        cells(g, world);
        boxes(g, world);
        contacts(g, world);
    }

    private static List<Body> bodiesOf(World world) {
        if (world == null) {
            throw new IllegalArgumentException("world must not be null");
        }
        return world.bodies();
    }
}
