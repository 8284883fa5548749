package hitbox;

import hitbox.internal.*;

/**
 * A shape in a {@link World}, which can move and turn: made by {@link World#add(Shape)}.
 *
 * <p><b>Its shape, in its own frame.</b> A body keeps the shape it was made with and a
 * <em>pose</em>: a position, where its pivot stands ({@link #pivotX()}, {@link #pivotY()}),
 * and an angle ({@link #angle()}, radians, clockwise on screen as Processing's
 * {@code rotate()}, y down). The pivot is, for {@link World#add(Shape)}, the centre of the
 * shape's bounding box as added (so {@code world.add(new Rect(40, 200, 20, 30)).pivotX()} is
 * 50, not the rectangle's left edge 40), for {@link World#add(Shape, float, float, float)} the
 * origin of the frame the shape was given in, so a body made with
 * {@code world.add(new Rect(-20, -10, 40, 20), x, y, a)} is where
 * {@code translate(x, y); rotate(a); rect(-20, -10, 40, 20);} draws. Turning turns it about
 * its pivot. {@link #shape()} is where it stands now, made when asked: a turned
 * rectangle is a {@link Polygon}, a turned ellipse an {@link Ellipse} with its angle added, the
 * other kinds stay their kind. At angle 0 the shape is the shape added, each coordinate moved
 * by the same amount, so a rectangle keeps its exact size.
 *
 * <p><b>Moving by hand</b> ({@link #moveTo}, {@link #turnTo}, {@link #turnBy}) is a teleport:
 * no sweep, nothing in the way is looked at. It re-validates nothing, takes time independent
 * of the number of bodies (a polygon's turn is linear in its vertices), and allocates nothing
 * once the world has grown. To move through the others, use {@link World#move}; to teleport by
 * an offset, {@code moveTo(pivotX() + dx, pivotY() + dy)} (one name, {@code move}, for the move
 * that looks at what is in the way).
 *
 * <p><b>Layers</b>, Box2D's rule: each body has a category (the bits it is) and a mask (the
 * bits it meets). Two bodies meet only when each one's category is in the other's mask
 * ({@code (a.category() & b.mask()) != 0 && (b.category() & a.mask()) != 0}); by default
 * every body is category 1 and meets all. Layers are applied before any
 * {@link CollisionFilter}, in {@link World#move} and the contacts of
 * {@link World#step()}; queries take their own filter. A <b>sensor</b> is reported but never
 * blocks nor is blocked: every move through it, or of it, crosses. A <b>one-way</b> body
 * blocks only a mover that meets its given side ({@link #oneWay(Side)}): a platform that is
 * {@code oneWay(Side.TOP)} is passed from below and from the sides and stood on from above.
 * A <b>carrier</b> ({@link #carrier(boolean)}) takes along, when {@link World#move} moves
 * it, the bodies that stand on it.
 *
 * <p>Bad input: NaN or infinite numbers throw an {@link IllegalArgumentException} naming the
 * parameter, and nothing changes. A body removed from its world is dead: its methods that
 * change it throw an {@link IllegalStateException}; reading it still works. A body may not be
 * changed from inside a filter or query callback of its world ({@link IllegalStateException}).
 *
 * <p>This class is longer than most (about 565 lines): the public face of a body (pose,
 * teleports, layers, sensor, one-way side, carrier, data) with full javadoc, and the few
 * package-private methods through which alone the world's parts change its state and read
 * where it stands (its shape, or the numbers the pair tests read without making one).
 */
