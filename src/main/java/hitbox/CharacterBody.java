package hitbox;

import hitbox.internal.*;

/**
 * A body that walks: it stands on ground, walks up and down slopes at the speed it is given,
 * climbs steps, stays on the ground going down, and is carried by the platforms it stands on.
 * Godot's {@code CharacterBody2D}, Rapier's {@code KinematicCharacterController}, Box2D 3.1's
 * mover, on Hitbox's exact sweeps.
 * <pre>{@code
 * CharacterBody hero = world.addCharacter(new Rect(40, 200, 20, 30)).stepHeight(8).snap(4);
 * vy += 0.5;                                  // gravity, every frame
 * hero.move(vx, vy);
 * if (hero.onGround()) vy = 0;                // landed: stop falling
 * if (jumpPressed && hero.onGround()) vy = -9;
 * }</pre>
 *
 * <h2>Ground, walls and ceilings</h2>
 * A surface met is <em>ground</em> when it faces up within {@link #maxSlope(float)} of
 * {@link #up(float, float) up} (45 degrees by default), a <em>ceiling</em> when it faces down
 * within that angle, and a <em>wall</em> otherwise. On ground the character walks: the part of
 * the move along the ground keeps its sideways length (up a slope or down it, a move of 2
 * pixels sideways goes 2 pixels sideways), and the part into the ground (gravity) is dropped,
 * so it stands still on any ground under any downward push. A wall it slides along, but
 * never gains height from one it is pushed into: steeper slopes are walls, and it slides down
 * them. {@code up(0, 0)} makes every surface a wall: a top-down game.
 *
 * <h2>Steps and snapping</h2>
 * Walking into a wall while on the ground, it tries to step up: up by
 * {@link #stepHeight(float)}, on, and down onto ground; the step is taken only if it lands on
 * ground further on. Walking down a slope or off a step, {@link #snap(float)} keeps it on the
 * ground below when that is no further down than the snap (and it is not moving up).
 *
 * <h2>State after a move</h2>
 * {@link #onGround()} (with {@link #ground()} and {@link #groundNormal()}) says what it
 * stands on after the move, found by a probe a few skins long straight down; {@link #onWall()}
 * and {@link #onCeiling()} say what the move met. Spawned inside a body, or with a body
 * teleported into it, its next move first pushes it out the shortest way.
 *
 * <p>It is a {@link Body} ({@link #body()}) with its layers, sensor flag, data and
 * carrier: {@link World#move} on that body walks by these rules too. A carrier it stands on
 * takes it along with the filter of its last move.
 */
public final class CharacterBody {

    private final Body body;
    private float maxSlope = 45;
    private double cosMaxSlope = StrictMath.cos(Math.toRadians(45));
    private float stepHeight;
    private float snap;
    private double upX;
    private double upY = -1;
    private CollisionFilter filter = World.SLIDE;

    private boolean onGround;
    private boolean onWall;
    private boolean onCeiling;
    private Body ground;
    private Vec groundNormal;

    // During a move.
    private boolean metWall;
    private boolean metCeiling;
    private final double[] redirected = new double[2];
    // The places a move keeps (see Spot; a move's own, set by copying): where it starts, where
    // its walk starts (pushed out of what it began in), where it is, a probe's stop, and a
    // step's raised, moved-on and landed places.
    private final Spot start = new Spot(), from = new Spot(), cur = new Spot(), stop = new Spot();
    private final Spot raised = new Spot(), on = new Spot(), landed = new Spot();

    /**
     * How close to a surface's tilt limit still counts as within it: the rounding of a
     * normal's cosine, so that a 45-degree slope is ground at {@code maxSlope(45)}.
     */
    private static final double SLOPE_TIE = 1e-6;

    CharacterBody(Body body) {
        this.body = body;
        body.becomes(this);
    }

    // ---------------------------------------------------------------- moving

    /**
     * Walks this frame by (dx, dy), sliding along what it meets by the rules of the class
     * notes: {@code move(dx, dy, (m, o) -> Reaction.SLIDE)}.
     *
     * @param dx the move this frame, x part
     * @param dy the move this frame, y part
     * @return what it met, in the order met, and whether the move finished; never null
     * @throws IllegalArgumentException if dx or dy is NaN or infinite, or the move leaves the
     *                                  float range
     * @throws IllegalStateException    if the body was removed, or this is called from inside
     *                                  a callback of its world
     */
    public Collisions move(float dx, float dy) {
        return move(dx, dy, World.SLIDE);
    }

