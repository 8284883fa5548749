package hitbox;

import hitbox.internal.*;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.IntConsumer;
import java.util.function.Predicate;

/**
 * Many bodies that move, turn, meet and are asked about: bump.lua's {@code world}, a
 * detect-collisions {@code System}, Box2D's world without its solver.
 * <pre>{@code
 * World world = new World();
 * Body player = world.add(new Rect(40, 40, 20, 30));
 * Body floor = world.add(new Rect(0, 380, 400, 20));
 * List<Collision> hits = world.move(player, vx, vy);   // slides along the floor
 * for (Collision c : hits) if (c.landed()) vy = 0;
 * }</pre>
 *
 * <h2>Moving</h2>
 * {@link #move(Body, float, float, CollisionFilter)} moves a body this frame through the
 * others: it goes until it first meets one, reacts as the filter says ({@link Reaction}:
 * slide along it, stop, pass through, bounce off), and goes on with what is left of the
 * move, up to {@value #MAX_LEGS} times. A slide keeps the part of the move along every
 * surface met, at any angle (two surfaces at once, a crease or a V, stop it); a slanted
 * surface is kept a skin (1/64 pixel) away so that rounding never stalls the slide, an
 * axis-aligned one is met touching exactly. A move that gives up with motion left says so
 * ({@link Collisions#finished()}). {@link #addCharacter} makes a body that walks on ground,
 * climbs steps and snaps down ({@link CharacterBody}); the project's docs/character.md shows
 * how both work. It uses the exact swept tests of {@link Sweep}, so it
 * never tunnels, for every pair of shape kinds at any speed, and at the end the mover overlaps
 * no body it slid on, touched or bounced off (except one it already overlapped at the start,
 * which never blocks it). A rectangle at angle 0 that slides among rectangles (every other it
 * meets a rectangle at angle 0 or a grid, every reaction {@link Reaction#SLIDE}) ends exactly
 * where {@link Sweep#move} puts it among the same rectangles in the order they were added;
 * the same walk does both. The broad phase narrows the bodies looked at to those whose boxes
 * meet the box the move sweeps.
 *
 * <h2>Contacts and events: a list per step</h2>
 * Call {@link #step()} once a frame, after the moves: it returns the {@link BodyEvent}s of the
 * frame, a contact's ENTER and EXIT once each and STAY every step in between. There are no
 * listeners, so nothing of the sketch runs while the world is changing.
 *
 * <h2>Queries</h2>
 * What a point, a box, a shape or a ray meets, and what a body overlaps now, each with an
 * optional filter ({@code Predicate<Body>}); answers are lists, bodies in the order they were
 * added, ray hits nearest first. A {@link Grid} added with {@link #add(Grid)} is one body that
 * acts as its solid cells (cells inside the grid; beyond its edges is open here).
 *
 * <h2>Bad input</h2>
 * A null, a NaN or infinite number, a removed body or another world's body throws an
 * {@link IllegalArgumentException} naming the parameter or the rule. Changing the world (add,
 * remove, move, turn, layers) from inside a filter or a query's filter throws an
 * {@link IllegalStateException}. A filter that throws is reported as an
 * {@link IllegalArgumentException} naming {@code filter}, the filter's exception as its cause
 * (an {@code IllegalStateException} passes as it is). Every refused call leaves the world
 * exactly as it was: every body's pose and shape and the broad phase's boxes. Not
 * thread-safe.
 *
 * <p>This class is longer than most (about 1,200 lines): it is the whole public face of the
 * world (bodies, moves, carrying, events, five queries) with full javadoc; the move's walk is
 * in {@code Mover}, the character's rules in {@link CharacterBody}, the shapes' placement in
 * {@code Poses} and the rectangles' walk in {@code MoveAndSlide}.
 */
public final class World {

    /** How many times one {@link #move} stops at a body and goes on before giving up. */
    public static final int MAX_LEGS = 8;

    private final BroadPhase broad;
    private Body[] byId = new Body[16];
    private int[] freeIds = new int[16];
    private int freeCount;
    private int nextId;
    private int size;
    private int serials;
    private int callbackDepth;
    private int riderMark;

    // Candidates of a query or a leg, by id.
    private int[] cand = new int[16];
    private int candCount;
    private final IntConsumer collect = id -> {
        if (candCount == cand.length) {
            cand = java.util.Arrays.copyOf(cand, 2 * candCount);
        }
        cand[candCount++] = id;
    };

    // Contacts and the collisions of the current step.
    private final ArrayList<Collision> stepCollisions = new ArrayList<>();
    private boolean stepped;
    private Map<Long, Body[]> contacts = new HashMap<>();

    private final double[] scratch = new double[4];
    /** The move-and-slide solver: every move walks there. */
    private final Mover mover = new Mover(this);

    /** Makes an empty world with a {@link BroadPhase#grid()} inside. */
    public World() {
        this(BroadPhase.grid());
    }

    /**
     * Makes an empty world on the given broad phase (one of {@link BroadPhase}'s factories),
     * which it then owns: do not change it yourself.
     *
     * @param broadPhase an empty broad phase, not null
     * @throws IllegalArgumentException if {@code broadPhase} is null or holds boxes already
     */
    public World(BroadPhase broadPhase) {
        Check.notNull("broadPhase", broadPhase);
        if (broadPhase.size() != 0) {
            throw new IllegalArgumentException("broadPhase must be empty, but holds " + broadPhase.size() + " boxes");
        }
        this.broad = broadPhase;
    }

    // ---------------------------------------------------------------- bodies

    /**
     * Adds a body where the shape stands: its position is the centre of the shape's bounding
     * box, its angle 0, so it turns about that centre.
     *
     * @param shape the body's shape, not null
     * @return the new body, never null
     * @throws IllegalArgumentException if {@code shape} is null
     * @throws IllegalStateException    if called from inside a callback of this world
     */
    public Body add(Shape shape) {
        Check.notNull("shape", shape);
        checkNotInCallback("add");
        double px = (shape.minX() + shape.maxX()) / 2, py = (shape.minY() + shape.maxY()) / 2;
        return added(shape, px, py, 0, 0, 0, null);
    }

