package hitbox.internal;

import hitbox.*;

import java.util.ArrayList;
import java.util.List;

/**
 * The straight time of impact for every pair that has no exact swept test of its own
 * (polygons, ellipses, capsules, two segments), as a mover or as an obstacle, against any
 * shape: {@link Sweep#timeOfImpact(Shape, float, float, Shape)}.
 *
 * <p>Each shape is taken as convex pieces (a concave polygon as its triangulation's pieces, a
 * segment as its two ends, a curved shape as itself, read through its support function, see
 * {@link Supports}). For each pair of pieces, conservative advancement along a separating
 * direction (G. van den Bergen, "Ray Casting against General Convex Objects", 2004, the
 * advancement without the simplex; Ericson, <i>Real-Time Collision Detection</i>, 9.5.3):
 * at time t the best separating direction n found (sampled and refined, as in
 * {@link TurningSweep}) leaves a gap g along n that is a lower bound on the distance, and the
 * gap along a fixed n closes at exactly {@code v . n}, so the mover can advance by
 * {@code g / (v . n)} and still not overlap; if {@code v . n <= 0} the gap never closes and
 * the pair never meets. The advancement stops within {@link #TOUCH} of contact: an entry
 * time in double that is never later than the real one.
 *
 * <p>Coming within TOUCH is not yet a hit: a path that starts touching and moves away, or
 * slides along a face, or passes a hair from the obstacle, comes that close and never
 * overlaps, while rounding of its float positions can still put one a hair inside. Whether
 * the pair meets at all is the exact path's decision (Sweep's class doc), made here by a line
 * ({@code passes}): if one keeps the obstacle's piece on one side and the mover's piece, at
 * every time from the entry to the end, on the other, the insides never overlap and the pair
 * is no hit; only a path that enters deeper than {@link Tolerance#SWEEP_PASSES} of the
 * shapes' size (the rounding of the search in double) goes on to the float positions. (Where
 * touching is meeting, between two shapes without area or for one without area against the
 * pieces of a concave polygon, the line must leave a gap of that size instead.)
 *
 * <p>Two convex polygons, a rectangle moving into a convex polygon and a circle moving into
 * any polygon go the exact way instead, {@link ConvexPolygonSweep}.
 *
 * <p>This class is longer than most (about 710 lines) because the advancement, the line that
 * decides whether a pair meets at all and the look-back over the float positions all read
 * the same pieces through the same separating-direction search; apart, each would carry a
 * copy of it. The thread's scratch they work in ({@code Work}: the pieces, the directions,
 * the searched functions) is here too, so that a search makes nothing. A box's and a
 * circle's sweeps given as numbers ({@link #rectTimeOfImpact}, {@link #circleTimeOfImpact}:
 * a world's walk keeps them so) take the same first steps here.
 *
 * <p>From each pair's entry, {@link SweptPairs#lastClear} finds the promised float t on the
 * real shapes, moved as a sketch moves them ({@code x + t * vx} in float) and tested by
 * {@link Overlaps}: the largest float at which the mover does not overlap while at the next
 * float up it does. Every answer it finds is such a boundary, so the least over the pairs is
 * the first one. Like every sweep here, a graze shorter than the float positions' rounding
 * (no float position overlaps) is not a hit.
 */
public final class ConvexSweep {
    private ConvexSweep() {
    }

    /** Closer than this (pixels) ends the advancement: the entry is within a float step or two. */
    public static final double TOUCH = 1e-6;
    private static final int MAX_STEPS = 500;
    private static final int DIRECTIONS = 32;
    /** The golden-section steps of the advancement's direction search (each safe, so few). */
    private static final int STEPS = 50;
    /**
     * The steps of {@link #passes}' search, to the width {@link Tolerance#SWEEP_ANGLE}: where
     * a path slides along a curved face the best direction is a kink, and the clearance it
     * gives falls off as the motion times the angle missed.
     */
    private static final int PASS_STEPS = 90;

    /**
     * The ring of directions {@link #separation} starts from, worked out once as it worked
     * them out at every call ({@code StrictMath}'s bits, the same every time): 64 cosines and
     * sines a call were most of a curved piece's sweep.
     */
    private static final double[] RING_X = new double[DIRECTIONS], RING_Y = new double[DIRECTIONS];