    /**
     * Walks this frame by (dx, dy), each other body reacting as the filter says
     * ({@link Reaction}); the rules of the class notes apply to the bodies it slides on.
     * Nothing changes if it throws.
     *
     * @param dx     the move this frame, x part
     * @param dy     the move this frame, y part
     * @param filter the reaction to each other body, not null
     * @return what it met, in the order met, and whether the move finished; never null
     * @throws IllegalArgumentException if dx or dy is NaN or infinite, the filter is null or
     *                                  threw, or the move leaves the float range
     * @throws IllegalStateException    if the body was removed, or this is called from inside
     *                                  a callback of its world
     */
    public Collisions move(float dx, float dy, CollisionFilter filter) {
        return live("move").move(body, dx, dy, filter);
    }

    /** The character's move, from {@link World#move}: checked already; the world changes at the end. */
    Collisions walk(Mover mv, float dx, float dy, CollisionFilter filter) {
        boolean wasGround = onGround;
        int st = mv.begin();
        start.set(body);
        from.set(start);
        if (mv.blockedAtStart(body, start, filter, st)) {
            mv.pushOut(body, start, filter, from);
            st = mv.restamp();
        }
        metWall = false;
        metCeiling = false;
        mv.walk(body, start, from, dx, dy, filter, st, this);
        cur.set(mv.walkEnd());
        boolean finished = mv.walkFinished();
        boolean rising = dx * upX + dy * upY > 0;
        if (metWall && wasGround && !rising && (upX != 0 || upY != 0)) {
            step(mv, dx, dy, filter, st);
        }
        boolean below = groundBelow(mv, from, cur, filter, st, probeLength(cur));
        if (!below && snap > 0 && wasGround && !rising) {
            float sx = (float) (-upX * snap), sy = (float) (-upY * snap);
            if (mv.probe(body, cur, sx, sy, filter, from, st) && isGround(mv)) {
                mv.probeStop(cur, sx, sy, stop);
                cur.set(stop);
                below = groundBelow(mv, from, cur, filter, st, probeLength(cur));
            }
        }
        // The last probe found the ground, if any.
        Body standsOn = below ? mv.probeBody() : null;
        float groundX = below ? -mv.probeNx() : 0, groundY = below ? -mv.probeNy() : 0;
        Collisions out = mv.end(body, start, cur, finished);
        this.filter = filter;
        onGround = below;
        ground = standsOn;
        if (!onGround) {
            groundNormal = null;
        } else if (groundNormal == null || Float.compare(groundNormal.x(), groundX) != 0
                || Float.compare(groundNormal.y(), groundY) != 0) {
            groundNormal = new Vec(groundX, groundY);  // kept while the slope stays the same: a Vec is a value
        }
        onWall = metWall;
        onCeiling = metCeiling;
        return out;
    }

    /** Is there ground under a shape within a probe's length (a surface that is ground)? Then the last probe met it. */
    private boolean groundBelow(Mover mv, Spot from, Spot cur, CollisionFilter filter, int st, double length) {
        if (upX == 0 && upY == 0) {
            return false;
        }
        float px = (float) (-upX * length), py = (float) (-upY * length);
        return mv.probe(body, cur, px, py, filter, from, st) && isGround(mv);
    }

    /** Four skins: what a resting character may stand off a slanted ground, and then some. */
    private static double probeLength(Spot cur) {
        return 4 * Mover.skin(cur);
    }