    /**
     * Adds a body whose shape is given in its own frame, placed at (x, y) and turned by angle:
     * what {@code translate(x, y); rotate(angle);} and then drawing the shape shows. The body
     * turns about (x, y).
     *
     * <p>A NaN or infinite number throws, naming it.
     *
     * @param shape the shape in the body's frame, around (0, 0), not null
     * @param x     where the frame's origin stands, x
     * @param y     where the frame's origin stands, y
     * @param angle how far the body is turned, radians, clockwise on screen
     * @return the new body, never null
     * @throws IllegalArgumentException if {@code shape} is null, a number is NaN or infinite,
     *                                  or the placed shape leaves the float range
     * @throws IllegalStateException    if called from inside a callback of this world
     */
    public Body add(Shape shape, float x, float y, float angle) {
        Check.notNull("shape", shape);
        Check.finite("x", x);
        Check.finite("y", y);
        Check.finite("angle", angle);
        checkNotInCallback("add");
        return added(shape, 0, 0, x, y, angle, null);
    }

    /**
     * Adds a character where the shape stands: a body that walks on ground, up slopes and
     * steps, and is carried by platforms ({@link CharacterBody}). Its position is the centre of
     * the shape's bounding box.
     *
     * @param shape the character's shape, not null
     * @return the new character, never null
     * @throws IllegalArgumentException if {@code shape} is null
     * @throws IllegalStateException    if called from inside a callback of this world
     */
    public CharacterBody addCharacter(Shape shape) {
        return new CharacterBody(add(shape));
    }

    /**
     * Adds a character whose shape is given in its own frame, placed at (x, y) and turned by
     * angle, as {@link #add(Shape, float, float, float)} places a body.
     *
     * @param shape the shape in the character's frame, around (0, 0), not null
     * @param x     where the frame's origin stands, x
     * @param y     where the frame's origin stands, y
     * @param angle how far it is turned, radians, clockwise on screen
     * @return the new character, never null
     * @throws IllegalArgumentException if {@code shape} is null, a number is NaN or infinite,
     *                                  or the placed shape leaves the float range
     * @throws IllegalStateException    if called from inside a callback of this world
     */
    public CharacterBody addCharacter(Shape shape, float x, float y, float angle) {
        return new CharacterBody(add(shape, x, y, angle));
    }

    /**
     * Adds a grid as one body that acts as its solid cells ({@link Grid#isSolid}, cells inside
     * the grid only) in moves, queries and contacts. The grid is read as it is at each use,
     * so {@link Grid#set} changes the world too. A grid's body does not move or turn.
     *
     * @param grid the grid, not null
     * @return the grid's body, never null
     * @throws IllegalArgumentException if {@code grid} is null
     * @throws IllegalStateException    if called from inside a callback of this world
     */
    public Body add(Grid grid) {
        Check.notNull("grid", grid);
        checkNotInCallback("add");
        Rect r = new Rect(0, 0, grid.width(), grid.height());
        return added(r, r.w() / 2.0, r.h() / 2.0, 0, 0, 0, grid);
    }

    private Body added(Shape home, double px, double py, double tx, double ty, float angle, Grid grid) {
        double cos = angle == 0 ? 1 : StrictMath.cos(angle), sin = angle == 0 ? 0 : StrictMath.sin(angle);
        Poses.extents(home, px, py, cos, sin, scratch);
        float[] box = box(px + tx, py + ty, scratch, "x, y and angle");
        int id = freeCount > 0 ? freeIds[--freeCount] : nextId++;
        Body b = new Body(this, id, serials++, home, px, py, grid);
        b.tx = tx;
        b.ty = ty;
        b.angle = angle;
        b.cos = cos;
        b.sin = sin;
        System.arraycopy(scratch, 0, b.extents, 0, 4);
        setBox(b, box[0], box[1], box[2], box[3]);
        if (id >= byId.length) {
            byId = java.util.Arrays.copyOf(byId, Math.max(2 * byId.length, id + 1));
        }
        byId[id] = b;
        size++;
        return b;
    }

    /**
     * Removes a body. It is dead afterwards: its own changing methods throw. The next
     * {@link #step()} reports the EXIT of its contacts.
     *
     * @param body a body of this world, not null
     * @throws IllegalArgumentException if {@code body} is null, was removed, or is another
     *                                  world's
     * @throws IllegalStateException    if called from inside a callback of this world
     */
    public void remove(Body body) {
        own("body", body);
        checkNotInCallback("remove");
        if (body.dirtyIndex >= 0) {
            undirty(body);
        }
        broad.remove(body.id);
        byId[body.id] = null;
        if (freeCount == freeIds.length) {
            freeIds = java.util.Arrays.copyOf(freeIds, 2 * freeCount);
        }
        freeIds[freeCount++] = body.id;
        body.world = null;
        size--;
    }

    /**
     * Is the body in this world?
     *
     * @param body any body, not null
     * @return true if it was added to this world and not removed
     * @throws IllegalArgumentException if {@code body} is null
     */
    public boolean contains(Body body) {
        Check.notNull("body", body);
        return body.world == this;
    }

    /** @return how many bodies the world holds */
    public int size() {
        return size;
    }

    /** @return the bodies, in the order they were added, as a new list, never null */
    public List<Body> bodies() {
        List<Body> out = new ArrayList<>(size);
        for (int i = 0; i < nextId; i++) {
            if (i < byId.length && byId[i] != null) {
                out.add(byId[i]);
            }
        }
        out.sort((a, b) -> Integer.compare(a.serial, b.serial));
        return out;
    }

    // ---------------------------------------------------------------- moving