    static {
        for (int i = 0; i < DIRECTIONS; i++) {
            RING_X[i] = StrictMath.cos(2 * Math.PI * i / DIRECTIONS);
            RING_Y[i] = StrictMath.sin(2 * Math.PI * i / DIRECTIONS);
        }
    }

    /**
     * What a sweep by pieces works in, a thread's own, so that its searches make nothing: the
     * directions the advancement and its look-back find, an edge to take normals from, the
     * golden search's answer, the gap it searches over and the float overlap test, each set
     * for the call. No method here calls another that is using the same array.
     */
    private static final class Work {
        final double[] piecesNormal = new double[2], entryNormal = new double[2], lookNormal = new double[2];
        final double[] edge = new double[4], golden = new double[2];
        /** The gap along the angle t, negated, for the golden search: {@link #gap} with cos t and sin t. */
        final GapAlong gapAlong = new GapAlong();
        /** Does the mover overlap the obstacle at time t ({@link #movedOverlaps})? */
        final MovedOverlap movedOverlap = new MovedOverlap();
        /** The mover's pieces and the obstacle's. */
        final PieceSlot moverPieces = new PieceSlot(), obstaclePieces = new PieceSlot();
        /** The sweep's side as an edge from (0, 0) to (ex, ey). */
        private final double[] sideEdge = new double[4];
        /** A shape's coordinates that a move moves: one point's, or two ({@link #coordinates}). */
        private final float[] two = new float[2], four = new float[4];

        double[] side(double ex, double ey) {
            sideEdge[2] = ex;
            sideEdge[3] = ey;
            return sideEdge;
        }

        float[] two(float x, float y) {
            two[0] = x;
            two[1] = y;
            return two;
        }

        float[] four(float x1, float y1, float x2, float y2) {
            four[0] = x1;
            four[1] = y1;
            four[2] = x2;
            four[3] = y2;
            return four;
        }
    }

    private static final ThreadLocal<Work> WORK = ThreadLocal.withInitial(Work::new);

    /**
     * One side's pieces of a sweep by pieces, in storage kept from call to call: a curved
     * shape, a rectangle's corners or a segment's ends written into this slot's own round,
     * corners or ends; a polygon's corners, or a concave one's pieces, its own (only read).
     */
    private static final class PieceSlot {
        private final ArrayList<Object> list = new ArrayList<>();
        private final Round round = new Round();
        private final double[] corners = new double[8], ends = new double[4];

        /** The shape's pieces, as {@link #pieces} says, in this slot: valid until it is asked again. */
        List<Object> of(Shape s) {
            list.clear();
            switch (ShapeKind.of(s)) {
                case ELLIPSE, CAPSULE, CIRCLE -> list.add(round.set(s));
                case RECT -> list.add(Polygons.corners((Rect) s, corners));
                case SEGMENT -> {
                    Segment g = (Segment) s;
                    ends[0] = g.x1();
                    ends[1] = g.y1();
                    ends[2] = g.x2();
                    ends[3] = g.y2();
                    list.add(ends);
                }
                case POLYGON -> {
                    Polygon p = (Polygon) s;
                    if (p.isConvex()) {
                        list.add(HiddenParts.corners(p));  // the polygon's own, only read
                    } else {
                        List<double[]> parts = Clearance.Parts.of(p).pieces();
                        for (int i = 0, n = parts.size(); i < n; i++) {
                            list.add(parts.get(i));
                        }
                    }
                }
            }
            return list;
        }
    }

    /** The golden search's function over the angle, set for each search. */
    private static final class GapAlong implements java.util.function.DoubleUnaryOperator {
        Object a, b;
        double dx, dy, ex, ey;

        @Override
        public double applyAsDouble(double t) {
            return -gap(a, b, dx, dy, ex, ey, StrictMath.cos(t), StrictMath.sin(t));
        }
    }

    /** The float overlap test of a sweep, set for each sweep. */
    private static final class MovedOverlap implements SweptPairs.OverlapAt {
        Shape mover, obstacle;
        float vx, vy;

