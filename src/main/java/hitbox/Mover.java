package hitbox;

import hitbox.internal.*;

import java.util.ArrayList;

/**
 * The move-and-slide solver of a {@link World}: one body's move through the others, leg by
 * leg, each leg a swept test to the first body met and a reaction to it. {@link World#move}
 * and {@link CharacterBody#move} both walk here; the world changes only when the walk is done
 * (nothing it calls can throw after that), through {@link World#commit}.
 *
 * <h2>Planes and the skin</h2>
 * A {@link Reaction#SLIDE} adds the surface met as a plane: the rest of the move may run along
 * it or away from it, never into it. Two planes at once (a crease, a V, a corner) leave the
 * motion that keeps clear of both, which in two dimensions is along one of them or nothing:
 * the nearest motion to the wanted one that breaks no plane ({@link #clip}), as Box2D 3.1's
 * {@code b2SolvePlanes} and Quake's clip do it.
 *
 * <p>A leg that meets a slanted surface stops {@linkplain #skin a skin} short of it, measured
 * along the surface's normal. Sliding along a slanted face needs that gap: the motion along the
 * face is rounded to floats, and a position a hair inside the face (the touching rule makes
 * that a hit) would stop the body at every step. A face whose normal is an axis needs no gap
 * (moving along it changes only the other coordinate), so the body stops touching it exactly,
 * as {@link Sweep#move} does. The gap is at most the skin, {@value #SKIN} pixels near the
 * origin (four float steps of the largest coordinate far from it).
 *
 * <h2>Nothing made but the collisions</h2>
 * A walk keeps its places (the start, each leg's meeting point and stop, the obstacles) as
 * {@link Spot}s: a box or a circle as numbers, so its legs, stops and probes make no shape;
 * every sweep answers as numbers (no {@code Hit} per candidate); the body keeps where it
 * ended as numbers, its shape made only when asked. A move of a box or a circle among any
 * bodies and grids makes nothing but the collisions it hands back
 * ({@code WorldMoveAllocationTest}); other kinds still make their shape at each stop.
 *
 * <p>This class is longer than most (about 860 lines): the walk, its obstacles, its crossings,
 * the rectangles' exact walk and the character's legs share the per-leg arrays here.
 */
final class Mover {

    /** The gap a slanted surface keeps from a body that met it, near the origin: 1/64 pixel. */
    static final float SKIN = 0x1p-6f;

    /**
     * A plane is broken when the motion runs into it by more than this part of its length:
     * the rounding of a motion projected onto a plane in {@code double}.
     */
    private static final double PLANE_TIE = 1e-12;

    /** How near an axis a surface's unit normal may be and still be taken as that axis. */
    private static final double AXIS_TIE = 1e-6;

    private final World world;
    private int stamp;

    // What the move under way knows of each other body, by id, valid where seenStamp is the
    // move's stamp: its reaction, whether the mover overlapped it at the start, crossed it
    // (reported once), or met its one-way side.
    private int[] seenStamp = new int[16];
    private Reaction[] seenReaction = new Reaction[16];
    private boolean[] seenOverlap = new boolean[16];
    private boolean[] seenCrossed = new boolean[16];
    private boolean[] seenBlocked = new boolean[16];

    // The obstacles of one leg: a body's shape, or one cell of a grid's.
    private Spot[] obSpot = Spot.grown(new Spot[0], 16);
    private Body[] obBody = new Body[16];
    private int[] obCell = new int[16];
    // Each obstacle's hit in this leg, as numbers (no Hit made per sweep): the side met, null
    // for none; its time and normal.
    private Side[] obSide = new Side[16];
    private float[] obT = new float[16];
    private float[] obNx = new float[16];
    private float[] obNy = new float[16];
    private final float[] swept = new float[3];
    private final float[] cellBox = new float[4];
    private int obCount;
    // The rectangles' walk's obstacles' boxes (x, y, w, h each).
    private float[] boxes = new float[64];

    // The planes of the move under way (normals from the mover into what it met).
    private final double[] planeX = new double[World.MAX_LEGS + 4];
    private final double[] planeY = new double[World.MAX_LEGS + 4];
    private int planeCount;