    /**
     * Moves a body this frame by (dx, dy) through the others, sliding along every one it
     * meets: {@code move(body, dx, dy, CollisionFilter.slide())}.
     *
     * <p>A NaN or infinite move throws, naming it, and nothing moves.
     *
     * @param body the body, of this world, not null
     * @param dx   the move this frame, x part
     * @param dy   the move this frame, y part
     * @return what it met, in the order met (empty if nothing), never null; where it ended is
     *         {@link Body#shape()}
     * @throws IllegalArgumentException if {@code body} is null, removed, another world's or a
     *                                  grid's, dx or dy is NaN or infinite, or the move leaves
     *                                  the float range
     * @throws IllegalStateException    if called from inside a callback of this world
     */
    public Collisions move(Body body, float dx, float dy) {
        return move(body, dx, dy, SLIDE);
    }

    static final CollisionFilter SLIDE = (m, o) -> Reaction.SLIDE;

    /**
     * Moves a body this frame by (dx, dy) through the others, each reacting as the filter
     * says (see the class notes and {@link Reaction}); a {@linkplain Body#isCarrier()
     * carrier} takes what stands on it along.
     *
     * <p>A NaN or infinite move throws, naming it, and nothing moves.
     *
     * @param body   the body, of this world, not a grid's, not null
     * @param dx     the move this frame, x part
     * @param dy     the move this frame, y part
     * @param filter the reaction to each other body, not null
     * @return what it met, in the order met (empty if nothing), never null; where it ended is
     *         {@link Body#shape()}
     * @throws IllegalArgumentException if an argument is null, dx or dy is NaN or infinite,
     *                                  the body was removed, is another world's or a grid's,
     *                                  the move leaves the float range, or the filter threw
     *                                  (then the world is as it was)
     * @throws IllegalStateException    if called from inside a callback of this world, or the
     *                                  filter tried to change the world
     */
    public Collisions move(Body body, float dx, float dy, CollisionFilter filter) {
        checkMove(body, dx, dy, filter);
        return body.carrier ? moveCarrier(body, dx, dy, filter) : moveOne(body, dx, dy, filter);
    }

    /** The checks of a move, before anything changes. */
    void checkMove(Body body, float dx, float dy, CollisionFilter filter) {
        own("body", body);
        Check.finite("dx", dx);
        Check.finite("dy", dy);
        Check.notNull("filter", filter);
        checkNotInCallback("move");
        if (body.grid != null) {
            throw new IllegalArgumentException("body is a grid's body, which does not move");
        }
        if (!Float.isFinite(body.x() + dx) || !Float.isFinite(body.y() + dy)
                || !Float.isFinite(body.boxX + dx) || !Float.isFinite(body.boxY + dy)
                || !Float.isFinite(body.boxX + body.boxW + dx) || !Float.isFinite(body.boxY + body.boxH + dy)) {
            throw new IllegalArgumentException("dx and dy move the body out of the float range: " + body + " by ("
                    + dx + ", " + dy + ")");
        }
    }

    /** One body's move, a character's by its own rules. */
    private Collisions moveOne(Body m, float dx, float dy, CollisionFilter filter) {
        return m.character != null ? m.character.walk(mover, dx, dy, filter) : mover.move(m, dx, dy, filter);
    }

    /** The filter a carrier moves a rider with: a character's own, else sliding. */
    private static CollisionFilter riderFilter(Body rider) {
        return rider.character != null ? rider.character.filter() : SLIDE;
    }

    /** A carrier's move: the riders go first when it goes up, after it otherwise. */
    private Collisions moveCarrier(Body p, float dx, float dy, CollisionFilter filter) {
        List<Body> riders = riders(p);
        int mark = ++riderMark;
        for (Body r : riders) {
            r.riderStamp = mark;
        }
        CollisionFilter platform = (m, o) -> o.riderStamp == mark ? null : filter.react(m, o);
        List<Collision> collisionsBefore = new ArrayList<>(stepCollisions);
        boolean steppedBefore = stepped;
        Saved[] saved = new Saved[riders.size() + 1];
        saved[0] = save(p);
        for (int i = 0; i < riders.size(); i++) {
            saved[i + 1] = save(riders.get(i));
        }
        holdFlush = true;
        try {
            Collisions out;
            float px = p.x(), py = p.y();
            if (dy < 0) {
                for (Body r : riders) {
                    mover.move(r, dx, dy, riderFilter(r));
                }
                out = moveOne(p, dx, dy, filter);  // a rider a ceiling stopped stops it too
                // Stopped short (a ceiling): the riders come back down with it.
                float cx = p.x() - px - dx, cy = p.y() - py - dy;
                if (cx != 0 || cy != 0) {
                    for (Body r : riders) {
                        mover.move(r, cx, cy, riderFilter(r));
                    }
                }
            } else {
                out = moveOne(p, dx, dy, platform);
                float ax = p.x() - px, ay = p.y() - py;
                for (Body r : riders) {
                    mover.move(r, ax, ay, riderFilter(r));
                }
            }
            holdFlush = false;
            flushIfMany();
            return out;
        } catch (RuntimeException e) {
            restore(p, saved[0]);
            for (int i = 0; i < riders.size(); i++) {
                restore(riders.get(i), saved[i + 1]);
            }
            stepCollisions.clear();
            stepCollisions.addAll(collisionsBefore);
            stepped = steppedBefore;
            throw e;
        } finally {
            riderMark++;
            holdFlush = false;
        }
    }

    /**
     * The bodies standing on a carrier now: touching its top from above (a drop of a hundredth
     * of a pixel would land them on it), layers accepting, not sensors, grids or carriers.
     */
    List<Body> riders(Body p) {
        List<Body> out = new ArrayList<>();
        Shape ps = p.shape();
        float probe = 2 * Mover.SKIN;
        gather(p.boxX, p.boxY - 2 * probe, (double) p.boxX + p.boxW, (double) p.boxY + p.boxH);
        for (int i = 0; i < candCount; i++) {
            Body o = byId[cand[i]];
            if (o == p || o.grid != null || o.sensor || o.carrier || !p.accepts(o)) {
                continue;
            }
            Shape os = o.shape();
            if (os.overlaps(ps)) {
                continue;
            }
            Hit h = Sweep.timeOfImpact(os, 0, probe, ps);
            if (h != null && h.side() == Side.TOP) {
                out.add(o);
            }
        }
        return out;
    }