        @Override
        public boolean at(float t) {
            return movedOverlaps(mover, t * vx, t * vy, obstacle);
        }
    }

    /**
     * {@link #timeOfImpact} for a box mover (x, y, w, h) given as numbers, its {@code Rect}
     * given if made (else null): against a convex polygon the same steps on the numbers, no
     * {@code Rect} made; any other pair by the shape, made if need be.
     */
    public static Hit rectTimeOfImpact(Rect made, float x, float y, float w, float h, float vx, float vy, Shape obstacle) {
        if (w > 0 && h > 0 && ShapeKind.of(obstacle) == ShapeKind.POLYGON && HiddenParts.convexWinding((Polygon) obstacle) != 0) {
            if (apart(x, y, (double) x + w, (double) y + h, vx, vy, obstacle)) {
                return null;
            }
            if (Overlaps.rectWith(x, y, w, h, obstacle)) {
                return SweptPairs.OVERLAPPING;
            }
            if (vx == 0 && vy == 0) {
                return null;
            }
            return ConvexPolygonSweep.rectTimeOfImpact(made, x, y, w, h, vx, vy, (Polygon) obstacle);
        }
        return timeOfImpact(made != null ? made : new Rect(x, y, w, h), vx, vy, obstacle);
    }

    /**
     * {@link #timeOfImpact} for a circle mover at (x, y) of radius r given as numbers, its
     * {@code Circle} given if made (else null): against a polygon the same steps on the
     * numbers, no {@code Circle} made; any other pair by the shape, made if need be.
     */
    public static Hit circleTimeOfImpact(Circle made, float x, float y, float r, float vx, float vy, Shape obstacle) {
        if (r > 0 && ShapeKind.of(obstacle) == ShapeKind.POLYGON) {
            if (apart((double) x - r, (double) y - r, (double) x + r, (double) y + r, vx, vy, obstacle)) {
                return null;
            }
            if (Overlaps.circleWith(x, y, r, obstacle)) {
                return SweptPairs.OVERLAPPING;
            }
            if (vx == 0 && vy == 0) {
                return null;
            }
            return ConvexPolygonSweep.circleTimeOfImpact(made, x, y, r, vx, vy, (Polygon) obstacle);
        }
        return timeOfImpact(made != null ? made : new Circle(x, y, r), vx, vy, obstacle);
    }

    /** The hit of a mover moving by (vx, vy) into the obstacle (both valid), or null. */
    public static Hit timeOfImpact(Shape mover, float vx, float vy, Shape obstacle) {
        if (apart(mover, vx, vy, obstacle)) {
            return null;
        }
        if (Overlaps.test(mover, obstacle)) {
            return SweptPairs.OVERLAPPING;
        }
        if (vx == 0 && vy == 0) {
            return null;
        }
        if (ConvexPolygonSweep.rectAgainstConvex(mover, obstacle)) {
            return ConvexPolygonSweep.rectTimeOfImpact((Rect) mover, vx, vy, (Polygon) obstacle);
        }
        if (ConvexPolygonSweep.circleAgainstPolygon(mover, obstacle)) {
            return ConvexPolygonSweep.circleTimeOfImpact((Circle) mover, vx, vy, (Polygon) obstacle);
        }
        if (convexPolygon(mover) && convexPolygon(obstacle)) {
            Hit h;
            boolean recording = SweptPairs.recording(false);  // the look back reads the hit
            try {
                h = ConvexPolygonSweep.timeOfImpact((Polygon) mover, vx, vy, (Polygon) obstacle);
            } finally {
                SweptPairs.recording(recording);
            }
            if (h == null || !(h.t() > 0) || h.alreadyOverlapping()) {
                return h;
            }
            // The exact entry's walk can land past a piece of float overlap that rounding split
            // off before it (a slanted edge, each coordinate rounded on its own): look back.
            Polygon m = (Polygon) mover, o = (Polygon) obstacle;
            float[] xy = HiddenParts.raw(m);
            double gx = 0, gy = 0;
            for (int i = 0; i < xy.length; i += 2) {
                gx = Math.max(gx, SweptPairs.slack(xy[i], vx));
                gy = Math.max(gy, SweptPairs.slack(xy[i + 1], vy));
            }
            double from = ConvexPolygonSweep.entryWithin(m, vx, vy, o, gx + TOUCH, gy + TOUCH);
            float f = from < h.t() ? ConvexPolygonSweep.firstOverlap(m, vx, vy, o, from, Math.nextDown(h.t()), h.nx(), h.ny())
                    : Float.POSITIVE_INFINITY;
            float t = f > 0 && f <= h.t() ? Math.nextDown(f) : h.t();
            return t == h.t() ? h : new Hit(t, h.nx(), h.ny(), h.side());
        }
        return byPieces(mover, vx, vy, obstacle);
    }