    /**
     * A step up: the sideways part of the move that a wall took, tried again from higher up
     * and then down onto ground. Higher up is {@link #stepHeight}, or the rise a slope up to
     * {@link #maxSlope} would give over that part (a wall met at the foot of a ramp, where the
     * character's corner meets the ramp's). The end if it lands on ground further on, either a
     * stair no higher than the step height or a slope that rises no faster than its own tilt:
     * then {@link #cur} is moved there; else it stays as it was.
     */
    private void step(Mover mv, float dx, float dy, CollisionFilter filter, int st) {
        double lx = -upY, ly = upX;
        double want = dx * lx + dy * ly;
        double got = (cur.refX() - from.refX()) * lx + (cur.refY() - from.refY()) * ly;
        double left = want - got, skin = Mover.skin(cur);
        if (Math.abs(left) <= skin || Math.signum(left) != Math.signum(want)) {
            return;
        }
        double height = (cur.maxX() - cur.minX()) * Math.abs(upX) + (cur.maxY() - cur.minY()) * Math.abs(upY);
        double slopeRise = Math.min(height, Math.abs(left) * Math.tan(Math.toRadians(maxSlope)) + 2 * skin);
        double lift = Math.max(stepHeight, slopeRise);
        float ux = (float) (upX * lift), uy = (float) (upY * lift);
        mv.probe(body, cur, ux, uy, filter, from, st);
        mv.probeStop(cur, ux, uy, raised);
        double rose = rise(cur, raised);
        float fx = (float) (lx * left), fy = (float) (ly * left);
        boolean blocked = mv.probe(body, raised, fx, fy, filter, from, st);
        mv.probeStop(raised, fx, fy, on);
        double went = ((on.refX() - raised.refX()) * lx + (on.refY() - raised.refY()) * ly) * Math.signum(left);
        if (went <= skin) {
            return;
        }
        float downX = (float) (-upX * (rose + probeLength(cur))), downY = (float) (-upY * (rose + probeLength(cur)));
        if (!mv.probe(body, on, downX, downY, filter, from, st) || !isGround(mv)) {
            return;
        }
        float floorX = mv.probeNx(), floorY = mv.probeNy();
        mv.probeStop(on, downX, downY, landed);
        double gained = rise(cur, landed);
        double cos = -(floorX * upX + floorY * upY) / Math.hypot(floorX, floorY);
        double tan = Math.sqrt(Math.max(0, 1 - cos * cos)) / cos;
        boolean stair = gained <= stepHeight + skin;
        boolean slope = gained <= went * tan + 2 * skin;
        if (!stair && !slope) {
            return;
        }
        metWall = blocked;
        cur.set(landed);
    }

    /** How much higher (along up) one place stands than another. */
    private double rise(Spot from, Spot to) {
        return (to.refX() - from.refX()) * upX + (to.refY() - from.refY()) * upY;
    }

    /** Is the surface the last probe met ground: facing up within the tilt limit? */
    private boolean isGround(Mover mv) {
        return -(mv.probeNx() * upX + mv.probeNy() * upY) >= cosMaxSlope - SLOPE_TIE && (upX != 0 || upY != 0);
    }

    /** Is a hit's surface a ceiling: facing down within the tilt limit? */
    private boolean isCeiling(double nx, double ny) {
        return (nx * upX + ny * upY) >= cosMaxSlope - SLOPE_TIE && (upX != 0 || upY != 0);
    }

    /** The walk met a surface it slides on (a normal from the character into it). */
    void slid(double nx, double ny) {
        double facing = -(nx * upX + ny * upY);
        if (upX == 0 && upY == 0) {
            metWall = true;
        } else if (facing >= cosMaxSlope - SLOPE_TIE) {
            return;  // ground: the probe at the end reports it
        } else if (isCeiling(nx, ny)) {
            metCeiling = true;
        } else {
            metWall = true;
        }
    }

    /**
     * The rest of a move after sliding into a surface: along ground at the same sideways
     * length, off a wall without gaining height, else the nearest motion clear of the planes met.
     */
    double[] redirect(Mover mv, double rx, double ry, double nx, double ny) {
        double rising = rx * upX + ry * upY;
        boolean hasUp = upX != 0 || upY != 0;
        double facing = -(nx * upX + ny * upY);
        if (hasUp && rising <= 0 && facing >= cosMaxSlope - SLOPE_TIE) {
            double lx = -upY, ly = upX;
            double side = rx * lx + ry * ly;
            double tx = -ny, ty = nx;
            if (tx * lx + ty * ly < 0) {
                tx = -tx;
                ty = -ty;
            }
            double k = side / (tx * lx + ty * ly);
            double wx = k * tx, wy = k * ty;
            if (nx == 0) {
                wy = 0;
            } else if (ny == 0) {
                wx = 0;
            }
            return copy(mv.clip(wx, wy));
        }
        double[] c = mv.clip(rx, ry);
        if (hasUp && rising <= 0 && c[0] * upX + c[1] * upY > 0) {
            // A wall never lifts a character pushed into it.
            mv.addPlane(upX, upY);
            c = mv.clip(rx, ry);
            mv.removeLastPlane();
        }
        return copy(c);
    }