public final class Body {
    // The world's bookkeeping: package-private, read by World, Mover and CharacterBody, and
    // written only by the methods below (pose, placed, box, fat, dirtyIndex, removed, becomes).
    World world;
    final int id;
    final int serial;
    final Shape home;
    final Grid grid;
    /** Where the pivot stands in the home shape's frame: the pivot when the translation is 0. */
    final double homePivotX;
    final double homePivotY;
    double tx;
    double ty;
    float angle;
    double cos = 1;
    double sin;
    /** The turned home shape's extents about the pivot: min x, min y, max x, max y. */
    final double[] extents = new double[4];
    /** The shape where it stands, or null until asked after a change. */
    Shape shape;
    /**
     * The shape where it stands as numbers, for the world's pair tests (no shape made each
     * frame for a body that moves); valid while {@link #placementSet}.
     */
    private final Placement placement;
    /** Is {@link #placement} this pose's (set when first asked after a change)? */
    private boolean placementSet;
    /**
     * The placement holds where a walk left the body (a box or a circle): the shape, when
     * asked, is made from those numbers, not from the pose (whose arithmetic can round
     * otherwise).
     */
    private boolean walked;
    /**
     * The fat box: the box held for the body in the broad phase (or waiting to be put there
     * while the body is dirty), the tight box grown by a margin and ahead of its last move.
     */
    float fatX;
    float fatY;
    float fatW;
    float fatH;
    /** Where the body is in the world's list of bodies whose fat box the broad phase lacks, or -1. */
    int dirtyIndex = -1;
    /** Has the body had a box yet? */
    boolean boxed;
    /** The tight box: at or a hair outside the shape's bounds. */
    float boxX;
    float boxY;
    float boxW;
    float boxH;
    int category = 1;
    int mask = -1;
    boolean sensor;
    Side oneWay = Side.NONE;
    boolean carrier;
    Object data;
    /** The character this body is, or null. */
    CharacterBody character;

    Body(World world, int id, int serial, Shape home, double homePivotX, double homePivotY, Grid grid) {
        this.world = world;
        this.id = id;
        this.serial = serial;
        this.home = home;
        this.homePivotX = homePivotX;
        this.homePivotY = homePivotY;
        this.grid = grid;
        this.placement = new Placement(home);
    }

    // ---------------------------------------------------------------- its state, changed by the world

    /**
     * A new pose (a teleport, or the body's first): the translation, the angle with its cosine
     * and sine, the turned shape's extents about the pivot; the shape is made again when asked.
     */
    void pose(double tx, double ty, float angle, double cos, double sin, double[] turnedExtents) {
        this.tx = tx;
        this.ty = ty;
        this.angle = angle;
        this.cos = cos;
        this.sin = sin;
        if (turnedExtents != extents) {
            System.arraycopy(turnedExtents, 0, extents, 0, 4);
        }
        this.shape = null;
        this.placementSet = false;
        this.walked = false;
    }

    /** Moved (not turned) to where a move left it: the translation and the shape there, made by the move. */
    void placed(double tx, double ty, Shape shape) {
        this.tx = tx;
        this.ty = ty;
        this.shape = shape;
        this.placementSet = false;
        this.walked = false;
    }

    /**
     * Moved (not turned) to where a walk left its box: the translation and the box's numbers,
     * with no shape made ({@link #shape()} makes it from them when asked).
     */
    void placedBox(double tx, double ty, float x, float y, float w, float h) {
        placement.rect(x, y, w, h);
        walkedTo(tx, ty);
    }

    /** Moved (not turned) to where a walk left its circle: {@link #placedBox} for a circle. */
    void placedCircle(double tx, double ty, float x, float y, float r) {
        placement.circle(x, y, r);
        walkedTo(tx, ty);
    }

    private void walkedTo(double tx, double ty) {
        this.tx = tx;
        this.ty = ty;
        this.shape = null;
        this.placementSet = true;
        this.walked = true;
    }

    /**
     * Where the body stands as numbers ({@link Placement}), made when first asked after a
     * change, into storage the body keeps: from the shape if it was made, else from the pose.
     *
     * @return the numbers, or null where only {@link #shape()} can answer (a concave
     *         polygon, a flat ellipse, a quarter turn: see {@link Placement})
     */
    Placement placement() {
        if (!placementSet) {
            if (shape != null) {
                placement.of(shape);
            } else {
                placement.place(home, homePivotX, homePivotY, tx, ty, angle, cos, sin);
            }
            placementSet = true;
        }
        return placement.kind() != null ? placement : null;
    }