    /**
     * {@link #timeOfImpact} for any pair, apart at the start, the mover moving: by
     * conservative advancement over the convex pieces (see the class comment).
     */
    public static Hit byPieces(Shape mover, float vx, float vy, Shape obstacle) {
        Work w = WORK.get();
        MovedOverlap overlapAt = w.movedOverlap;
        overlapAt.mover = mover;
        overlapAt.obstacle = obstacle;
        overlapAt.vx = vx;
        overlapAt.vy = vy;
        try {
            return byPieces(mover, vx, vy, obstacle, overlapAt, w.piecesNormal, w.moverPieces.of(mover),
                    w.obstaclePieces.of(obstacle));
        } finally {
            overlapAt.mover = null;  // no shape kept alive by the thread's scratch
            overlapAt.obstacle = null;
        }
    }

    private static Hit byPieces(Shape mover, float vx, float vy, Shape obstacle, SweptPairs.OverlapAt overlapAt,
                                double[] normal, List<Object> movers, List<Object> obstacles) {
        float best = Float.POSITIVE_INFINITY;
        double bx = 0, by = 0;
        // A line that keeps one pair of pieces apart rules the pair out (see passes), touching
        // included where one shape has area (its inside is open). Not so between two shapes
        // without (two segments that touch collide: they are closed), nor for a shape without
        // area against the pieces of a concave polygon (it can run along the line two pieces
        // share, inside the polygon and in neither piece): there the line must leave a gap.
        boolean moverArea = ShapeKind.hasInside(mover), obstacleArea = ShapeKind.hasInside(obstacle);
        boolean open = (moverArea || obstacleArea) && (obstacles.size() == 1 || moverArea)
                && (movers.size() == 1 || obstacleArea);
        double size = size(mover, vx, vy) + size(obstacle, 0, 0);
        double clearance = (open ? -Tolerance.SWEEP_PASSES : Tolerance.SWEEP_PASSES) * size;
        for (int i = 0, na = movers.size(); i < na; i++) {  // by index: no iterator made
            Object a = movers.get(i);
            for (int j = 0, nb = obstacles.size(); j < nb; j++) {
                Object b = obstacles.get(j);
                double te = entry(a, b, vx, vy, normal);
                if (te > 1 || passes(a, b, te, vx, vy, clearance, normal)) {
                    continue;  // never within TOUCH, or within it but the path goes on clear
                }
                float t = SweptPairs.lastClear(te, overlapAt);
                if (te == 0 && t > 0 && t < 1 && withinRounding(mover, t * vx, t * vy)) {
                    // Within TOUCH of the obstacle at the start and closing in, and the last
                    // clear float moves the mover by less than the rounding of its coordinates:
                    // it touched at the start (to within that rounding) and moves in, which Hit
                    // answers with t = 0, not with the hair at which its float position has
                    // barely moved. (This entry is only a bound, so it cannot say it exactly.)
                    t = 0;
                }
                if (t > 0 && t <= 1) {
                    t = notWalkedOver(mover, a, b, vx, vy, t, overlapAt);
                }
                if (t < best && (t < 1 || overlapAt.at(1))) {
                    best = t;
                    bx = normal[0];
                    by = normal[1];
                }
            }
        }
        return best <= 1 ? SweptPairs.hit(best, bx, by) : null;
    }