    /** A body's pose, shape and box, to put back when a carrier's move is refused. */
    private record Saved(double tx, double ty, Shape shape, float[] box, boolean dirty) {
    }

    private static Saved save(Body b) {
        return new Saved(b.tx, b.ty, b.shape, new float[] {b.boxX, b.boxY, b.boxW, b.boxH, b.fatX, b.fatY, b.fatW, b.fatH},
                b.dirtyIndex >= 0);
    }

    /** Puts a body back as saved; no flush happened meanwhile, so the broad phase is as it was. */
    private void restore(Body b, Saved saved) {
        b.tx = saved.tx();
        b.ty = saved.ty();
        b.shape = saved.shape();
        float[] k = saved.box();
        b.boxX = k[0];
        b.boxY = k[1];
        b.boxW = k[2];
        b.boxH = k[3];
        b.fatX = k[4];
        b.fatY = k[5];
        b.fatW = k[6];
        b.fatH = k[7];
        if (!saved.dirty() && b.dirtyIndex >= 0) {
            undirty(b);
        }
    }

    /** Asks a filter for a pair's reaction, reporting what it throws as the world's rules say. */
    Reaction ask(CollisionFilter filter, Body m, Body o) {
        callbackDepth++;
        try {
            return filter.react(m, o);
        } catch (IllegalStateException e) {
            throw e;
        } catch (RuntimeException e) {
            throw new IllegalArgumentException("filter threw " + e + " for " + m + " and " + o
                    + "; the world is as it was before the call", e);
        } finally {
            callbackDepth--;
        }
    }

    /** The world changes: the mover's pose, shape and box; the collisions handed back. */
    Collisions commit(Body m, Shape start, Shape end, List<Collision> out, boolean finished) {
        double ntx = m.tx + (Poses.refX(end) - Poses.refX(start)), nty = m.ty + (Poses.refY(end) - Poses.refY(start));
        float[] box = box(m.pivotX + ntx, m.pivotY + nty, m.extents, "dx and dy");
        // The shape's own extents too (no Rect made for them: a move's only new object is its shape).
        float x0 = Math.min(box[0], Math.nextDown((float) end.minX())), y0 = Math.min(box[1], Math.nextDown((float) end.minY()));
        float x1 = Math.max(box[0] + box[2], Math.nextUp((float) end.maxX())), y1 = Math.max(box[1] + box[3], Math.nextUp((float) end.maxY()));
        m.tx = ntx;
        m.ty = nty;
        m.shape = end;
        setBox(m, x0, y0, Math.nextUp(x1 - x0), Math.nextUp(y1 - y0));
        if (stepped) {
            stepCollisions.clear();
            stepped = false;
        }
        if (!out.isEmpty()) {
            stepCollisions.addAll(out);  // addAll copies even an empty list
        }
        Collisions result = Collisions.of(out, finished);
        out.clear();
        return result;
    }

    // ---------------------------------------------------------------- teleports (Body calls these)

    void teleport(Body b, double tx, double ty, float angle, String what) {
        if (b.grid != null) {
            throw new IllegalStateException("a grid's body does not move or turn");
        }
        double cos = b.cos, sin = b.sin;
        double[] ex = b.extents;
        if (angle != b.angle) {
            cos = angle == 0 ? 1 : StrictMath.cos(angle);
            sin = angle == 0 ? 0 : StrictMath.sin(angle);
            Poses.extents(b.home, b.pivotX, b.pivotY, cos, sin, scratch);
            ex = scratch;
        }
        float[] box = box(b.pivotX + tx, b.pivotY + ty, ex, what);
        if (ex == scratch) {
            System.arraycopy(scratch, 0, b.extents, 0, 4);
        }
        b.tx = tx;
        b.ty = ty;
        b.angle = angle;
        b.cos = cos;
        b.sin = sin;
        b.shape = null;
        setBox(b, box[0], box[1], box[2], box[3]);
    }

    private final float[] boxOut = new float[4];

    /** The box of a pose, rounded outwards a float step more; checked before anything changes. */
    private float[] box(double ox, double oy, double[] ex, String what) {
        // The placed shape's coordinates are rounded to float where they are, anywhere in the
        // box: a capsule's end 4.5 inside its box edge rounds at the end's size, which can
        // move the edge by more than one step of the edge's own size. A step at the box's
        // largest size along each axis covers any such rounding.
        double sx = Math.ulp((float) Math.max(Math.abs(ox + ex[0]), Math.abs(ox + ex[2])));
        double sy = Math.ulp((float) Math.max(Math.abs(oy + ex[1]), Math.abs(oy + ex[3])));
        float x0 = Math.nextDown((float) (ox + ex[0] - sx)), y0 = Math.nextDown((float) (oy + ex[1] - sy));
        float x1 = Math.nextUp((float) (ox + ex[2] + sx)), y1 = Math.nextUp((float) (oy + ex[3] + sy));
        float w = Math.nextUp((float) ((double) x1 - x0)), h = Math.nextUp((float) ((double) y1 - y0));
        if (!Float.isFinite(x0) || !Float.isFinite(y0) || !Float.isFinite(x1) || !Float.isFinite(y1)
                || !Float.isFinite(w) || !Float.isFinite(h)) {
            throw new IllegalArgumentException(what + " put the body's shape out of the float range");
        }
        boxOut[0] = x0;
        boxOut[1] = y0;
        boxOut[2] = w;
        boxOut[3] = h;
        return boxOut;
    }