    /** The tight box, at or a hair outside the shape. */
    void box(float x, float y, float w, float h) {
        boxX = x;
        boxY = y;
        boxW = w;
        boxH = h;
        boxed = true;
    }

    /** The fat box the broad phase holds (or will hold, while the body is dirty). */
    void fat(float x, float y, float w, float h) {
        fatX = x;
        fatY = y;
        fatW = w;
        fatH = h;
    }

    /** Where the body is in the world's list of bodies waiting for the broad phase, or -1. */
    void dirtyIndex(int i) {
        dirtyIndex = i;
    }

    /** Removed from its world: dead from now on. */
    void removed() {
        world = null;
    }

    /** This body is a character's. */
    void becomes(CharacterBody character) {
        this.character = character;
    }

    // ---------------------------------------------------------------- the pose

    /**
     * Where the body's pivot stands now, x: the point it turns about and {@link #moveTo} moves
     * (for {@link World#add(Shape)} the centre of the shape's box as added, so
     * {@code world.add(new Rect(40, 200, 20, 30)).pivotX()} is 50).
     *
     * @return the pivot's x
     */
    public float pivotX() {
        return (float) (homePivotX + tx);
    }

    /**
     * Where the body's pivot stands now, y (see {@link #pivotX()}).
     *
     * @return the pivot's y
     */
    public float pivotY() {
        return (float) (homePivotY + ty);
    }

    /** @return how far the body is turned about its pivot, in radians, clockwise on screen */
    public float angle() {
        return angle;
    }

    /**
     * Where the body stands now: its shape turned and moved by its pose, made when asked (and
     * kept until the body moves again). After {@link World#move}, exactly the shape the move
     * left it as. For a {@link Grid}'s body, the grid's rectangle.
     *
     * @return the shape, never null
     * @throws IllegalArgumentException if rounding the turned polygon to floats makes its
     *                                  outline touch itself (a tiny polygon far from the
     *                                  origin), or the pose puts it out of the float range
     */
    public Shape shape() {
        if (shape == null) {
            shape = walked ? placement.shape() : Poses.place(home, homePivotX, homePivotY, tx, ty, angle, cos, sin);
        }
        return shape;
    }

    /**
     * The shape in the body's own frame: the shape it was added with (for
     * {@link World#add(Shape)}, where it stood then; its pivot was the centre of its
     * box).
     *
     * @return the shape as added, never null
     */
    public Shape homeShape() {
        return home;
    }

    /**
     * The body's box: for a body at angle 0 (and a grid's) exactly {@code shape().bounds()},
     * so a floor added as {@code new Rect(0, 400, 800, 20)} has its top at 400; for a turned
     * body, at or a hair outside {@code shape().bounds()}, made without making the turned
     * shape. (The broad phase holds it grown by a margin, so a body that moves a little costs
     * it nothing.)
     *
     * @return a new rectangle, never null
     */
    public Rect bounds() {
        if (angle == 0) {
            return shape().bounds();
        }
        return new Rect(boxX, boxY, boxW, boxH);
    }

    /**
     * Teleports the body: its pivot moves to (x, y), so that {@link #pivotX()} and
     * {@link #pivotY()} are x and y (not its box's corner: the shape moves with the pivot), its
     * angle stays. Nothing in the way is looked at.
     *
     * <p>A NaN or infinite coordinate throws, naming it, and the body stays where it was.
     *
     * @param x where the pivot goes, x
     * @param y where the pivot goes, y
     * @return this body, for chaining, never null
     * @throws IllegalArgumentException if x or y is NaN or infinite, or the shape would leave
     *                                  the float range
     * @throws IllegalStateException    if the body was removed, is a grid's, or this is called
     *                                  from inside a callback of its world
     */
    public Body moveTo(float x, float y) {
        Check.finite("x", x);
        Check.finite("y", y);
        World w = live("moveTo");
        w.teleport(this, (double) x - homePivotX, (double) y - homePivotY, angle, "x and y");
        return this;
    }