    /**
     * Does piece a, moving on from time te (where the advancement came within {@link #TOUCH}
     * of piece b) to the end of the motion, stay clear of b: is there a line with b on one
     * side and every position of a from te to 1 on the other, so that the insides never
     * overlap? That is the exact path's decision (Sweep's class doc): a path that only comes
     * near (a graze), or that starts touching and moves away (against the contact normal, or
     * along a face), is no hit, however rounding moves the float positions. The line is the
     * best separating direction of the obstacle and the mover's swept hull (a at te and at
     * 1 and everything between, whose reach along n is a's plus the larger of the two moves
     * along n), searched as the advancement searches, with the sweep's own sides among the
     * candidates; clear if the gap along it is at least {@code clearance}: minus
     * {@link Tolerance#SWEEP_PASSES} of the shapes' size (the rounding of the doubles the
     * reaches are summed in) where touching is not meeting, plus as much where it is. Any
     * direction gives a lower bound on the true separation, so a path that really enters the
     * obstacle deeper than that is never passed: no tunnelling. {@code normal} is left as it
     * was (the search's direction goes through it, so that no array is made).
     */
    private static boolean passes(Object a, Object b, double te, float vx, float vy, double clearance, double[] normal) {
        double nx = normal[0], ny = normal[1];
        double rest = 1 - te;
        double clear = separation(a, b, te * vx, te * vy, rest * vx, rest * vy, normal, PASS_STEPS);
        normal[0] = nx;
        normal[1] = ny;
        return clear >= clearance;
    }

    /** The shape's largest coordinate (by size) plus the motion's: the scale of its reaches' rounding. */
    private static double size(Shape s, float vx, float vy) {
        return Extents.reach(s)
                + Math.abs(vx) + Math.abs(vy);
    }

    /**
     * The walk's answer t, or an earlier one if rounding of the float positions made one
     * overlap before it: far from the origin the float overlap can start before the exact
     * one, or be split in pieces, and the walk from the entry may land in a later piece.
     * The float positions are visited one by one from the time the pieces come within the
     * rounding slack of the mover's coordinates (before it none can overlap) up to t; the
     * first overlapping one gives the float just below it. The slack is the tight one
     * ({@link SweptPairs#slack}) for straight pieces, whose overlap tests are exact, and the
     * generous one ({@link SweptPairs#searchedSlack}) where a piece is round. (Past
     * {@link SweptPairs#MAX_POSITIONS} positions, a graze near the origin or a walk started
     * far back, t stands.)
     */
    private static float notWalkedOver(Shape mover, Object a, Object b, float vx, float vy, float t,
                                       SweptPairs.OverlapAt overlapAt) {
        Work w = WORK.get();
        float[] xy = coordinates(mover, w);
        boolean round = a instanceof Round || b instanceof Round;
        double g = 0;
        for (int i = 0; i < xy.length; i += 2) {
            g = Math.max(g, round ? SweptPairs.searchedSlack(xy[i], vx) + SweptPairs.searchedSlack(xy[i + 1], vy)
                    : SweptPairs.slack(xy[i], vx) + SweptPairs.slack(xy[i + 1], vy));
        }
        return lookBack(entryWithin(a, b, vx, vy, w.lookNormal, g + TOUCH), t, xy, vx, vy, overlapAt);
    }

    /**
     * {@link #notWalkedOver} once the time {@code from} is known before which no float position
     * can overlap: the walk over the float positions from there up to t.
     */
    private static float lookBack(double from, float t, float[] xy, float vx, float vy, SweptPairs.OverlapAt overlapAt) {
        if (!(from < t)) {
            return t;
        }
        float f = SweptPairs.firstOverlap(from, Math.nextDown(t), overlapAt, xy, vx, vy);
        return f > 0 && f <= t ? Math.nextDown(f) : t;
    }