    // The rectangles' walk's stops.
    private final int[] stopIndex = new int[Sweep.MAX_SLIDES];
    private final double[] stopT = new double[Sweep.MAX_SLIDES];
    private final Side[] stopSide = new Side[Sweep.MAX_SLIDES];
    private final float[] stopX = new float[Sweep.MAX_SLIDES];
    private final float[] stopY = new float[Sweep.MAX_SLIDES];
    private int stopCount;
    /** Where the rectangles' walk left the box, and the velocity it kept (x, y, vx, vy). */
    private final float[] walked = new float[4];
    private final MoveAndSlide.Stops stops = (index, t, side, x, y) -> {
        stopIndex[stopCount] = index;
        stopT[stopCount] = t;
        stopSide[stopCount] = side;
        stopX[stopCount] = x;
        stopY[stopCount] = y;
        stopCount++;
    };

    /** The collisions of the move under way, copied out when it ends. */
    private final ArrayList<Collision> found = new ArrayList<>();

    // What the walk leaves: where it ended, and whether it finished.
    private final Spot walkEnd = new Spot();
    private boolean walkFinished;

    // The places a walk keeps (each set by copying: see Spot): where a move starts (a body's
    // move), where the leg under way starts, where it meets its obstacle, where it stops, a
    // step back, and a halving's try.
    private final Spot moveStart = new Spot(), cur = new Spot(), meet = new Spot(), at = new Spot();
    private final Spot back = new Spot(), tried = new Spot();
    // Another body, for a test of the start against it (no shape made for a box or a circle).
    private final Spot other = new Spot();

    // The latest time of the frame at which the walk under way met something.
    private double metTime;

    // A single sweep's answer (probe): the obstacle met (its hit in obT, obNx, obNy), or -1.
    private int probeIndex;

    Mover(World world) {
        this.world = world;
    }

    /**
     * The gap a slanted surface keeps from a body near a shape: the skin, or four float steps
     * of the shape's largest coordinate where that is more.
     */
    static double skin(Spot s) {
        double m = s.reach();
        return Math.max(SKIN, 4 * Math.ulp((float) Math.min(m, Float.MAX_VALUE / 8)));
    }

    // ---------------------------------------------------------------- a body's move

    /**
     * A body's move: the rectangles' exact walk where it applies (read from the body's
     * numbers, no shape made), else the general walk.
     */
    Collisions move(Body m, float dx, float dy, CollisionFilter filter) {
        int st = ++stamp;
        found.clear();
        moveStart.set(m);
        if (!m.sensor && moveStart.box()) {
            float w = moveStart.w(), h = moveStart.h();
            if (rectWalk(m, moveStart.x(), moveStart.y(), w, h, dx, dy, filter, st)) {
                return world.commit(m, moveStart, walkEnd.setBox(walked[0], walked[1], w, h), found, true);
            }
        }
        walk(m, moveStart, moveStart, dx, dy, filter, st, null);
        return world.commit(m, moveStart, walkEnd, found, walkFinished);
    }

    /** Starts a character's move: a new stamp and no collisions yet. */
    int begin() {
        found.clear();
        return ++stamp;
    }

    /** Ends a character's move: the world changes. */
    Collisions end(Body m, Spot start, Spot end, boolean finished) {
        return world.commit(m, start, end, found, finished);
    }

    /** Where the last walk ended (the mover's own spot: copy it to keep it). */
    Spot walkEnd() {
        return walkEnd;
    }

    /** Did the last walk finish (false: it ran out of legs with motion left)? */
    boolean walkFinished() {
        return walkFinished;
    }