    /**
     * Sets a body's tight box. The broad phase holds a fat box: when the tight box leaves it,
     * a new fat box (grown by an eighth of the body's size and a pixel, and four times the
     * last move ahead) waits in the dirty list, which queries scan, until enough wait to put
     * them all at once (or the next {@link #step()}): the grid rebuilds after each change, so
     * putting one box per move would rebuild it once per move.
     */
    private void setBox(Body b, float x, float y, float w, float h) {
        if (b.grid != null) {
            b.boxX = b.fatX = 0;
            b.boxY = b.fatY = 0;
            b.boxW = b.fatW = b.grid.width();
            b.boxH = b.fatH = b.grid.height();
            broad.put(b.id, 0, 0, b.boxW, b.boxH);
            return;
        }
        boolean fresh = !b.boxed;
        b.boxed = true;
        double ddx = fresh ? 0 : (double) x - b.boxX, ddy = fresh ? 0 : (double) y - b.boxY;
        b.boxX = x;
        b.boxY = y;
        b.boxW = w;
        b.boxH = h;
        if (!fresh && x >= b.fatX && y >= b.fatY && (double) x + w <= (double) b.fatX + b.fatW
                && (double) y + h <= (double) b.fatY + b.fatH) {
            return;
        }
        double m = 1 + Math.max(w, h) / 8.0;
        double x0 = Math.max(-Float.MAX_VALUE, x - m + Math.min(0, 4 * ddx));
        double y0 = Math.max(-Float.MAX_VALUE, y - m + Math.min(0, 4 * ddy));
        double x1 = Math.min(Float.MAX_VALUE, (double) x + w + m + Math.max(0, 4 * ddx));
        double y1 = Math.min(Float.MAX_VALUE, (double) y + h + m + Math.max(0, 4 * ddy));
        // Never past the float range: a body near its edge gets a fat box that ends there.
        b.fatX = Math.min(x, Math.max(-Float.MAX_VALUE, Math.nextDown((float) x0)));
        b.fatY = Math.min(y, Math.max(-Float.MAX_VALUE, Math.nextDown((float) y0)));
        b.fatW = (float) Math.min(Float.MAX_VALUE, Math.nextUp(x1 - b.fatX));
        b.fatH = (float) Math.min(Float.MAX_VALUE, Math.nextUp(y1 - b.fatY));
        if (b.dirtyIndex < 0) {
            if (dirtyCount == dirty.length) {
                dirty = java.util.Arrays.copyOf(dirty, 2 * dirtyCount);
            }
            b.dirtyIndex = dirtyCount;
            dirty[dirtyCount++] = b;
        }
        flushIfMany();
    }

    private Body[] dirty = new Body[16];
    private int dirtyCount;
    private boolean holdFlush;

    private void flushIfMany() {
        if (!holdFlush && dirtyCount > 64 + 2 * Math.sqrt(size)) {
            flush();
        }
    }

    /** Puts every waiting fat box into the broad phase. */
    private void flush() {
        for (int i = 0; i < dirtyCount; i++) {
            Body b = dirty[i];
            broad.put(b.id, b.fatX, b.fatY, b.fatW, b.fatH);
            b.dirtyIndex = -1;
            dirty[i] = null;
        }
        dirtyCount = 0;
    }

    private void undirty(Body b) {
        int i = b.dirtyIndex;
        Body last = dirty[--dirtyCount];
        dirty[i] = last;
        last.dirtyIndex = i;
        dirty[dirtyCount] = null;
        b.dirtyIndex = -1;
    }

    // ---------------------------------------------------------------- events

    /**
     * Ends the frame: the contacts now (pairs whose layers accept each other that overlap, or
     * that a move since the last step met), compared with those of the last step. Call once a
     * frame, after the moves.
     *
     * @return the events, ENTER and EXIT once per change and STAY for each contact that goes
     *         on, bodies of each pair in the order added; empty if there are none, never null
     * @throws IllegalStateException if called from inside a callback of this world
     */
    public List<BodyEvent> step() {
        checkNotInCallback("step");
        flush();
        Map<Long, Body[]> now = new HashMap<>();
        broad.pairs((i, j) -> {
            Body a = byId[i], b = byId[j];
            if (a.accepts(b) && overlap(a, b)) {
                putPair(now, a, b);
            }
        });
        if (!stepped) {
            for (Collision c : stepCollisions) {
                if (c.mover().world == this && c.other().world == this && c.mover().accepts(c.other())) {
                    putPair(now, c.mover(), c.other());
                }
            }
        }
        List<BodyEvent> events = new ArrayList<>();
        List<Long> keys = new ArrayList<>(now.keySet());
        for (Long k : contacts.keySet()) {
            if (!now.containsKey(k)) {
                keys.add(k);
            }
        }
        Collections.sort(keys);
        for (Long k : keys) {
            Body[] p = now.get(k);
            if (p == null) {
                Body[] q = contacts.get(k);
                events.add(new BodyEvent(BodyEvent.Kind.EXIT, q[0], q[1]));
            } else {
                events.add(new BodyEvent(contacts.containsKey(k) ? BodyEvent.Kind.STAY : BodyEvent.Kind.ENTER, p[0], p[1]));
            }
        }
        contacts = now;
        stepped = true;
        return events;
    }

    /**
     * Reports every pair of bodies whose layers accept each other and whose shapes overlap now
     * (a grid's body: one of its solid cells), each pair once, the body added first first, in
     * no particular order of pairs: the all-pairs question of {@link BroadPhase#pairs} asked
     * of the bodies, without making events. Sensors are reported like any body.
     *
     * @param out receives each pair; it may read the world but not change it, not null
     * @throws IllegalArgumentException if {@code out} is null, or it threw (the world is as it
     *                                  was)
     * @throws IllegalStateException    if called from inside a callback of this world, or
     *                                  {@code out} tried to change the world
     */
    public void pairs(java.util.function.BiConsumer<Body, Body> out) {
        Check.notNull("out", out);
        checkNotInCallback("pairs");
        flush();
        broad.pairs((i, j) -> {
            Body a = byId[i], b = byId[j];
            if (a.accepts(b) && overlap(a, b)) {
                if (a.serial > b.serial) {
                    Body t = a;
                    a = b;
                    b = t;
                }
                callbackDepth++;
                try {
                    out.accept(a, b);
                } catch (IllegalStateException e) {
                    throw e;
                } catch (RuntimeException e) {
                    throw new IllegalArgumentException("out threw " + e + " for " + a + " and " + b, e);
                } finally {
                    callbackDepth--;
                }
            }
        });
    }