    /**
     * The coordinates that {@link Shape#translated} moves, in x, y pairs: a polygon's own
     * array (only read), else the thread's {@code two} or {@code four}, written.
     */
    private static float[] coordinates(Shape s, Work w) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> w.two(((Ellipse) s).x(), ((Ellipse) s).y());
            case CIRCLE -> w.two(((Circle) s).x(), ((Circle) s).y());
            case RECT -> w.two(((Rect) s).x(), ((Rect) s).y());
            case CAPSULE -> w.four(((Capsule) s).x1(), ((Capsule) s).y1(), ((Capsule) s).x2(), ((Capsule) s).y2());
            case SEGMENT -> w.four(((Segment) s).x1(), ((Segment) s).y1(), ((Segment) s).x2(), ((Segment) s).y2());
            case POLYGON -> HiddenParts.raw((Polygon) s);
        };
    }

    /** Is a move by (dx, dy) no longer than a float step of the shape's largest coordinate? */
    private static boolean withinRounding(Shape s, float dx, float dy) {
        float m = (float) Extents.reach(s);
        return Math.max(Math.abs(dx), Math.abs(dy)) <= Math.ulp(m);
    }

    /**
     * Does the mover, moved by (dx, dy) as {@link Shape#translated} moves it, overlap the
     * obstacle? No, if the move leaves the float range (nothing is there).
     */
    public static boolean movedOverlaps(Shape mover, float dx, float dy, Shape obstacle) {
        if (ShapeKind.of(mover) == ShapeKind.RECT) {
            // Rect.translated's sums and its refusal, without a Rect made for every step of
            // the search (a box sliding along a turned wall asks this dozens of times a move).
            // A sum with a finite corner is finite only if the move is, so two checks do.
            Rect r = (Rect) mover;
            float x = r.x() + dx, y = r.y() + dy;
            return Float.isFinite(x) && Float.isFinite(y) && Overlaps.rectWith(x, y, r.w(), r.h(), obstacle);
        }
        Shape moved;
        try {
            moved = mover.translated(dx, dy);
        } catch (IllegalArgumentException beyondTheFloats) {
            return false;
        }
        return Overlaps.test(moved, obstacle);
    }

    // ---------------------------------------------------------------- any pair, by convex pieces

    /**
     * The cheap answer first: is the box the mover's box sweeps through clear of the
     * obstacle's box by more than the rounding of the float positions (a moved coordinate
     * {@code x + t * vx} in float lies between x and the float nearest {@code x + vx})?
     */
    public static boolean apart(Shape m, float vx, float vy, Shape o) {
        // The shapes' extents in double (Extents), not their bounds: a circle's bounds would be
        // a new Rect on every sweep.
        return apart(Extents.minX(m), Extents.minY(m), Extents.maxX(m), Extents.maxY(m), vx, vy, o);
    }

    /** {@link #apart(Shape, float, float, Shape)} for a mover of extents (mx, my) to (mr, mb). */
    private static boolean apart(double mx, double my, double mr, double mb, float vx, float vy, Shape o) {
        double ox = Extents.minX(o), oy = Extents.minY(o), or = Extents.maxX(o), ob = Extents.maxY(o);
        double left = Math.min(mx, mx + vx), top = Math.min(my, my + vy);
        double right = Math.max(mr, mr + vx), bottom = Math.max(mb, mb + vy);
        double slack = Tolerance.SWEEP_BOX_SLACK * (Math.abs(left) + Math.abs(right) + Math.abs(top) + Math.abs(bottom)
                + Math.abs(ox) + Math.abs(oy) + Math.abs(or) + Math.abs(ob)) + Float.MIN_NORMAL;
        return left > or + slack || right < ox - slack || top > ob + slack || bottom < oy - slack;
    }

    /** Is the shape a convex polygon? */
    private static boolean convexPolygon(Shape s) {
        return ShapeKind.of(s) == ShapeKind.POLYGON && ((Polygon) s).isConvex();
    }

    /**
     * The shape's convex pieces: vertex lists (double[]: a rectangle's or convex polygon's
     * corners, a segment's two ends, a concave polygon's convex pieces), or the curved shape
     * itself as a {@link Round}; only read (a polygon's corners are its own).
     */
    public static List<Object> pieces(Shape s) {
        return new PieceSlot().of(s);  // a slot of its own: the caller keeps the pieces
    }

    /**
     * A curved piece with what its support function needs worked out once: a turned
     * ellipse's cos and sin (the hot loop asks for thousands of directions), a circle as an
     * ellipse with equal radii, a capsule as its segment and radius.
     */
    public static final class Round {
        /**
         * Its centre (a capsule's first end), a capsule's second end, the radii (a, b) and the
         * turn's cosine and sine; read only (set when made, or when a sweep's own piece is
         * set again for the next sweep).
         */
        public double x, y, a, b, c, s, x2, y2;
        /** Is it a capsule (its segment and radius a), else an ellipse (a circle's radii equal)? */
        public boolean capsule;

        private Round() {
        }

        /** This piece made the curved shape's (a slot's own piece, set for each sweep). */
        private Round set(Shape shape) {
            switch (ShapeKind.of(shape)) {
                case ELLIPSE -> {
                    Ellipse e = (Ellipse) shape;
                    double c = e.angle() == 0 ? 1 : StrictMath.cos(e.angle()), s = e.angle() == 0 ? 0 : StrictMath.sin(e.angle());
                    return set(false, e.x(), e.y(), 0, 0, e.rx(), e.ry(), c, s);
                }
                case CAPSULE -> {
                    Capsule k = (Capsule) shape;
                    return set(true, k.x1(), k.y1(), k.x2(), k.y2(), k.r(), k.r(), 1, 0);
                }
                case CIRCLE -> {
                    Circle o = (Circle) shape;
                    return set(false, o.x(), o.y(), 0, 0, o.r(), o.r(), 1, 0);
                }
                default -> throw new IllegalArgumentException("not a curved shape: " + shape);
            }
        }

        private Round set(boolean capsule, double x, double y, double x2, double y2, double a, double b, double c, double s) {
            this.capsule = capsule;
            this.x = x;
            this.y = y;
            this.x2 = x2;
            this.y2 = y2;
            this.a = a;
            this.b = b;
            this.c = c;
            this.s = s;
            return this;
        }

        /** How far it reaches along (nx, ny), as {@link Supports#support}. */
        public double reach(double nx, double ny) {
            if (capsule) {
                return Math.max(x * nx + y * ny, x2 * nx + y2 * ny) + a;
            }
            return x * nx + y * ny + Math.hypot(a * (nx * c + ny * s), b * (-nx * s + ny * c));
        }
    }

    /**
     * When piece a, moving by (vx, vy), comes within {@link #TOUCH} of piece b (never later
     * than the real contact), with the separating direction (from a to b) into
     * {@code normal}; +infinity if never within the motion.
     */
    public static double entry(Object a, Object b, double vx, double vy, double[] normal) {
        return entry(a, b, 0, 0, vx, vy, normal);
    }

    /** As {@link #entry(Object, Object, double, double, double[])}, piece a starting moved by (sx, sy). */
    public static double entry(Object a, Object b, double sx, double sy, double vx, double vy, double[] normal) {
        return entryWithin(a, b, sx, sy, vx, vy, normal, TOUCH);
    }

    /** As {@link #entry(Object, Object, double, double, double[])}, coming within {@code within} instead. */
    public static double entryWithin(Object a, Object b, double vx, double vy, double[] normal, double within) {
        return entryWithin(a, b, 0, 0, vx, vy, normal, within);
    }

    private static double entryWithin(Object a, Object b, double sx, double sy, double vx, double vy, double[] normal,
                                      double within) {
        double t = 0;
        double[] n = WORK.get().entryNormal;
        for (int step = 0; step < MAX_STEPS; step++) {
            double gap = separation(a, b, sx + t * vx, sy + t * vy, 0, 0, n, STEPS);
            normal[0] = n[0];
            normal[1] = n[1];
            if (gap <= within) {
                return t;
            }
            double closing = vx * n[0] + vy * n[1];
            if (!(closing > 0)) {
                return Double.POSITIVE_INFINITY; // the gap along n never closes
            }
            // The separation along n closes at exactly v . n and the distance is never less,
            // so stepping to a separation of within / 2 along n keeps it above that (coming
            // within TOUCH, to the contact: the step the advancement has always taken).
            t += (within > TOUCH ? gap - within / 2 : gap) / closing;
            if (t > 1) {
                return Double.POSITIVE_INFINITY;
            }
        }
        return t;
    }

    /**
     * The best gap found between piece a moved by (dx, dy) and piece b: the largest
     * {@code least_b(n) - most_a(n)} over a ring of directions and both pieces' edge normals,
     * the best ring direction refined by golden-section search in up to {@code steps} steps.
     * A lower bound on the distance (negative when they overlap); its direction goes into
     * {@code n}. With (ex, ey) not 0, a is swept on from there by (ex, ey) (its hull from
     * the one place to the other, see {@link #gap}), and the sweep's sides are candidates too.
     */
    private static double separation(Object a, Object b, double dx, double dy, double ex, double ey, double[] n,
                                      int steps) {
        double best = Double.NEGATIVE_INFINITY, bx = 1, by = 0;
        boolean ring = true;
        for (int i = 0; i < DIRECTIONS; i++) {
            double nx = RING_X[i], ny = RING_Y[i];
            double g = gap(a, b, dx, dy, ex, ey, nx, ny);
            if (g > best) {
                best = g;
                bx = nx;
                by = ny;
            }
        }
        // The pieces' edge normals, and a swept hull's sides (the motion, as an edge): the line
        // of a path that slides along a face or past a corner.
        Work w = WORK.get();
        for (int k = 0, count = ex == 0 && ey == 0 ? 2 : 3; k < count; k++) {
            double[] xy = k == 0 ? edges(a, w.edge) : k == 1 ? edges(b, w.edge) : w.side(ex, ey);
            int m = xy.length / 2;
            for (int i = 0; i < m && m > 1; i++) {
                int j = (i + 1) % m;
                double fx = xy[2 * j] - xy[2 * i], fy = xy[2 * j + 1] - xy[2 * i + 1], len = Math.hypot(fx, fy);
                if (len > 0) {
                    for (int sign = -1; sign <= 1; sign += 2) {
                        double nx = sign * fy / len, ny = -sign * fx / len;
                        double g = gap(a, b, dx, dy, ex, ey, nx, ny);
                        if (g > best) {
                            best = g;
                            bx = nx;
                            by = ny;
                            ring = false;
                        }
                    }
                }
            }
        }
        if (ring || a instanceof Round || b instanceof Round) {
            // Golden-section search about the best direction (a curved piece's best gap is
            // seldom an edge normal): still a lower bound, since every direction's gap is one.
            double lo = Math.atan2(by, bx) - 2 * Math.PI / DIRECTIONS, hi = lo + 4 * Math.PI / DIRECTIONS;
            // The largest gap is the least of its negative.
            GapAlong f = w.gapAlong;
            f.a = a;
            f.b = b;
            f.dx = dx;
            f.dy = dy;
            f.ex = ex;
            f.ey = ey;
            double[] r = Golden.least(f, lo, hi, steps, Tolerance.SWEEP_ANGLE, w.golden);
            f.a = null;
            f.b = null;
            double m = r[0], g = -r[1];
            if (g > best) {
                best = g;
                bx = StrictMath.cos(m);
                by = StrictMath.sin(m);
            }
        }
        n[0] = bx;
        n[1] = by;
        return best;
    }

    /**
     * The piece's outline for edge normals: its vertices, a capsule's segment (written into
     * {@code four}), nothing for a round shape.
     */
    private static double[] edges(Object piece, double[] four) {
        if (piece instanceof double[] xy) {
            return xy;
        }
        if (piece instanceof Round r && r.capsule) {
            four[0] = r.x;
            four[1] = r.y;
            four[2] = r.x2;
            four[3] = r.y2;
            return four;
        }
        return NO_EDGES;
    }

    private static final double[] NO_EDGES = new double[0];

    /**
     * How far apart along unit n: b's least reach minus a's greatest, a moved by (dx, dy) and
     * swept on from there by (ex, ey) (its reach the larger of the two places'; (0, 0): a
     * in one place).
     */
    private static double gap(Object a, Object b, double dx, double dy, double ex, double ey, double nx, double ny) {
        return -reach(b, -nx, -ny) - (reach(a, nx, ny) + dx * nx + dy * ny + Math.max(0, ex * nx + ey * ny));
    }

    /** How far the piece reaches along (nx, ny). */
    private static double reach(Object piece, double nx, double ny) {
        if (piece instanceof double[] xy) {
            double best = Double.NEGATIVE_INFINITY;
            for (int i = 0; i + 1 < xy.length; i += 2) {
                best = Math.max(best, xy[i] * nx + xy[i + 1] * ny);
            }
            return best;
        }
        return ((Round) piece).reach(nx, ny);
    }
}