    /**
     * Walks a body from {@code from} by (dx, dy), leg by leg; leaves the end in
     * {@link #walkEnd()}. The character, if any, decides how a slide redirects the motion.
     */
    void walk(Body m, Spot start, Spot from, double dx, double dy, CollisionFilter filter, int st, CharacterBody ch) {
        cur.set(from);
        double vx = dx, vy = dy, time = 0;
        // What the move wants, for the rest of the frame: slides clip it against every plane
        // met (not the last leg's motion, which a crease would turn back up the other face).
        double wantX = dx, wantY = dy;
        metTime = 0;
        planeCount = 0;
        boolean finished = true;
        int leg = 0;
        while (true) {
            float fvx = (float) vx, fvy = (float) vy;
            if (fvx == 0 && fvy == 0) {
                break;
            }
            if (leg++ == World.MAX_LEGS) {
                finished = false;
                break;
            }
            int best = nearest(m, cur, fvx, fvy, filter, from, st, true);
            crossings(m, start, cur, fvx, fvy, best >= 0 ? obT[best] : 1, time);
            if (best < 0) {
                clearAlong(cur, fvx, fvy, 1, fvx, fvy, at);
                cur.set(at);
                vx = 0;
                vy = 0;
                break;
            }
            Body o = obBody[best];
            Reaction reaction = seenReaction[o.id];
            // The normal in double, of length 1 there too (a float normal is only near it).
            double len = Math.hypot(obNx[best], obNy[best]);
            double nx = obNx[best] / len, ny = obNy[best] / len;
            // The collision is where and when they met; a slide or a bounce off a slanted
            // surface goes on from a skin short of it.
            float t = obT[best];
            boolean metMoved = clearAlong(cur, fvx, fvy, t, t * fvx, t * fvy, meet);
            if (o.oneWay != Side.NONE) {
                seenBlocked[o.id] = true;
            }
            // Times never run back, though a stop a skin short of a hit starts the next leg a
            // little before the hit's own time.
            report(m, start, meet, reaction, timeMet(time + t * (1 - time)), best, metMoved);
            double tStop = t;
            at.set(meet);
            boolean moved = metMoved;
            if (reaction != Reaction.TOUCH && slanted(nx, ny)) {
                tStop = stopAt(cur, fvx, fvy, t, nx, ny);
                if (tStop != t) {
                    moved = clearAlong(cur, fvx, fvy, tStop, (float) (tStop * fvx), (float) (tStop * fvy), at);
                }
                moved |= keepSkin(at, fvx, fvy, t, tStop, nx, ny);
            }
            double frame = time + tStop * (1 - time);
            cur.set(at);
            double rx = (1 - tStop) * vx, ry = (1 - tStop) * vy;
            double into = rx * nx + ry * ny;
            double restX = (1 - frame) * wantX, restY = (1 - frame) * wantY;
            switch (reaction) {
                case TOUCH -> {
                    rx = 0;
                    ry = 0;
                }
                case BOUNCE -> {
                    if (into > 0) {
                        rx -= 2 * into * nx;
                        ry -= 2 * into * ny;
                        double w = wantX * nx + wantY * ny;
                        wantX -= 2 * w * nx;
                        wantY -= 2 * w * ny;
                    }
                    planeCount = 0;  // a bounce starts a new motion: the planes before it are behind
                }
                default -> {
                    addPlane(nx, ny);
                    if (ch != null) {
                        ch.slid(nx, ny);
                    }
                    double[] r = ch != null ? ch.redirect(this, restX, restY, nx, ny) : clip(restX, restY);
                    rx = r[0];
                    ry = r[1];
                }
            }
            if (!moved && rx == vx && ry == vy) {
                // Nothing changed: rounding holds the body against this surface. Step back from
                // it by the skin (the surface's normal, out), if that is clear, and go on.
                double k = skin(cur);
                back.set(cur).translate((float) (-nx * k), (float) (-ny * k));
                if (!clear(back)) {
                    finished = false;
                    break;
                }
                cur.set(back);
            }
            vx = rx;
            vy = ry;
            time = frame;
        }
        walkEnd.set(cur);
        walkFinished = finished;
    }

    /**
     * Is a normal slanted? One within {@link #AXIS_TIE} of an axis is taken as the axis: moving
     * along such a face changes the other coordinate by less than rounding does.
     */
    private static boolean slanted(double nx, double ny) {
        return Math.abs(nx) > AXIS_TIE && Math.abs(ny) > AXIS_TIE;
    }

    /** Where a leg stops before a slanted surface it meets at t: a skin back along the motion, as far as the leg's start. */
    private static double stopAt(Spot cur, float fvx, float fvy, double t, double nx, double ny) {
        double into = fvx * nx + fvy * ny;
        return into > 0 && t > 0 ? Math.max(0, t - skin(cur) / into) : t;
    }

    /**
     * A stop nearer a slanted surface than half the skin (the leg started nearer than that)
     * steps back out along the surface's normal to the skin, where that is clear: otherwise the
     * float positions of the slide along it would round into it.
     */
    private boolean keepSkin(Spot at, float fvx, float fvy, double t, double tStop, double nx, double ny) {
        double gap = (t - tStop) * (fvx * nx + fvy * ny), k = skin(at);
        if (!(gap < k / 2)) {
            return false;  // half a skin or more is gap enough; stepping by less would only jitter
        }
        back.set(at).translate((float) (-nx * (k - Math.max(0, gap))), (float) (-ny * (k - Math.max(0, gap))));
        if (!clear(back)) {
            return false;
        }
        at.set(back);
        return true;
    }

