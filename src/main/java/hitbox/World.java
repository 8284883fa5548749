package hitbox;

import hitbox.internal.*;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.function.BiConsumer;
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
 * ({@link Collisions#finished()}); a game that moves many bodies every frame passes its own
 * list ({@link #move(Body, float, float, CollisionFilter, List)}), and a move then makes
 * nothing but what it met. {@link #addCharacter} makes a body that walks on ground,
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
 * <h2>Contacts and events: once a frame</h2>
 * Call {@link #step()} once a frame, after the moves: it returns the {@link BodyEvent}s of the
 * frame, a contact's ENTER and EXIT once each and STAY every step in between. A world with
 * many bodies at rest calls {@link #step(List)} instead, as Box2D v3 users do: only the
 * contacts that began and ended, and the contacts that go on read when needed
 * ({@link #contacts(BiConsumer)}, {@link #contacts(Body, List)}, {@link #inContact}). The
 * contacts are kept from step to step, so a step costs in proportion to the bodies that moved,
 * turned or changed, and a pair of bodies that both stand costs nothing. There are no
 * listeners, so nothing of the sketch runs while the world is changing.
 *
 * <h2>Queries</h2>
 * What a point, a shape (a box is a {@link Rect}) or a ray meets, and what a body overlaps
 * now, each in two forms: the plain one asks about every body and hands back an unmodifiable
 * list, bodies in the order they were added, ray hits nearest first; the other takes a filter
 * ({@code Predicate<Body>}, {@code b -> true} for every body) and fills the caller's list,
 * which allocates nothing once the list has grown: the form for a query every frame. A
 * {@link Grid} added with {@link #add(Grid)} is one body that acts as its solid cells (cells
 * inside the grid; beyond its edges is open here); a ray walks its cells along the ray.
 *
 * <h2>Bad input</h2>
 * A null, a NaN or infinite number or another world's body throws an
 * {@link IllegalArgumentException} naming the parameter or the rule. A removed body throws an
 * {@link IllegalStateException} wherever it is used, here as in its own methods. Changing the
 * world (add, remove, move, turn, layers) from inside a filter or a query's filter throws an
 * {@link IllegalStateException}. A filter that throws is reported as an
 * {@link IllegalArgumentException} naming {@code filter}, the filter's exception as its cause
 * (an {@code IllegalStateException} passes as it is). Every refused call leaves the world
 * exactly as it was: every body's pose and shape and the broad phase's boxes. Not
 * thread-safe.
 *
 * <p>This class is the face of the world, longer than most (about 1,010 lines, most of them
 * javadoc of the public methods), over parts with one job each: the bodies with their poses
 * and boxes and the broad phase's upkeep ({@code BodyTable}), the contacts kept from step to
 * step ({@code ContactTracker}), a grid's body's cells ({@code GridCollider}), the queries
 * ({@code WorldQueries}), the move's walk ({@code Mover}) and a carrier's move with its
 * riders ({@code CarrierMove}); it keeps the checks, the collisions kept for the step and
 * the callbacks' rules. The character's rules are in {@link CharacterBody}, the
 * shapes' placement in {@code Poses} and the rectangles' walk in {@code MoveAndSlide}.
 */
public final class World {

    /** How many times one {@link #move} stops at a body and goes on before giving up. */
    public static final int MAX_LEGS = 8;

    /**
     * How many of the collisions met since the last {@link #step()} a world keeps at least
     * (eight per body, if that is more), when it is moved and not stepped (bump.lua's way: the
     * moves' answers used, no events): at twice that many, the older ones are let go down to
     * that many, so such a world does not fill the memory with a collision a move for as long
     * as it runs.
     */
    public static final int UNSTEPPED_COLLISIONS = 1 << 16;

    private final BroadPhase broad;
    private int callbackDepth;

    // Contacts and the collisions of the current step.
    private final ArrayList<Collision> stepCollisions = new ArrayList<>();

    /** The caller's list of a move that fills one, and the body it is for (not its riders). */
    private List<Collision> sink;
    private Body sinkBody;
    /** Is a carrier's rider moving (its collisions kept for the step, none handed back)? */
    private boolean quiet;
    /** Where the held collisions of a carrier's move begin, or -1; and {@link #stepped} then. */
    private int heldFrom = -1;
    private boolean heldStepped;
    private boolean stepped;
    /** The contacts, kept from step to step. */
    private final ContactTracker tracker;
    /** The bodies with their poses and boxes, and the broad phase's upkeep. */
    private final BodyTable table;

    /** A grid's body's cells, for the queries and the contacts. */
    private final GridCollider grids = new GridCollider();
    /** The queries: what a point, a shape, a body and a ray meet. */
    private final WorldQueries queries = new WorldQueries(this, grids);
    /** The move-and-slide solver: every move walks there. */
    private final Mover mover = new Mover(this);
    /** A carrier's move with its riders. */
    private final CarrierMove carriers;

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
        this.tracker = new ContactTracker(this, broadPhase, grids);
        this.table = new BodyTable(this, broadPhase, tracker);
        this.carriers = new CarrierMove(this, table, tracker);
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
        double px = (Extents.minX(shape) + Extents.maxX(shape)) / 2, py = (Extents.minY(shape) + Extents.maxY(shape)) / 2;
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
        return table.add(home, px, py, tx, ty, angle, grid);
    }

    /**
     * Removes a body. It is dead afterwards: its own changing methods throw. The next
     * {@link #step()} reports the EXIT of its contacts.
     *
     * @param body a body of this world, not null
     * @throws IllegalArgumentException if {@code body} is null or another world's
     * @throws IllegalStateException    if the body was removed, or this is called from inside
     *                                  a callback of this world
     */
    public void remove(Body body) {
        own("body", body);
        checkNotInCallback("remove");
        table.remove(body);
    }

    /** @return how many bodies the world holds */
    public int size() {
        return table.size();
    }

    /**
     * The bodies, in the order they were added.
     *
     * @return the bodies, unmodifiable (a copy: later adds and removes do not show in it),
     *         never null
     */
    public List<Body> bodies() {
        return Collections.unmodifiableList(table.all());
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
     * @throws IllegalArgumentException if {@code body} is null, another world's or a grid's,
     *                                  dx or dy is NaN or infinite, or the move leaves the
     *                                  float range
     * @throws IllegalStateException    if the body was removed, or this is called from inside
     *                                  a callback of this world
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
     *                                  the body is another world's or a grid's, the move
     *                                  leaves the float range, or the filter threw (then the
     *                                  world is as it was)
     * @throws IllegalStateException    if the body was removed, this is called from inside a
     *                                  callback of this world, or the filter tried to change
     *                                  the world
     */
    public Collisions move(Body body, float dx, float dy, CollisionFilter filter) {
        checkMove(body, dx, dy, filter);
        return body.carrier ? carriers.move(body, dx, dy, filter) : moveOne(body, dx, dy, filter);
    }

    /**
     * Moves a body as {@link #move(Body, float, float, CollisionFilter)} does, putting what it
     * met into the caller's list instead of a new {@link Collisions}: the form for a move every
     * frame, which makes nothing but the collisions themselves once the list has grown. A
     * character's body walks by its character's rules, as there.
     *
     * <p>A NaN or infinite move throws, naming it, and nothing moves; so does a list that
     * cannot be added to, and then the list is as it was too.
     *
     * @param body   the body, of this world, not a grid's, not null
     * @param dx     the move this frame, x part
     * @param dy     the move this frame, y part
     * @param filter the reaction to each other body, not null
     * @param out    the caller's list: the collisions are added after what it holds, in the
     *               order met; not null
     * @return whether the move finished ({@link Collisions#finished()}); where it ended is
     *         {@link Body#shape()}
     * @throws IllegalArgumentException if an argument is null, dx or dy is NaN or infinite,
     *                                  the body is another world's or a grid's, the move
     *                                  leaves the float range, the filter threw, or
     *                                  {@code out} cannot be added to (then the world is as it
     *                                  was)
     * @throws IllegalStateException    if the body was removed, this is called from inside a
     *                                  callback of this world, or the filter tried to change
     *                                  the world
     */
    public boolean move(Body body, float dx, float dy, CollisionFilter filter, List<Collision> out) {
        checkMove(body, dx, dy, filter);
        Check.notNull("out", out);
        sink = out;
        sinkBody = body;
        try {
            return (body.carrier ? carriers.move(body, dx, dy, filter) : moveOne(body, dx, dy, filter)).finished();
        } finally {
            sink = null;
            sinkBody = null;
        }
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
        if (!Float.isFinite(body.pivotX() + dx) || !Float.isFinite(body.pivotY() + dy)
                || !Float.isFinite(body.boxX + dx) || !Float.isFinite(body.boxY + dy)
                || !Float.isFinite(body.boxX + body.boxW + dx) || !Float.isFinite(body.boxY + body.boxH + dy)) {
            throw new IllegalArgumentException("dx and dy move the body out of the float range: " + body + " by ("
                    + dx + ", " + dy + ")");
        }
    }

    /** One body's move, a character's by its own rules. */
    Collisions moveOne(Body m, float dx, float dy, CollisionFilter filter) {
        return m.character != null ? m.character.walk(mover, dx, dy, filter) : mover.move(m, dx, dy, filter);
    }

    /**
     * A rider's part of a carrier's move ({@link CarrierMove}): by its character's filter if it
     * is one, else sliding; its collisions kept for the step, none handed back.
     */
    void moveRider(Body rider, float dx, float dy) {
        quiet = true;
        try {
            mover.move(rider, dx, dy, rider.character != null ? rider.character.filter() : SLIDE);
        } finally {
            quiet = false;
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

    /**
     * The world changes: the mover's pose, shape and box; the collisions handed back, into the
     * caller's list if the move was asked for with one (first: a list that refuses them leaves
     * the world as it was).
     */
    Collisions commit(Body m, Spot start, Spot end, List<Collision> found, boolean finished) {
        Collisions result = m == sinkBody ? intoSink(found, finished)
                : quiet ? (finished ? Collisions.NONE : Collisions.UNFINISHED) : Collisions.of(found, finished);
        table.moved(m, start, end);
        keepForStep(found);
        found.clear();
        return result;
    }

    /** A move's collisions added to the caller's list; the answer says only whether it finished. */
    private Collisions intoSink(List<Collision> found, boolean finished) {
        int before = sink.size();
        try {
            for (int i = 0, n = found.size(); i < n; i++) {
                sink.add(found.get(i));
            }
        } catch (UnsupportedOperationException e) {
            if (sink.size() > before) {
                sink.subList(before, sink.size()).clear();
            }
            throw refused("out", e);
        }
        return finished ? Collisions.NONE : Collisions.UNFINISHED;
    }

    /** A move's collisions, kept for the next step's contacts. */
    private void keepForStep(List<Collision> found) {
        if (stepped && heldFrom < 0) {
            stepCollisions.clear();
            stepped = false;
        }
        for (int i = 0, n = found.size(); i < n; i++) {
            stepCollisions.add(found.get(i));  // not addAll, which copies the list into a new array
        }
        if (heldFrom < 0) {
            trimStepCollisions();
        }
    }

    /** Keeps the latest of the collisions of a world moved but not stepped (see {@link #collisions()}). */
    private void trimStepCollisions() {
        int keep = Math.max(UNSTEPPED_COLLISIONS, 8 * table.size());
        if (stepCollisions.size() > 2 * keep) {
            // Half of them go at once, so the shift is paid once per keep collisions.
            stepCollisions.subList(0, stepCollisions.size() - keep).clear();
        }
    }

    /**
     * Holds the collisions since the last step as they are, for a carrier's move that may be
     * refused: its moves add after them, and none go until {@link #releaseCollisions()}
     * (the move done) or {@link #dropHeldCollisions()} (refused: the list as it was).
     */
    void holdCollisions() {
        heldFrom = stepCollisions.size();
        heldStepped = stepped;
    }

    /** The held moves done: as if each had been kept as it came. */
    void releaseCollisions() {
        int from = heldFrom;
        heldFrom = -1;
        if (heldStepped) {
            // Those of the frame the last step ended give way to the new frame's, shifted down by hand.
            int n = stepCollisions.size() - from;
            for (int i = 0; i < n; i++) {
                stepCollisions.set(i, stepCollisions.get(from + i));
            }
            for (int i = stepCollisions.size() - 1; i >= n; i--) {
                stepCollisions.remove(i);
            }
            stepped = false;
        }
        trimStepCollisions();
    }

    /** The held moves refused: the collisions as they were before them. */
    void dropHeldCollisions() {
        for (int i = stepCollisions.size() - 1; i >= heldFrom; i--) {
            stepCollisions.remove(i);
        }
        stepped = heldStepped;
        heldFrom = -1;
    }

    // ---------------------------------------------------------------- events

    /**
     * Ends the frame and reports every contact as an event: the contacts now (pairs whose
     * layers accept each other that overlap, or that a move since the last step met), compared
     * with those of the last step. Call once a frame, after the moves. Matter.js's
     * {@code collisionStart}, {@code collisionActive} and {@code collisionEnd} in one list.
     *
     * <p>This is the simple form, for a sketch with a few contacts: it lists a STAY event for
     * every contact that goes on, every frame (the same event object each frame while the
     * contact lasts, so a contact costs a list entry, not a new event; the list is new each
     * step). A world with many bodies at rest calls
     * {@link #step(List)} instead, which hands only the changes, and reads the contacts that
     * go on when it needs them ({@link #contacts(BiConsumer)}, {@link #contacts(Body, List)},
     * {@link #inContact}), as Box2D v3's begin and end events and contact data.
     *
     * @return the events, ENTER and EXIT once per change and STAY for each contact that goes
     *         on, ordered by pair (the pair's body added first, then the other), bodies of each
     *         pair in the order added; unmodifiable, never null; empty if there are none
     * @throws IllegalStateException if called from inside a callback of this world
     */
    public List<BodyEvent> step() {
        checkNotInCallback("step");
        // Room for every contact now and a few changes: no copying as the STAYs go in.
        List<BodyEvent> events = new ArrayList<>(tracker.count() + 16);
        endFrame(events, true);
        return Collections.unmodifiableList(events);
    }

    /**
     * Ends the frame and puts into {@code changes} the contacts that began (ENTER) and ended
     * (EXIT) since the last step, each once; never a STAY. The contacts are those of
     * {@link #step()}. It costs in proportion to what changed: the bodies moved, turned, added,
     * removed or given new layers since the last step (and the grids whose cells changed),
     * and their neighbours; a pair of bodies that both stand keeps its contact untested, and a
     * step in which nothing changed tests no pair and allocates nothing.
     *
     * @param changes cleared, then given the ENTER and EXIT events ordered by pair (the pair's
     *                body added first, then the other); not null, modifiable
     * @throws IllegalArgumentException if {@code changes} is null or cannot be cleared
     * @throws IllegalStateException    if called from inside a callback of this world
     */
    public void step(List<BodyEvent> changes) {
        Check.notNull("changes", changes);
        checkNotInCallback("step");
        try {
            changes.clear();
        } catch (UnsupportedOperationException e) {
            throw refused("changes", e);  // before anything changed
        }
        endFrame(changes, false);
    }

    private void endFrame(List<BodyEvent> out, boolean stays) {
        table.flush();
        tracker.step(stepped ? null : stepCollisions, out, stays);
        stepped = true;
    }

    /**
     * How many pairs of bodies are in contact, as of the last step.
     *
     * @return the number of contacts, 0 or more
     */
    public int contactCount() {
        return tracker.count();
    }

    /**
     * Visits every pair of bodies in contact, as of the last step ({@link #step(List)}): the
     * contacts that go on, read when needed rather than reported every frame. Nothing is made
     * per contact.
     *
     * @param out receives each pair, the body added first first, in no particular order of
     *            pairs; it may read the world but not change it; not null
     * @throws IllegalArgumentException if {@code out} is null, or it threw
     * @throws IllegalStateException    if called from inside a callback of this world, or
     *                                  {@code out} tried to change the world
     */
    public void contacts(BiConsumer<Body, Body> out) {
        Check.notNull("out", out);
        checkNotInCallback("contacts");
        callbackDepth++;
        try {
            tracker.forEach(out);
        } catch (IllegalStateException e) {
            throw e;
        } catch (RuntimeException e) {
            throw new IllegalArgumentException("out threw " + e, e);
        } finally {
            callbackDepth--;
        }
    }

    /**
     * Adds to a list the bodies in contact with a body, as of the last step.
     *
     * @param body a body of this world, not null
     * @param out  the caller's list, which gets the bodies added (in no particular order;
     *             nothing is removed from it), not null
     * @throws IllegalArgumentException if an argument is null, the body is another world's,
     *                                  or {@code out} cannot be added to
     * @throws IllegalStateException    if the body was removed
     */
    public void contacts(Body body, List<Body> out) {
        own("body", body);
        Check.notNull("out", out);
        try {
            tracker.of(body, out);
        } catch (UnsupportedOperationException e) {
            throw refused("out", e);
        }
    }

    /**
     * Are two bodies in contact, as of the last step?
     *
     * @param a a body of this world, not null
     * @param b another body of this world, not null
     * @return true if they were in contact at the last step
     * @throws IllegalArgumentException if an argument is null, or a body is another world's
     * @throws IllegalStateException    if a body was removed
     */
    public boolean inContact(Body a, Body b) {
        own("a", a);
        own("b", b);
        return a != b && tracker.touching(a, b);
    }

    /** The contact tracker, for the tests that count the pairs it tests. */
    ContactTracker tracker() {
        return tracker;
    }

    /** A body's layers changed: its contacts need a look at the next step. */
    void layersChanged(Body b) {
        table.layers(b);
        tracker.changed(b);
    }

    /** {@link BodyTable#mayMeet}: layers accepting and tight boxes overlapping, read without the bodies. */
    boolean mayMeet(int i, int j) {
        return table.mayMeet(i, j);
    }

    /** Do two bodies overlap now (a grid's body: one of its solid cells)? The tracker's pair test, for the queries. */
    boolean overlap(Body a, Body b) {
        return tracker.overlap(a, b);
    }

    /** The body of an id, or null. */
    Body body(int id) {
        return table.body(id);
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
    public void pairs(BiConsumer<Body, Body> out) {
        Check.notNull("out", out);
        checkNotInCallback("pairs");
        table.flush();
        pairsOut = out;
        try {
            broad.pairs(pairScan);
        } finally {
            pairsOut = null;
        }
    }

    /** The caller's sink of the {@link #pairs} call under way (never nested: no call from a callback). */
    private BiConsumer<Body, Body> pairsOut;
    /** {@link #pairs}' scan of the broad phase's pairs, made once: a lambda capturing the sink would be made every call. */
    private final PairConsumer pairScan = this::scanPair;

    private void scanPair(int i, int j) {
        if (!table.mayMeet(i, j)) {
            return;  // most of the broad phase's pairs, rejected without reading the bodies
        }
        Body a = table.body(i), b = table.body(j);
        if (!tracker.overlap(a, b)) {
            return;
        }
        if (a.serial > b.serial) {
            Body t = a;
            a = b;
            b = t;
        }
        callbackDepth++;
        try {
            pairsOut.accept(a, b);
        } catch (IllegalStateException e) {
            throw e;
        } catch (RuntimeException e) {
            throw new IllegalArgumentException("out threw " + e + " for " + a + " and " + b, e);
        } finally {
            callbackDepth--;
        }
    }

    /**
     * The collisions the moves reported since the last {@link #step()}, or, right after a step,
     * those of the frame it ended (until the next move): for drawing the frame's contacts. A
     * world that is moved but not stepped keeps the latest of them only, at least
     * {@link #UNSTEPPED_COLLISIONS} (or eight per body) and at most twice that, and the next
     * step learns of contacts from those kept: call {@code step()} once a frame to have them
     * all.
     *
     * @return the collisions in the order met, unmodifiable; empty if none, never null
     */
    public List<Collision> collisions() {
        return Collections.unmodifiableList(new ArrayList<>(stepCollisions));
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
     * @return the bodies, in the order added, unmodifiable; empty if none, never null
     * @throws IllegalArgumentException if x or y is NaN or infinite
     */
    public List<Body> queryPoint(float x, float y) {
        List<Body> out = new ArrayList<>();
        queryPoint(x, y, ALL, out);
        return Collections.unmodifiableList(out);
    }

    /**
     * The bodies the filter keeps whose shape holds a point, put into the caller's list: the
     * form for a query every frame, which makes nothing once the list has grown.
     *
     * @param x      the point's x
     * @param y      the point's y
     * @param filter which bodies to keep, not null
     * @param out    the caller's list: the bodies are added after what it holds, in the order
     *               added; not null
     * @throws IllegalArgumentException if x or y is NaN or infinite, {@code filter} or
     *                                  {@code out} is null, the filter threw, or {@code out}
     *                                  cannot be added to
     */
    public void queryPoint(float x, float y, Predicate<Body> filter, List<Body> out) {
        Check.finite("x", x);
        Check.finite("y", y);
        Check.notNull("filter", filter);
        Check.notNull("out", out);
        try {
            queries.point(x, y, filter, out);
        } catch (UnsupportedOperationException e) {
            throw refused("out", e);
        }
    }

    /**
     * The bodies whose shape overlaps a shape ({@link Shape#overlaps}, the touching rule): a
     * box is {@code queryShape(new Rect(x, y, w, h))}.
     *
     * @param shape the shape, not null
     * @return the bodies, in the order added, unmodifiable; empty if none, never null
     * @throws IllegalArgumentException if {@code shape} is null
     */
    public List<Body> queryShape(Shape shape) {
        List<Body> out = new ArrayList<>();
        queryShape(shape, ALL, out);
        return Collections.unmodifiableList(out);
    }

    /**
     * The bodies the filter keeps whose shape overlaps a shape (a box is a {@link Rect}), put
     * into the caller's list: the form for a query every frame, which makes nothing once the
     * list has grown.
     *
     * @param shape  the shape, not null
     * @param filter which bodies to keep, not null
     * @param out    the caller's list: the bodies are added after what it holds, in the order
     *               added; not null
     * @throws IllegalArgumentException if an argument is null, {@code filter} threw, or
     *                                  {@code out} cannot be added to
     */
    public void queryShape(Shape shape, Predicate<Body> filter, List<Body> out) {
        Check.notNull("shape", shape);
        Check.notNull("filter", filter);
        Check.notNull("out", out);
        try {
            queries.shape(shape, null, filter, out);
        } catch (UnsupportedOperationException e) {
            throw refused("out", e);
        }
    }

    /**
     * The bodies a body overlaps now (not itself; for a grid's body, the bodies on its solid
     * cells).
     *
     * @param body a body of this world, not null
     * @return the bodies, in the order added, unmodifiable; empty if none, never null
     * @throws IllegalArgumentException if {@code body} is null or another world's
     * @throws IllegalStateException    if the body was removed
     */
    public List<Body> overlapping(Body body) {
        List<Body> out = new ArrayList<>();
        overlapping(body, ALL, out);
        return Collections.unmodifiableList(out);
    }

    /**
     * The bodies the filter keeps that a body overlaps now, put into the caller's list: the
     * form for a query every frame, which makes nothing once the list has grown.
     *
     * @param body   a body of this world, not null
     * @param filter which bodies to keep, not null
     * @param out    the caller's list: the bodies are added after what it holds, in the order
     *               added; not null
     * @throws IllegalArgumentException if an argument is null, the body is another world's,
     *                                  {@code filter} threw, or {@code out} cannot be added to
     * @throws IllegalStateException    if the body was removed
     */
    public void overlapping(Body body, Predicate<Body> filter, List<Body> out) {
        own("body", body);
        Check.notNull("filter", filter);
        Check.notNull("out", out);
        try {
            queries.overlapping(body, filter, out);
        } catch (UnsupportedOperationException e) {
            throw refused("out", e);
        }
    }

    /**
     * Every body a ray meets within its reach, nearest first ({@link Ray#cast}: distance,
     * point, normal from the ray into the body); each body once, at its nearest point. A
     * grid's body: its nearest solid cell, found by walking the cells along the ray.
     *
     * @param ray the ray, not null
     * @return the hits, nearest first (equal distances: in the order added), unmodifiable;
     *         empty if none, never null
     * @throws IllegalArgumentException if {@code ray} is null
     */
    public List<BodyHit> raycast(Ray ray) {
        List<BodyHit> out = new ArrayList<>();
        raycast(ray, ALL, out);
        return Collections.unmodifiableList(out);
    }

    /**
     * Every body the filter keeps that a ray meets, nearest first, put into the caller's list:
     * see {@link #raycast(Ray)}. Nothing is made but the hits once the list has grown.
     *
     * @param ray    the ray, not null
     * @param filter which bodies to keep, not null
     * @param out    the caller's list: the hits are added after what it holds, nearest first;
     *               not null
     * @throws IllegalArgumentException if an argument is null, {@code filter} threw, or
     *                                  {@code out} cannot be added to
     */
    public void raycast(Ray ray, Predicate<Body> filter, List<BodyHit> out) {
        Check.notNull("ray", ray);
        Check.notNull("filter", filter);
        Check.notNull("out", out);
        try {
            queries.ray(ray, filter, false, out);
        } catch (UnsupportedOperationException e) {
            throw refused("out", e);
        }
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
        firstHit.clear();
        queries.ray(ray, filter, true, firstHit);
        BodyHit hit = firstHit.isEmpty() ? null : firstHit.get(0);
        firstHit.clear();
        return hit;
    }

    /** The nearest hit of {@link #raycastFirst}, while it is found. */
    private final ArrayList<BodyHit> firstHit = new ArrayList<>(1);

    // ---------------------------------------------------------------- looking inside

    /**
     * Visits the broad phase's own regions, for drawing: see {@link BroadPhase#cells}.
     *
     * @param out receives each region, not null
     * @throws IllegalArgumentException if {@code out} is null
     */
    public void cells(BoxConsumer out) {
        Check.notNull("out", out);
        table.flush();
        broad.cells(out);
    }

    /** @return the name of the broad phase inside, for labels */
    @Override
    public String toString() {
        return "World of " + table.size() + " bodies on " + broad;
    }

    /** The grids' cell answers, for the tests that count the cells looked at. */
    GridCollider grids() {
        return grids;
    }

    /** The broad phase, for the tests that check a refused call changed nothing. */
    BroadPhase broadPhase() {
        return broad;
    }

    // ---------------------------------------------------------------- helpers

    private static final Predicate<Body> ALL = b -> true;

    boolean keep(Predicate<Body> filter, Body b) {
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
        table.gather(left, top, right, bottom);
    }

    /** A few float steps at a box's largest coordinate, and the smallest normal float. */
    static double pad(double left, double top, double right, double bottom) {
        return BodyTable.pad(left, top, right, bottom);
    }

    /** How many bodies the last {@link #gather} found. */
    int candidateCount() {
        return table.candidateCount();
    }

    /** The i-th body the last {@link #gather} found, in the order added. */
    Body candidate(int i) {
        return table.candidate(i);
    }

    /** The candidates of a ray: the bodies whose boxes it meets, in no particular order. */
    void rayCandidates(Ray ray) {
        table.rayCandidates(ray);
    }

    /** Teleports a body (Body's moveTo, turnTo and turnBy); checked before anything changes. */
    void teleport(Body b, double tx, double ty, float angle, String what) {
        table.teleport(b, tx, ty, angle, what);
    }

    /** The exception for a caller's list the world cannot add to. */
    private static IllegalArgumentException refused(String name, UnsupportedOperationException e) {
        return new IllegalArgumentException(name + " must be a list the world can add to (an ArrayList, say), "
                + "not an unmodifiable one: " + e, e);
    }

    /** A body argument of this world, checked. */
    Body own(String name, Body body) {
        Check.notNull(name, body);
        if (body.world == null) {
            // One kind for a removed body, as its own methods throw: the state is wrong, not the value.
            throw new IllegalStateException(name + " was removed from its world: " + body);
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