    /**
     * Teleports the body to a pose: its pivot to (x, y) and its angle to {@code angle}, where
     * {@link World#add(Shape, float, float, float)} would place it, so that a body drawn with
     * {@code translate(x, y); rotate(angle);} follows its drawing with one call a frame. The
     * same pose as {@code moveTo(x, y)} then {@code turnTo(angle)}, for the cost of one
     * teleport (Box2D's {@code b2Body_SetTransform}). Nothing in the way is looked at.
     *
     * <p>A NaN or infinite number throws, naming it, and the body stays where it was.
     *
     * @param x     where the pivot goes, x
     * @param y     where the pivot goes, y
     * @param angle the angle it turns to, radians, clockwise on screen
     * @return this body, for chaining, never null
     * @throws IllegalArgumentException if a number is NaN or infinite, or the shape would
     *                                  leave the float range
     * @throws IllegalStateException    if the body was removed, is a grid's, or this is called
     *                                  from inside a callback of its world
     */
    public Body moveTo(float x, float y, float angle) {
        Check.finite("x", x);
        Check.finite("y", y);
        Check.finite("angle", angle);
        World w = live("moveTo");
        w.teleport(this, (double) x - homePivotX, (double) y - homePivotY, angle, "x, y and angle");
        return this;
    }

    /**
     * Turns the body about its pivot to the given angle (a teleport).
     *
     * <p>A NaN or infinite angle throws, naming it, and the body stays as it was.
     *
     * @param angle the new angle, radians, clockwise on screen
     * @return this body, for chaining, never null
     * @throws IllegalArgumentException if angle is NaN or infinite, or the shape would leave
     *                                  the float range
     * @throws IllegalStateException    if the body was removed, is a grid's, or this is called
     *                                  from inside a callback of its world
     */
    public Body turnTo(float angle) {
        Check.finite("angle", angle);
        World w = live("turnTo");
        w.teleport(this, tx, ty, angle, "angle");
        return this;
    }

    /**
     * Turns the body about its pivot by {@code da} (a teleport).
     *
     * <p>A NaN or infinite turn throws, naming it, and the body stays as it was.
     *
     * @param da how much more to turn, radians, clockwise on screen
     * @return this body, for chaining, never null
     * @throws IllegalArgumentException if da is NaN or infinite, or the shape would leave the
     *                                  float range
     * @throws IllegalStateException    if the body was removed, is a grid's, or this is called
     *                                  from inside a callback of its world
     */
    public Body turnBy(float da) {
        Check.finite("da", da);
        World w = live("turnBy");
        w.teleport(this, tx, ty, (float) Math.IEEEremainder((double) angle + da, 2 * Math.PI), "da");
        return this;
    }

    // ---------------------------------------------------------------- what it is

    /** @return true from when the body is added to its world until it is removed from it (false after) */
    public boolean alive() {
        return world != null;
    }

    /** @return the grid this body stands for ({@link World#add(Grid)}), or null for a shape's body */
    public Grid grid() {
        return grid;
    }

    /** @return the bits this body is, Box2D's category bits (1 by default) */
    public int category() {
        return category;
    }

    /** @return the bits of the categories this body meets (all, -1, by default) */
    public int mask() {
        return mask;
    }

    /**
     * Sets the body's layers: what it is and what it meets.
     *
     * @param category the bits this body is (any int; 0 meets nothing)
     * @param mask     the categories it meets (any int; -1 meets all)
     * @return this body, for chaining, never null
     * @throws IllegalStateException if the body was removed or this is called from inside a
     *                               callback of its world
     */
    public Body layers(int category, int mask) {
        World w = live("layers");
        this.category = category;
        this.mask = mask;
        w.layersChanged(this);
        return this;
    }