    /** The time of the frame at which the walk met something: never before the last one met, never past 1. */
    private float timeMet(double frame) {
        metTime = Math.max(metTime, Math.min(1, frame));
        return (float) metTime;
    }

    /**
     * Adds a collision with obstacle i, met at the frame's time {@code when}, unless it repeats
     * the last one of this move without having moved.
     */
    private void report(Body m, Spot start, Spot at, Reaction reaction, float when, int i, boolean moved) {
        Body o = obBody[i];
        int cell = obCell[i];
        if (!moved && !found.isEmpty()) {
            Collision last = found.get(found.size() - 1);
            if (last.other() == o && last.cell() == cell && last.nx() == obNx[i] && last.ny() == obNy[i]
                    && last.reaction() == reaction) {
                return;  // before its Hit is made: a dropped repeat makes nothing
            }
        }
        found.add(new Collision(m, o, reaction, new Hit(when, obNx[i], obNy[i], obSide[i]), poseX(m, start, at), poseY(m, start, at), cell));
    }

    // ---------------------------------------------------------------- planes

    /** Forgets the plane added last. */
    void removeLastPlane() {
        planeCount--;
    }

    /** Adds a plane (a normal from the mover into a surface it met). */
    void addPlane(double nx, double ny) {
        for (int i = 0; i < planeCount; i++) {
            if (planeX[i] == nx && planeY[i] == ny) {
                return;
            }
        }
        if (planeCount == planeX.length) {
            // The oldest plane goes: the body has slid on since.
            System.arraycopy(planeX, 1, planeX, 0, planeCount - 1);
            System.arraycopy(planeY, 1, planeY, 0, planeCount - 1);
            planeCount--;
        }
        planeX[planeCount] = nx;
        planeY[planeCount] = ny;
        planeCount++;
    }

    private final double[] clipped = new double[2];

    /**
     * The motion nearest to (rx, ry) that runs into none of the planes: itself if it breaks
     * none, else its projection onto the one plane that keeps clear of the others (the nearest
     * such), else nothing. A plane whose normal is an axis takes its part exactly.
     */
    double[] clip(double rx, double ry) {
        if (keepsClear(rx, ry)) {
            return answer(rx, ry);
        }
        double bx = 0, by = 0, bestD = Double.POSITIVE_INFINITY;
        for (int i = 0; i < planeCount; i++) {
            double nx = planeX[i], ny = planeY[i];
            double d = rx * nx + ry * ny;
            if (d <= 0) {
                continue;
            }
            double px = rx - d * nx, py = ry - d * ny;
            if (nx == 0) {
                px = rx;
                py = 0;
            } else if (ny == 0) {
                px = 0;
                py = ry;
            }
            double dd = d * d;
            if (dd < bestD && keepsClear(px, py)) {
                bestD = dd;
                bx = px;
                by = py;
            }
        }
        return answer(bx, by);
    }

    private double[] answer(double x, double y) {
        clipped[0] = x;
        clipped[1] = y;
        return clipped;
    }

    /** Does a motion run into none of the planes (beyond rounding)? */
    boolean keepsClear(double rx, double ry) {
        double len = Math.abs(rx) + Math.abs(ry);
        for (int i = 0; i < planeCount; i++) {
            if (rx * planeX[i] + ry * planeY[i] > PLANE_TIE * len) {
                return false;
            }
        }
        return true;
    }

    // ---------------------------------------------------------------- legs