    private static void putPair(Map<Long, Body[]> map, Body a, Body b) {
        if (a.serial > b.serial) {
            Body t = a;
            a = b;
            b = t;
        }
        map.putIfAbsent(((long) a.serial << 32) | b.serial, new Body[] {a, b});
    }

    /** Do two bodies overlap now (a grid's body: one of its solid cells)? */
    private boolean overlap(Body a, Body b) {
        // The tight boxes first (the broad phase holds fat ones): no shape is made for a pair
        // whose boxes are apart.
        if (a.boxX > (double) b.boxX + b.boxW || b.boxX > (double) a.boxX + a.boxW
                || a.boxY > (double) b.boxY + b.boxH || b.boxY > (double) a.boxY + a.boxH) {
            return false;
        }
        if (a.grid != null && b.grid != null) {
            return false;
        }
        if (a.grid != null) {
            return gridMeets(a, b.shape());
        }
        if (b.grid != null) {
            return gridMeets(b, a.shape());
        }
        return a.shape().overlaps(b.shape());
    }

    /** Does a shape overlap a solid cell of a grid's body? */
    private boolean gridMeets(Body g, Shape s) {
        return gridCell(g, s) >= 0;
    }

    /** The first solid cell (row by row) of a grid's body that a shape overlaps, or -1. */
    private int gridCell(Body g, Shape s) {
        Grid grid = g.grid;
        double pad = pad(s.minX(), s.minY(), s.maxX(), s.maxY());
        int c0 = Math.max(0, grid.colAt((float) (s.minX() - pad))), c1 = Math.min(grid.cols() - 1, grid.colAt((float) (s.maxX() + pad)));
        int r0 = Math.max(0, grid.rowAt((float) (s.minY() - pad))), r1 = Math.min(grid.rows() - 1, grid.rowAt((float) (s.maxY() + pad)));
        for (int row = r0; row <= r1; row++) {
            for (int col = c0; col <= c1; col++) {
                if (grid.isSolid(col, row) && s.overlaps(grid.cellRect(col, row))) {
                    return row * grid.cols() + col;
                }
            }
        }
        return -1;
    }

    /**
     * The collisions the moves reported since the last {@link #step()}, or, right after a step,
     * those of the frame it ended (until the next move): for drawing the frame's contacts.
     *
     * @return the collisions in the order met, a new list; empty if none, never null
     */
    public List<Collision> collisions() {
        return new ArrayList<>(stepCollisions);
    }

    // ---------------------------------------------------------------- queries

    /**
     * The bodies whose shape holds a point ({@link Shape#contains}: the outline of a shape with
     * area does not count; a grid's body: the point is inside a solid cell).
     *
     * <p>A NaN or infinite coordinate throws, naming it.
     *
     * @param x the point's x
     * @param y the point's y
     * @return the bodies, in the order added; empty if none, never null
     * @throws IllegalArgumentException if x or y is NaN or infinite
     */
    public List<Body> queryPoint(float x, float y) {
        return queryPoint(x, y, ALL);
    }

    /**
     * The bodies the filter keeps whose shape holds a point: see {@link #queryPoint(float, float)}.
     *
     * <p>A NaN or infinite coordinate throws, naming it.
     *
     * @param x      the point's x
     * @param y      the point's y
     * @param filter which bodies to keep, not null
     * @return the bodies, in the order added; empty if none, never null
     * @throws IllegalArgumentException if x or y is NaN or infinite, {@code filter} is null or
     *                                  threw
     */
    public List<Body> queryPoint(float x, float y, Predicate<Body> filter) {
        Check.finite("x", x);
        Check.finite("y", y);
        Check.notNull("filter", filter);
        gather(x, y, x, y);
        List<Body> out = new ArrayList<>();
        for (int i = 0; i < candCount; i++) {
            Body b = byId[cand[i]];
            boolean in;
            if (b.grid != null) {
                Grid g = b.grid;
                int col = g.colAt(x), row = g.rowAt(y);
                in = g.inGrid(col, row) && g.isSolid(col, row) && g.cellRect(col, row).contains(x, y);
            } else {
                in = b.shape().contains(x, y);
            }
            if (in && keep(filter, b)) {
                out.add(b);
            }
        }
        return out;
    }

    /**
     * The bodies whose shape overlaps a box ({@link Shape#overlaps}, the touching rule).
     *
     * <p>A NaN or infinite number, or a negative size, throws, naming it.
     *
     * @param x the box's left edge
     * @param y the box's top edge
     * @param w the box's width, 0 or more
     * @param h the box's height, 0 or more
     * @return the bodies, in the order added; empty if none, never null
     * @throws IllegalArgumentException if a number is NaN or infinite, or a size negative
     */
    public List<Body> queryBox(float x, float y, float w, float h) {
        return queryShape(new Rect(x, y, w, h), ALL);
    }

    /**
     * The bodies the filter keeps whose shape overlaps a box: see
     * {@link #queryBox(float, float, float, float)}.
     *
     * <p>A NaN or infinite number, or a negative size, throws, naming it.
     *
     * @param x      the box's left edge
     * @param y      the box's top edge
     * @param w      the box's width, 0 or more
     * @param h      the box's height, 0 or more
     * @param filter which bodies to keep, not null
     * @return the bodies, in the order added; empty if none, never null
     * @throws IllegalArgumentException if a number is NaN or infinite, a size negative, or
     *                                  {@code filter} is null or threw
     */
    public List<Body> queryBox(float x, float y, float w, float h, Predicate<Body> filter) {
        return queryShape(new Rect(x, y, w, h), filter);
    }