    /**
     * Do these two bodies meet, by Box2D's rule: each one's category is in the other's mask.
     * The world's own rule, applied before any filter; not API (a sketch that needs it spells
     * it out from {@link #category()} and {@link #mask()}).
     */
    boolean accepts(Body other) {
        return (category & other.mask) != 0 && (other.category & mask) != 0;
    }

    /** @return true if the body is a sensor: reported, never blocking */
    public boolean isSensor() {
        return sensor;
    }

    /**
     * Makes the body a sensor (or a solid body again): every move into it, or of it, crosses,
     * and it is still reported and in contact.
     *
     * @param sensor true for a sensor
     * @return this body, for chaining, never null
     * @throws IllegalStateException if the body was removed or this is called from inside a
     *                               callback of its world
     */
    public Body sensor(boolean sensor) {
        live("sensor");
        this.sensor = sensor;
        return this;
    }

    /** @return the side from which alone the body blocks, or {@link Side#NONE} if it blocks from every side */
    public Side oneWay() {
        return oneWay;
    }

    /**
     * Makes the body one-way: it blocks a mover only when the mover meets the given side of it
     * (the hit's side), and is passed through otherwise. {@code oneWay(Side.TOP)} is a
     * platform stood on from above and jumped through from below and the sides.
     * {@link Side#NONE} makes it block from every side again (the default). A mover that
     * already overlaps it when its move starts is never blocked by it.
     *
     * @param side the side that blocks, or {@link Side#NONE}; not null
     * @return this body, for chaining, never null
     * @throws IllegalArgumentException if {@code side} is null
     * @throws IllegalStateException    if the body was removed or this is called from inside a
     *                                  callback of its world
     */
    public Body oneWay(Side side) {
        Check.notNull("side", side);
        live("oneWay");
        this.oneWay = side;
        return this;
    }

    /** @return true if {@link World#move} carries what stands on this body along with it */
    public boolean isCarrier() {
        return carrier;
    }

    /**
     * Makes the body a carrier (a moving platform): when {@link World#move} moves it, the
     * bodies standing on its top (touching it from above, layers accepting) move along by as
     * much as it moved, sliding against everything else. Going up they move first, and the
     * platform then meets them as any other body (a rider a ceiling stopped stops it, as the
     * filter says); going sideways or down the platform moves first, passing through them.
     *
     * @param carrier true to carry
     * @return this body, for chaining, never null
     * @throws IllegalStateException if the body was removed or this is called from inside a
     *                               callback of its world
     */
    public Body carrier(boolean carrier) {
        live("carrier");
        this.carrier = carrier;
        return this;
    }

    /** @return the sketch's own object kept with the body (a name, a sprite), or null if none was set */
    public Object data() {
        return data;
    }

    /**
     * Keeps any object of the sketch's with the body, for a filter or an event to read.
     *
     * @param data the object, not null (a body made without one has none)
     * @return this body, for chaining, never null
     * @throws IllegalArgumentException if {@code data} is null
     * @throws IllegalStateException    if the body was removed, as every method that changes a
     *                                  body (a filter may set it: it changes no contact)
     */
    public Body data(Object data) {
        Check.notNull("data", data);
        if (world == null) {
            throw new IllegalStateException("data: this body was removed from its world");
        }
        this.data = data;
        return this;
    }

    /** @return the body's kind of shape, position, angle and number, for printing */
    @Override
    public String toString() {
        String kind = grid != null ? "Grid" : home.getClass().getSimpleName();
        return "Body#" + serial + "[" + kind + " at (" + pivotX() + ", " + pivotY() + "), angle " + angle
                + (world == null ? ", removed" : "") + (data != null ? ", " + data : "") + "]";
    }

    /** The world, checked: the body is alive, not a grid's, and its world is not in a callback. */
    private World live(String what) {
        if (world == null) {
            throw new IllegalStateException(what + ": this body was removed from its world");
        }
        world.checkNotInCallback(what);
        return world;
    }
}