    /**
     * The first blocking obstacle a shape meets moving by (fvx, fvy), as {@link #walk} sees it:
     * its index (then {@link #hitOf}) or -1. With {@code all}, every obstacle's hit is kept
     * for the crossings too.
     */
    private int nearest(Body m, Spot cur, float fvx, float fvy, CollisionFilter filter, Spot start, int st, boolean all) {
        obstacles(m, cur, fvx, fvy, filter, start, st);
        int best = -1;
        for (int i = 0; i < obCount; i++) {
            Body o = obBody[i];
            if (!all && seenReaction[o.id] == Reaction.CROSS) {
                obSide[i] = null;
                continue;
            }
            Side side = cur.sweep(fvx, fvy, obSpot[i], swept);
            if (side != null && (side == Side.NONE
                    || seenReaction[o.id] != Reaction.CROSS && o.oneWay != Side.NONE && side != o.oneWay)) {
                side = null;  // overlapping at the start, or a one-way body met from a side that does not block
            }
            obSide[i] = side;
            if (side == null) {
                continue;
            }
            float t = swept[0];
            obT[i] = t;
            obNx[i] = swept[1];
            obNy[i] = swept[2];
            if (seenReaction[o.id] != Reaction.CROSS
                    && (best < 0 || t < obT[best] || t == obT[best] && o.serial < obBody[best].serial)) {
                best = i;
            }
        }
        return best;
    }

    /**
     * A character's single leg that reports nothing: the first blocking obstacle met moving
     * by (vx, vy); then {@link #probeNx()}, {@link #probeNy()}, {@link #probeBody()} and
     * {@link #probeStop}.
     *
     * @return true if one is met within the motion
     */
    boolean probe(Body m, Spot cur, float vx, float vy, CollisionFilter filter, Spot start, int st) {
        if (vx == 0 && vy == 0) {
            probeIndex = -1;
            return false;
        }
        probeIndex = nearest(m, cur, vx, vy, filter, start, st, false);
        return probeIndex >= 0;
    }

    /** The normal of the surface the last probe met (from the mover into it), x part. */
    float probeNx() {
        return obNx[probeIndex];
    }

    /** The normal of the surface the last probe met, y part. */
    float probeNy() {
        return obNy[probeIndex];
    }

    Body probeBody() {
        return obBody[probeIndex];
    }

    /**
     * Where the last probe from {@code cur} stops (touching, or a skin short of a slanted
     * surface), or its end if it met nothing: into {@code out}, another spot than cur.
     */
    void probeStop(Spot cur, float vx, float vy, Spot out) {
        if (probeIndex < 0) {
            clearAlong(cur, vx, vy, 1, vx, vy, out);
            return;
        }
        float nx0 = obNx[probeIndex], ny0 = obNy[probeIndex], t0 = obT[probeIndex];
        double len = Math.hypot(nx0, ny0);
        double nx = nx0 / len, ny = ny0 / len;
        double t = slanted(nx, ny) ? stopAt(cur, vx, vy, t0, nx, ny) : t0;
        clearAlong(cur, vx, vy, t, (float) (t * vx), (float) (t * vy), out);
    }

    /** The crossed bodies met before tb in this leg, each reported once a move, in the order met. */
    private void crossings(Body m, Spot start, Spot cur, float fvx, float fvy, float tb, double time) {
        while (true) {
            int first = -1;
            for (int i = 0; i < obCount; i++) {
                Body o = obBody[i];
                if (obSide[i] != null && seenReaction[o.id] == Reaction.CROSS && !seenCrossed[o.id] && obT[i] <= tb
                        && (first < 0 || obT[i] < obT[first])) {
                    first = i;
                }
            }
            if (first < 0) {
                return;
            }
            Body o = obBody[first];
            seenCrossed[o.id] = true;
            float t = obT[first];
            found.add(new Collision(m, o, Reaction.CROSS, new Hit(timeMet(time + t * (1 - time)), obNx[first], obNy[first], obSide[first]),
                    poseX(m, start, cur) + t * fvx, poseY(m, start, cur) + t * fvy, obCell[first]));
        }
    }

    /**
     * Where a leg from cur stops at t along (fvx, fvy), moved there by (dx, dy): that stop if
     * it overlaps no blocking obstacle of this leg; otherwise (only rounding can cause it) the
     * farthest clear point before it along the leg, by halving; else cur itself. Into
     * {@code out}, another spot than cur.
     *
     * @return true if out is not cur itself (t above 0, and a clear point found)
     */
    private boolean clearAlong(Spot cur, float fvx, float fvy, double t, float dx, float dy, Spot out) {
        out.set(cur);
        if (t == 0) {
            return false;
        }
        out.translate(dx, dy);
        if (clear(out)) {
            return true;
        }
        out.set(cur);
        boolean found = false;
        double lo = 0, hi = t;
        for (int i = 0; i < 64 && lo < hi; i++) {
            double mid = (lo + hi) / 2;
            tried.set(cur).translate((float) (mid * fvx), (float) (mid * fvy));
            if (clear(tried)) {
                lo = mid;
                out.set(tried);
                found = true;
            } else {
                hi = mid;
            }
            if (mid == lo && mid == hi) {
                break;
            }
        }
        return found;
    }