    /**
     * The bodies whose shape overlaps a shape ({@link Shape#overlaps}).
     *
     * @param shape the shape, not null
     * @return the bodies, in the order added; empty if none, never null
     * @throws IllegalArgumentException if {@code shape} is null
     */
    public List<Body> queryShape(Shape shape) {
        return queryShape(shape, ALL);
    }

    /**
     * The bodies the filter keeps whose shape overlaps a shape.
     *
     * @param shape  the shape, not null
     * @param filter which bodies to keep, not null
     * @return the bodies, in the order added; empty if none, never null
     * @throws IllegalArgumentException if an argument is null, or {@code filter} threw
     */
    public List<Body> queryShape(Shape shape, Predicate<Body> filter) {
        Check.notNull("shape", shape);
        Check.notNull("filter", filter);
        return meeting(shape, null, filter);
    }

    private List<Body> meeting(Shape shape, Body except, Predicate<Body> filter) {
        gather(shape.minX(), shape.minY(), shape.maxX(), shape.maxY());
        List<Body> out = new ArrayList<>();
        for (int i = 0; i < candCount; i++) {
            Body b = byId[cand[i]];
            if (b == except) {
                continue;
            }
            boolean meets = b.grid != null ? gridMeets(b, shape) : b.shape().overlaps(shape);
            if (meets && keep(filter, b)) {
                out.add(b);
            }
        }
        return out;
    }

    /**
     * The bodies a body overlaps now (not itself; for a grid's body, the bodies on its solid
     * cells).
     *
     * @param body a body of this world, not null
     * @return the bodies, in the order added; empty if none, never null
     * @throws IllegalArgumentException if {@code body} is null, removed or another world's
     */
    public List<Body> overlapping(Body body) {
        return overlapping(body, ALL);
    }

    /**
     * The bodies the filter keeps that a body overlaps now.
     *
     * @param body   a body of this world, not null
     * @param filter which bodies to keep, not null
     * @return the bodies, in the order added; empty if none, never null
     * @throws IllegalArgumentException if an argument is null, the body is removed or another
     *                                  world's, or {@code filter} threw
     */
    public List<Body> overlapping(Body body, Predicate<Body> filter) {
        own("body", body);
        Check.notNull("filter", filter);
        if (body.grid == null) {
            return meeting(body.shape(), body, filter);
        }
        gather(body.boxX, body.boxY, (double) body.boxX + body.boxW, (double) body.boxY + body.boxH);
        List<Body> out = new ArrayList<>();
        for (int i = 0; i < candCount; i++) {
            Body b = byId[cand[i]];
            if (b != body && b.grid == null && gridMeets(body, b.shape()) && keep(filter, b)) {
                out.add(b);
            }
        }
        return out;
    }

    /**
     * Every body a ray meets within its reach, nearest first ({@link Ray#cast}: distance,
     * point, normal from the ray into the body); each body once, at its nearest point.
     *
     * @param ray the ray, not null
     * @return the hits, nearest first (equal distances: in the order added); empty if none,
     *         never null
     * @throws IllegalArgumentException if {@code ray} is null
     */
    public List<BodyHit> raycast(Ray ray) {
        return raycast(ray, ALL);
    }

    /**
     * Every body the filter keeps that a ray meets, nearest first: see {@link #raycast(Ray)}.
     *
     * @param ray    the ray, not null
     * @param filter which bodies to keep, not null
     * @return the hits, nearest first; empty if none, never null
     * @throws IllegalArgumentException if an argument is null, or {@code filter} threw
     */
    public List<BodyHit> raycast(Ray ray, Predicate<Body> filter) {
        Check.notNull("ray", ray);
        Check.notNull("filter", filter);
        return rayHits(ray, filter, false);
    }

    /**
     * The nearest body a ray meets within its reach: line of sight, a laser.
     *
     * @param ray    the ray, not null
     * @param filter which bodies to keep (leave out the one looking), not null
     * @return the nearest hit, or null if the ray meets nothing
     * @throws IllegalArgumentException if an argument is null, or {@code filter} threw
     */
    public BodyHit raycastFirst(Ray ray, Predicate<Body> filter) {
        Check.notNull("ray", ray);
        Check.notNull("filter", filter);
        List<BodyHit> hits = rayHits(ray, filter, true);
        return hits.isEmpty() ? null : hits.get(0);
    }

    private List<BodyHit> rayHits(Ray ray, Predicate<Body> filter, boolean firstOnly) {
        candCount = 0;
        double[] nearest = {Double.POSITIVE_INFINITY};
        broad.raycast(ray, (id, distance) -> {
            if (firstOnly && distance > nearest[0]) {
                return false;
            }
            if (byId[id].dirtyIndex < 0) {
                collect.accept(id);
            }
            return true;
        });
        for (int i = 0; i < dirtyCount; i++) {
            collect.accept(dirty[i].id);
        }
        List<BodyHit> out = new ArrayList<>();
        for (int i = 0; i < candCount; i++) {
            Body b = byId[cand[i]];
            BodyHit hit = b.grid != null ? gridRay(b, ray) : hitOf(b, ray.cast(b.shape()));
            if (hit != null && keep(filter, b)) {
                out.add(hit);
                if (firstOnly) {
                    nearest[0] = Math.min(nearest[0], hit.distance());
                }
            }
        }
        out.sort((p, q) -> p.distance() != q.distance() ? Float.compare(p.distance(), q.distance())
                : Integer.compare(p.body().serial, q.body().serial));
        if (firstOnly && out.size() > 1) {
            return out.subList(0, 1);
        }
        return out;
    }

    private static BodyHit hitOf(Body b, RayHit h) {
        return h == null ? null : new BodyHit(b, h, -1);
    }