    private double[] copy(double[] c) {
        redirected[0] = c[0];
        redirected[1] = c[1];
        return redirected;
    }

    // ---------------------------------------------------------------- state

    /** @return the character's body (its position, shape, layers, data), never null */
    public Body body() {
        return body;
    }

    /** @return true if it stood on ground after its last move */
    public boolean onGround() {
        return onGround;
    }

    /** @return true if its last move met a wall */
    public boolean onWall() {
        return onWall;
    }

    /** @return true if its last move met a ceiling */
    public boolean onCeiling() {
        return onCeiling;
    }

    /** @return the body it stood on after its last move, or null if it was not on ground */
    public Body ground() {
        return ground;
    }

    /** @return the unit normal out of the ground it stood on after its last move, or null if it was not on ground */
    public Vec groundNormal() {
        return groundNormal;
    }

    /** @return the filter of its last move (sliding before the first), which a carrier moves it with */
    CollisionFilter filter() {
        return filter;
    }

    // ---------------------------------------------------------------- settings

    /**
     * Sets the steepest ground, in degrees from flat: it stands still on slopes up to this and
     * walks up and down them; steeper ones are walls it slides down. 45 by default.
     *
     * @param degrees from 0 (only flat ground) to less than 90
     * @return this character, for chaining, never null
     * @throws IllegalArgumentException if degrees is NaN, infinite, negative, or 90 or more;
     *                                  then nothing changes
     */
    public CharacterBody maxSlope(float degrees) {
        Check.size("degrees", degrees);
        if (degrees >= 90) {
            throw new IllegalArgumentException("degrees must be less than 90 (a wall is not ground), was " + degrees);
        }
        maxSlope = degrees;
        cosMaxSlope = StrictMath.cos(Math.toRadians(degrees));
        return this;
    }

    /** @return the steepest ground, in degrees from flat */
    public float maxSlope() {
        return maxSlope;
    }

    /**
     * Sets how high a ledge it climbs by walking into it, as stairs: 0 by default (none).
     *
     * @param px the height, 0 or more
     * @return this character, for chaining, never null
     * @throws IllegalArgumentException if px is NaN, infinite or negative; then nothing changes
     */
    public CharacterBody stepHeight(float px) {
        stepHeight = Check.size("px", px);
        return this;
    }

    /** @return how high a ledge it climbs */
    public float stepHeight() {
        return stepHeight;
    }

    /**
     * Sets how far down it keeps to the ground when walking down a slope or off a step,
     * instead of leaving it: 0 by default (none).
     *
     * @param px the distance, 0 or more
     * @return this character, for chaining, never null
     * @throws IllegalArgumentException if px is NaN, infinite or negative; then nothing changes
     */
    public CharacterBody snap(float px) {
        snap = Check.size("px", px);
        return this;
    }

    /** @return how far down it keeps to the ground */
    public float snap() {
        return snap;
    }

    /**
     * Sets which way is up: (0, -1) by default, up the screen. (0, 0) is a top-down game:
     * no ground, every surface a wall. The direction's length does not matter.
     *
     * @param x the direction's x
     * @param y the direction's y
     * @return this character, for chaining, never null
     * @throws IllegalArgumentException if x or y is NaN or infinite; then nothing changes
     */
    public CharacterBody up(float x, float y) {
        Check.finite("x", x);
        Check.finite("y", y);
        double len = Math.hypot(x, y);
        if (len == 0) {
            upX = 0;
            upY = 0;
        } else {
            upX = x / len;
            upY = y / len;
        }
        return this;
    }

    /** @return which way is up, of length 1, or (0, 0) for a top-down game; never null */
    public Vec up() {
        return new Vec((float) upX, (float) upY);
    }

    private World live(String what) {
        World w = body.world;
        if (w == null) {
            throw new IllegalStateException(what + ": this character's body was removed from its world");
        }
        return w;
    }

    @Override
    public String toString() {
        return "CharacterBody " + body + (onGround ? " on ground" : "");
    }
}