    /** Does a spot overlap none of this leg's blocking obstacles? */
    boolean clear(Spot s) {
        for (int i = 0; i < obCount; i++) {
            Body o = obBody[i];
            boolean blocks = seenReaction[o.id] != Reaction.CROSS && (o.oneWay == Side.NONE || seenBlocked[o.id]);
            if (blocks && s.overlaps(obSpot[i])) {
                return false;
            }
        }
        return true;
    }

    private static float poseX(Body m, Spot start, Spot at) {
        return (float) (m.homePivotX + m.tx + (at.refX() - start.refX()));
    }

    private static float poseY(Body m, Spot start, Spot at) {
        return (float) (m.homePivotY + m.ty + (at.refY() - start.refY()));
    }

    /**
     * The obstacles of one leg: the bodies (and grid cells) whose boxes meet the leg's swept
     * box, that the filter does not ignore, that the mover did not overlap at the start, and
     * not crossed already. Bodies the mover overlaps at the start are reported once.
     */
    private void obstacles(Body m, Spot cur, float fvx, float fvy, CollisionFilter filter, Spot start, int st) {
        double left = Math.min(cur.minX(), cur.minX() + fvx), right = Math.max(cur.maxX(), cur.maxX() + fvx);
        double top = Math.min(cur.minY(), cur.minY() + fvy), bottom = Math.max(cur.maxY(), cur.maxY() + fvy);
        // A skin around the swept box: a stop may step back from a slanted surface by that much.
        double k = skin(cur);
        left -= k;
        top -= k;
        right += k;
        bottom += k;
        world.gather(left, top, right, bottom);
        obCount = 0;
        for (int i = 0, n = world.candidateCount(); i < n; i++) {
            Body o = world.candidate(i);
            if (o == m || reaction(m, o, filter, start, st) == null || seenOverlap[o.id]) {
                continue;
            }
            if (o.grid != null) {
                cells(o, left, top, right, bottom, start);
            } else {
                addObstacle(o, -1).set(o);
            }
        }
    }

    /** The solid cells of a grid's body under a box, row by row, not those the start overlaps. */
    private void cells(Body o, double left, double top, double right, double bottom, Spot start) {
        Grid g = o.grid;
        double pad = World.pad(left, top, right, bottom);
        int c0 = Math.max(0, g.colAt((float) (left - pad))), c1 = Math.min(g.cols() - 1, g.colAt((float) (right + pad)));
        int r0 = Math.max(0, g.rowAt((float) (top - pad))), r1 = Math.min(g.rows() - 1, g.rowAt((float) (bottom + pad)));
        if ((long) (c1 - c0 + 1) * (r1 - r0 + 1) > GridMove.MAX_CELLS) {
            throw new IllegalArgumentException("a move over a grid of the world sweeps more than " + GridMove.MAX_CELLS
                    + " cells: moves are made for a few cells a frame");
        }
        for (int row = r0; row <= r1; row++) {
            for (int col = c0; col <= c1; col++) {
                if (g.isSolid(col, row)) {
                    g.cellBox(col, row, cellBox);
                    Spot cell = addObstacle(o, row * g.cols() + col).setBox(cellBox[0], cellBox[1], cellBox[2], cellBox[3]);
                    if (start != null && start.overlaps(cell)) {
                        obCount--;  // the start overlaps it: not an obstacle
                    }
                }
            }
        }
    }

    /** Adds an obstacle: a body, or one cell of a grid's; its place is set by the caller. */
    private Spot addObstacle(Body o, int cell) {
        if (obCount == obSpot.length) {
            int n = 2 * obCount;
            obSpot = Spot.grown(obSpot, n);
            obBody = java.util.Arrays.copyOf(obBody, n);
            obCell = java.util.Arrays.copyOf(obCell, n);
            obSide = java.util.Arrays.copyOf(obSide, n);
            obT = java.util.Arrays.copyOf(obT, n);
            obNx = java.util.Arrays.copyOf(obNx, n);
            obNy = java.util.Arrays.copyOf(obNy, n);
        }
        obBody[obCount] = o;
        obCell[obCount] = cell;
        return obSpot[obCount++];
    }