    /** The nearest solid cell of a grid's body that a ray meets, within its reach and the grid. */
    private BodyHit gridRay(Body b, Ray ray) {
        Grid g = b.grid;
        double len = Math.hypot(ray.dx(), ray.dy());
        double reach = Math.min(ray.maxDistance(), Math.hypot(g.width(), g.height())
                + Math.hypot(Math.max(Math.abs(ray.ox()), Math.abs(ray.ox() - g.width())),
                Math.max(Math.abs(ray.oy()), Math.abs(ray.oy() - g.height()))));
        double ex = ray.ox() + ray.dx() / len * reach, ey = ray.oy() + ray.dy() / len * reach;
        int c0 = Math.max(0, g.colAt((float) Math.min(ray.ox(), ex))), c1 = Math.min(g.cols() - 1, g.colAt((float) Math.max(ray.ox(), ex)));
        int r0 = Math.max(0, g.rowAt((float) Math.min(ray.oy(), ey))), r1 = Math.min(g.rows() - 1, g.rowAt((float) Math.max(ray.oy(), ey)));
        BodyHit best = null;
        for (int row = r0; row <= r1; row++) {
            for (int col = c0; col <= c1; col++) {
                if (g.isSolid(col, row)) {
                    RayHit h = ray.cast(g.cellRect(col, row));
                    if (h != null && (best == null || h.distance() < best.distance())) {
                        best = new BodyHit(b, h, row * g.cols() + col);
                    }
                }
            }
        }
        return best;
    }

    // ---------------------------------------------------------------- looking inside

    /**
     * Visits the broad phase's own regions, for drawing: see {@link BroadPhase#cells}.
     *
     * @param out receives each region, not null
     * @throws IllegalArgumentException if {@code out} is null
     */
    public void cells(BoxConsumer out) {
        Check.notNull("out", out);
        flush();
        broad.cells(out);
    }

    /** @return the name of the broad phase inside, for labels */
    @Override
    public String toString() {
        return "World of " + size + " bodies on " + broad;
    }

    /** The broad phase, for the tests that check a refused call changed nothing. */
    BroadPhase broadPhase() {
        return broad;
    }

    // ---------------------------------------------------------------- helpers

    private static final Predicate<Body> ALL = b -> true;

    private boolean keep(Predicate<Body> filter, Body b) {
        if (filter == ALL) {
            return true;
        }
        callbackDepth++;
        try {
            return filter.test(b);
        } catch (IllegalStateException e) {
            throw e;
        } catch (RuntimeException e) {
            throw new IllegalArgumentException("filter threw " + e + " for " + b, e);
        } finally {
            callbackDepth--;
        }
    }

    /** The ids of the bodies whose boxes meet a box (padded by a few float steps), in the order added. */
    void gather(double left, double top, double right, double bottom) {
        double pad = pad(left, top, right, bottom);
        float x0 = (float) Math.max(-Float.MAX_VALUE, left - pad), y0 = (float) Math.max(-Float.MAX_VALUE, top - pad);
        float x1 = (float) Math.min(Float.MAX_VALUE, right + pad), y1 = (float) Math.min(Float.MAX_VALUE, bottom + pad);
        float w = (float) Math.min(Float.MAX_VALUE, Math.nextUp((double) x1 - x0));
        float h = (float) Math.min(Float.MAX_VALUE, Math.nextUp((double) y1 - y0));
        candCount = 0;
        broad.query(x0, y0, w, h, collect);
        int kept = 0;
        for (int i = 0; i < candCount; i++) {
            if (byId[cand[i]].dirtyIndex < 0) {
                cand[kept++] = cand[i];  // a dirty body's box in the broad phase is stale
            }
        }
        candCount = kept;
        for (int i = 0; i < dirtyCount; i++) {
            Body b = dirty[i];
            if (b.fatX <= x1 && x0 <= (double) b.fatX + b.fatW && b.fatY <= y1 && y0 <= (double) b.fatY + b.fatH) {
                collect.accept(b.id);
            }
        }
        sortCandidates();
    }

    static double pad(double left, double top, double right, double bottom) {
        double m = Math.max(Math.max(Math.abs(left), Math.abs(right)), Math.max(Math.abs(top), Math.abs(bottom)));
        return 4 * Math.ulp((float) Math.min(m, Float.MAX_VALUE / 4)) + Float.MIN_NORMAL;
    }

    /**
     * Sorts the candidates by the order added (ties are met in that order): insertion sort for
     * the few of a move's leg, a sort of (serial, id) keys for the many of a large query, so a
     * query over the whole world costs k log k, not k squared.
     */
    private void sortCandidates() {
        if (candCount <= 32) {
            for (int i = 1; i < candCount; i++) {
                int id = cand[i];
                int s = byId[id].serial;
                int j = i - 1;
                while (j >= 0 && byId[cand[j]].serial > s) {
                    cand[j + 1] = cand[j];
                    j--;
                }
                cand[j + 1] = id;
            }
            return;
        }
        if (keys.length < candCount) {
            keys = new long[Math.max(candCount, 2 * keys.length)];
        }
        for (int i = 0; i < candCount; i++) {
            keys[i] = ((long) byId[cand[i]].serial << 32) | cand[i];
        }
        java.util.Arrays.sort(keys, 0, candCount);
        for (int i = 0; i < candCount; i++) {
            cand[i] = (int) keys[i];
        }
    }

    /** The sort keys of a large query's candidates: serial above, id below. */
    private long[] keys = new long[64];

    /** How many bodies the last {@link #gather} found. */
    int candidateCount() {
        return candCount;
    }

    /** The i-th body the last {@link #gather} found, in the order added. */
    Body candidate(int i) {
        return byId[cand[i]];
    }

    /** A body argument of this world, checked. */
    Body own(String name, Body body) {
        Check.notNull(name, body);
        if (body.world == null) {
            throw new IllegalArgumentException(name + " was removed from its world: " + body);
        }
        if (body.world != this) {
            throw new IllegalArgumentException(name + " belongs to another world: " + body);
        }
        return body;
    }

    void checkNotInCallback(String what) {
        if (callbackDepth > 0) {
            throw new IllegalStateException(what + " was called from inside a filter of this world: a filter may read"
                    + " the world but not change it; collect the bodies and change the world after the call");
        }
    }
}