    /**
     * The reaction to another body, asked once a move: layers, then sensors, then the filter.
     * {@code start} is where the move starts from, null for the body as it stands.
     */
    Reaction reaction(Body m, Body o, CollisionFilter filter, Spot start, int st) {
        if (o.id >= seenStamp.length) {
            int n = Math.max(2 * seenStamp.length, o.id + 1);
            seenStamp = java.util.Arrays.copyOf(seenStamp, n);
            seenReaction = java.util.Arrays.copyOf(seenReaction, n);
            seenOverlap = java.util.Arrays.copyOf(seenOverlap, n);
            seenCrossed = java.util.Arrays.copyOf(seenCrossed, n);
            seenBlocked = java.util.Arrays.copyOf(seenBlocked, n);
        }
        if (seenStamp[o.id] != st) {
            seenStamp[o.id] = st;
            seenCrossed[o.id] = false;
            seenBlocked[o.id] = false;
            seenOverlap[o.id] = false;
            Reaction r = decide(m, o, filter);
            seenReaction[o.id] = r;
            if (r != null && o.grid == null && (start == null ? world.overlap(m, o) : start.overlaps(other.set(o)))) {
                seenOverlap[o.id] = true;
                seenCrossed[o.id] = true;
                reportStartOverlap(m, o, r);
            }
        }
        return seenReaction[o.id];
    }

    /** Reports a body the mover overlapped when its move began, once a move. */
    private void reportStartOverlap(Body m, Body o, Reaction r) {
        for (int i = 0, n = found.size(); i < n; i++) {  // by index: no iterator made
            Collision c = found.get(i);
            if (c.other() == o && c.hit().alreadyOverlapping()) {
                return;
            }
        }
        found.add(new Collision(m, o, r, new Hit(0, 0, 0, Side.NONE), m.pivotX(), m.pivotY(), -1));
    }

    /** The reaction to another body: null where the layers refuse, crossing for a sensor, else the filter's. */
    private Reaction decide(Body m, Body o, CollisionFilter filter) {
        if (!m.accepts(o)) {
            return null;
        }
        if (m.sensor || o.sensor) {
            return Reaction.CROSS;
        }
        return world.ask(filter, m, o);
    }

    // ---------------------------------------------------------------- a character's start

    /**
     * Does the shape a move starts from overlap a body that would block it (not a one-way
     * body)? Asked through {@link #reaction}, so the walk that follows with the same stamp
     * reuses each answer and the filter is asked once.
     */
    boolean blockedAtStart(Body m, Spot start, CollisionFilter filter, int st) {
        world.gather(start.minX(), start.minY(), start.maxX(), start.maxY());
        for (int i = 0, n = world.candidateCount(); i < n; i++) {
            Body o = world.candidate(i);
            if (o == m) {
                continue;
            }
            Reaction r = reaction(m, o, filter, start, st);
            if (r == null || r == Reaction.CROSS || o.oneWay != Side.NONE) {
                continue;
            }
            if (o.grid == null ? seenOverlap[o.id] : gridOverlaps(o, start)) {
                return true;
            }
        }
        return false;
    }

    private boolean gridOverlaps(Body o, Spot s) {
        obCount = 0;
        cells(o, s.minX(), s.minY(), s.maxX(), s.maxY(), null);
        for (int c = 0; c < obCount; c++) {
            if (s.overlaps(obSpot[c])) {
                return true;
            }
        }
        return false;
    }

    /** A new stamp for the same move: every reaction is asked again (after a push out). */
    int restamp() {
        return ++stamp;
    }

    /**
     * A shape pushed out of the bodies it overlaps that would block it (not one-way bodies,
     * which it may stand inside while it jumps through), the deepest first, each the shortest
     * way ({@link Shape#contact}) and a skin beyond, a few times; the shape itself when it
     * overlaps none.
     */
    void pushOut(Body m, Spot start, CollisionFilter filter, Spot out) {
        out.set(start);
        for (int round = 0; round < 4; round++) {
            boolean first = round == 0;
            world.gather(out.minX(), out.minY(), out.maxX(), out.maxY());
            Contact deepest = null;
            for (int i = 0, n = world.candidateCount(); i < n; i++) {
                Body o = world.candidate(i);
                if (o == m || o.oneWay != Side.NONE) {
                    continue;
                }
                Reaction r = decide(m, o, filter);
                if (r == null) {
                    continue;
                }
                if (first && o.grid == null && out.overlaps(other.set(o))) {
                    reportStartOverlap(m, o, r);
                }
                if (r == Reaction.CROSS) {
                    continue;
                }
                // A push out is rare (a character that starts inside something): its contacts
                // are asked of the shape.
                if (o.grid != null) {
                    obCount = 0;
                    cells(o, out.minX(), out.minY(), out.maxX(), out.maxY(), null);
                    for (int c = 0; c < obCount; c++) {
                        deepest = deeper(deepest, out.shape(), obSpot[c].shape());
                    }
                } else {
                    deepest = deeper(deepest, out.shape(), o.shape());
                }
            }
            if (deepest == null) {
                return;
            }
            double k = deepest.depth() + skin(out);
            out.translate((float) (-deepest.nx() * k), (float) (-deepest.ny() * k));
        }
    }

    /**
     * The deeper of the best contact so far and the contact of {@code cur} with {@code other}.
     * A segment has no inside to be pushed out of (a segment body across the mover, or a
     * segment that moves): it is passed by, as the walk lets a start that overlaps it move off.
     */
    private static Contact deeper(Contact best, Shape cur, Shape other) {
        if (!ShapeKind.of(cur).hasArea() || !ShapeKind.of(other).hasArea()) {
            return best;
        }
        Contact c = cur.contact(other);
        return c != null && (best == null || c.depth() > best.depth()) ? c : best;
    }

    // ---------------------------------------------------------------- the rectangles' walk

    /**
     * A box's slide among boxes, by {@link Sweep#move}'s own walk, all as numbers: the box at
     * (x, y) of size w by h, the bodies as it stands; the end into {@link #walked}. False
     * when some body met is not a box that slides (then the general walk runs, the start's
     * overlaps already reported).
     */
    private boolean rectWalk(Body m, float x, float y, float w, float h, float dx, float dy, CollisionFilter filter, int st) {
        double left = Math.min(x, (double) x + dx), right = Math.max((double) x + w, (double) x + w + dx);
        double top = Math.min(y, (double) y + dy), bottom = Math.max((double) y + h, (double) y + h + dy);
        world.gather(left, top, right, bottom);
        int n = world.candidateCount();
        for (int i = 0; i < n; i++) {
            Body o = world.candidate(i);
            if (o == m) {
                continue;
            }
            Reaction re = reaction(m, o, filter, null, st);
            if (re != null && (re != Reaction.SLIDE || o.oneWay != Side.NONE || o.grid == null && !other.set(o).box())) {
                return false;
            }
        }
        obCount = 0;
        for (int i = 0; i < n; i++) {
            Body o = world.candidate(i);
            if (o == m || seenReaction[o.id] == null) {
                continue;
            }
            if (o.grid != null) {
                cells(o, left, top, right, bottom, null);
            } else {
                addObstacle(o, -1).set(o);
            }
        }
        if (boxes.length < 4 * obCount) {
            boxes = new float[Math.max(4 * obCount, 2 * boxes.length)];
        }
        for (int i = 0; i < obCount; i++) {
            Spot b = obSpot[i];  // a box: a grid's cell, or a body found a box above
            boxes[4 * i] = b.x();
            boxes[4 * i + 1] = b.y();
            boxes[4 * i + 2] = b.w();
            boxes[4 * i + 3] = b.h();
        }
        stopCount = 0;
        MoveAndSlide.walk(x, y, w, h, dx, dy, boxes, obCount, stops, walked);
        double time = 0;
        for (int k = 0; k < stopCount; k++) {
            double frame = time + stopT[k] * (1 - time);
            Side side = stopSide[k];
            float nx = side == Side.LEFT ? 1 : side == Side.RIGHT ? -1 : 0;
            float ny = side == Side.TOP ? 1 : side == Side.BOTTOM ? -1 : 0;
            int i = stopIndex[k];
            found.add(new Collision(m, obBody[i], Reaction.SLIDE, new Hit((float) Math.min(1, frame), nx, ny, side),
                    (float) (m.homePivotX + m.tx + ((double) stopX[k] - x)),
                    (float) (m.homePivotY + m.ty + ((double) stopY[k] - y)), obCell[i]));
            time = frame;
        }
        return true;
    }
}
