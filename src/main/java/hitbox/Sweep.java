package hitbox;

import hitbox.internal.*;

/**
 * Moving objects done exactly: when, during this frame's motion, does a moving shape first
 * run into an obstacle? A swept test never tunnels: a small object moving thousands of
 * pixels a frame still hits a wall one pixel thick.
 *
 * <p>The tutorial only tests positions (where an object landed, or where it would be next
 * frame), so a fast object can jump
 * over a thin wall between two frames. A swept test looks at the whole motion instead: the
 * mover starts where it is and moves by {@code (vx, vy)} this frame; the answer is the
 * <em>time of impact</em> {@code t}, the fraction of the motion done when the mover's inside
 * starts to overlap the obstacle's.
 *
 * <h2 id="t">What t promises</h2>
 * {@code t} is a {@code float} in [0, 1], and it is the <em>largest</em> float for which the
 * mover, moved the way a sketch moves it ({@code x + t * vx} and {@code y + t * vy}, in
 * {@code float}), does not overlap the obstacle ({@link Collide}'s test), while at the next
 * float up it does, and every float below it is clear too. So moving a sketch's object by
 * {@code t} never leaves it a hair inside, and it stands as close as floats allow. Where
 * rounding leaves the moved position unchanged over a range of {@code t} (a mover far from
 * the origin moving slowly), {@code t} is the end of that range. Far from the origin the
 * rounding of the moved position can start the float overlap before the exact one, shorten
 * it or split it in pieces; the pairs on plain floats (and their shape forms) visit the
 * float positions one by one from the earliest time rounding could make one overlap, so
 * {@code t} stands before the first piece (up to 4096 positions; past that, a walk from the
 * exact entry decides; two boxes need no visit, their float overlap is one interval; a
 * rectangle moving into a convex polygon and a circle moving into any polygon are of these),
 * and the searched pairs and two convex polygons look back the same way from the walk's
 * answer.
 * Whether there is a hit at all is the exact path's decision: a path
 * that misses exactly is no hit, even where rounding puts a float position a hair inside,
 * so a mover that touches the obstacle (or is a hair from it) and moves away, against the
 * contact normal or along the face, is never stopped. For the pairs found by conservative
 * advancement (ellipses, capsules, and a polygon with anything but a convex polygon, a
 * rectangle moving into a convex one or a circle moving into it) the exact
 * path is decided by a separating line: one that keeps the obstacle on one side and every
 * position of the mover along the motion on the other rules the hit out, a path entering
 * less than 2^-40 of the shapes' size deep counting as clear (the rounding of that search in
 * double; between two shapes without area, and for a shape without area against a concave
 * polygon, the line must leave a gap that large, and closer paths are left to the float
 * positions).
 * The one exception: a mover that touches the obstacle at the start and moves
 * into it gets {@code t = 0} exactly, as {@link Hit} promises, not the hair above 0 at which
 * its float position has not yet moved: for the exact pairs (circles, rectangles, segments,
 * two convex polygons, a rectangle moving into a convex polygon, a circle moving into any
 * polygon) its exact entry is 0, which decides before any float is tried; for
 * the pairs found by conservative advancement, a start within 1e-6 pixels whose path goes
 * on into the obstacle, and whose last clear float has moved the mover by no more than a
 * float step of its largest coordinate. If the float positions never overlap
 * during the motion although the exact path does (a graze thinner than a float step), the
 * hit is reported with {@code t = 1}.
 *
 * <p>The <a href="package-summary.html#touching">touching rule</a> holds throughout:
 * <ul>
 *   <li>Already overlapping at the start (exactly what {@link Collide} says): {@code t = 0},
 *       and a {@link Hit} says {@link Hit#alreadyOverlapping()}.</li>
 *   <li>Touching at the start and moving away, or sliding along the obstacle's edge (a box
 *       moving sideways with its bottom level with a platform's top): the insides never
 *       overlap, so it is no hit.</li>
 *   <li>Only reaching the obstacle at the very end of the motion (touching at 1): no hit
 *       this frame.</li>
 * </ul>
 *
 * <h2>Answers, normals and bad input</h2>
 * No hit is {@link Float#POSITIVE_INFINITY} for {@link #rectRect} and {@code null}
 * for the {@link Hit} methods, so {@code t <= 1} reads "it hits this frame". A hit's normal
 * points <em>from the mover into the obstacle</em> (landing on a floor gives (0, 1)), the
 * package's one convention, so it goes straight to {@link Response#bounce(float, float,
 * float, float, float)}. {@link #rectRect} on plain floats never throws: NaN or an infinite value in
 * any argument, or a negative size, gives "no hit". The methods on shapes check their
 * arguments as constructors do.
 *
 * <p>One call per question: {@link #timeOfImpact(Shape, float, float, Shape)} for any moving
 * shape against any standing one, returning a {@link Hit} with the normal and the
 * {@link Side} hit; {@link #move} walks a box through a list of obstacles, sliding along what
 * it hits (the walk itself lives in a class of its own); {@link #turningTimeOfImpact} for a
 * polygon that turns as it moves. One form on plain floats stays, {@link #rectRect}, because
 * the narrow-phase table (docs/narrow-phase.md) shows the shape form of that question more
 * than 10% slower. The maths is shared with
 * {@link Ray}: slabs for boxes, discs for round parts. Entry times are computed in
 * {@code double}: for whole-number coordinates and velocities every decision (hit or not,
 * which side) is exact.
 *
 * <p>This class is longer than most (about 735 lines) because it is the public face of every
 * swept pair and of the turning sweep, each with its full javadoc; the maths is in
 * package-private kernels ({@code SweptPairs}, {@code MoveAndSlide}, {@code TurningSweep}).
 *
 * <p>Reference: Christer Ericson, <i>Real-Time Collision Detection</i> (2005), 5.5
 * "Dynamic Intersection Tests" (moving sphere against sphere, moving sphere against AABB as
 * a rounded box, moving AABB against AABB).
 */
public final class Sweep {

    /** How many times {@link #move} stops at an obstacle and slides on before giving up. */
    public static final int MAX_SLIDES = 4;

    private Sweep() {
    }

    // ---------------------------------------------------------------- time only

    /**
     * When does a moving rectangle first overlap a standing one? Swept box against box, on
     * plain floats: the one form on floats this class keeps, because the narrow-phase table
     * (docs/narrow-phase.md, "swept rect vs rect") shows
     * {@link #timeOfImpact(Shape, float, float, Shape)} more than 10% slower on this question.
     *
     * <p>On each axis the boxes overlap during an open interval of time; the insides overlap
     * while both intervals do, from the later entry to the earlier exit.
     *
     * @param x  the mover's left edge at the start
     * @param y  the mover's top edge at the start
     * @param w  the mover's width
     * @param h  the mover's height
     * @param vx the mover's motion this frame, x part
     * @param vy the mover's motion this frame, y part
     * @param ox the obstacle's left edge
     * @param oy the obstacle's top edge
     * @param ow the obstacle's width
     * @param oh the obstacle's height
     * @return the time of impact in [0, 1] (see <a href="#t">what t promises</a>); 0 if the
     *         rectangles already overlap (exactly when {@link Collide#rectRect} says so);
     *         {@link Float#POSITIVE_INFINITY} if their insides do not start to overlap within
     *         the motion, or for NaN, infinite or negative input
     */
    public static float rectRect(float x, float y, float w, float h, float vx, float vy,
                                 float ox, float oy, float ow, float oh) {
        if (Check.notFinite(x, y, w, h, vx) || Check.notFinite(vy, ox, oy, ow, oh)) {
            return Float.POSITIVE_INFINITY;
        }
        if (Collide.rectRect(x, y, w, h, ox, oy, ow, oh)) {
            return 0;
        }
        return rectRectAnswer(x, y, w, h, vx, vy, ox, oy, ow, oh, SweptPairs.rectRectEntry(x, y, w, h, vx, vy, ox, oy, ow, oh));
    }

    /**
     * The promised t of a box sweep from its exact entry e: 0 if inside or touching at the
     * start and moving in, +infinity if the exact path misses, else the walk from the entry.
     */
    private static float rectRectAnswer(float x, float y, float w, float h, float vx, float vy,
                                        float ox, float oy, float ow, float oh, Earliest e) {
        if (e.inside || e.found() && e.t == 0) {
            return 0;  // overlapping, or touching at the start and moving in (Hit's promise)
        }
        // Two boxes overlap on one interval of floats, with "clear, not past" below it and
        // "past" above it (SweptPairs.Search.answer), so the walk from the exact entry cannot
        // step over it however rounding moves or shortens it.
        if (!e.found()) {
            return Float.POSITIVE_INFINITY;  // hit or not is the exact path's decision
        }
        double from = e.t;
        // The search's loop here, with the overlap test written out: see SweptPairs.Search.
        SweptPairs.Search s = SweptPairs.search(from, false);
        while (s.searching()) {
            float t = s.t();
            float mx = x + t * vx, my = y + t * vy;
            s.answer(Collide.rectRect(mx, my, w, h, ox, oy, ow, oh), SweptPairs.rectPast(mx, my, w, h, vx, vy, ox, oy, ow, oh));
        }
        return s.t();
    }

    // ---------------------------------------------------------------- richer answers, on floats

    /**
     * Where does a moving rectangle first run into a standing one, and which side does it hit?
     *
     * <p>Same time as {@link #rectRect}; the side is the obstacle's side whose axis was
     * entered last. A box that hits a corner exactly (both axes at once) counts as hitting
     * the {@link Side#TOP} or {@link Side#BOTTOM}, so a player landing exactly on a
     * platform's corner lands rather than being stopped.
     *
     * @param x  the mover's left edge at the start
     * @param y  the mover's top edge at the start
     * @param w  the mover's width
     * @param h  the mover's height
     * @param vx the mover's motion this frame, x part
     * @param vy the mover's motion this frame, y part
     * @param ox the obstacle's left edge
     * @param oy the obstacle's top edge
     * @param ow the obstacle's width
     * @param oh the obstacle's height
     * @return the hit, normal from the mover into the obstacle; null if the insides do not
     *         start to overlap within the motion, or for NaN, infinite or negative input
     */
    static Hit rectRectHit(float x, float y, float w, float h, float vx, float vy,
                                  float ox, float oy, float ow, float oh) {
        if (Check.notFinite(x, y, w, h, vx) || Check.notFinite(vy, ox, oy, ow, oh)) {
            return null;
        }
        Earliest e = SweptPairs.rectRectEntry(x, y, w, h, vx, vy, ox, oy, ow, oh);
        float t = rectRectAnswer(x, y, w, h, vx, vy, ox, oy, ow, oh, e);
        return SweptPairs.hit(t, e, e, false);
    }

    /**
     * Where does a moving circle first run into a standing one?
     *
     * <p>The normal points from the mover's centre to the
     * obstacle's at the impact, and the side is the one the normal points into.
     *
     * @param x  the mover's centre x at the start
     * @param y  the mover's centre y at the start
     * @param r  the mover's radius
     * @param vx the mover's motion this frame, x part
     * @param vy the mover's motion this frame, y part
     * @param ox the obstacle's centre x
     * @param oy the obstacle's centre y
     * @param or the obstacle's radius
     * @return the hit, or null if the circles do not start to overlap within the motion, or
     *         for NaN, infinite or negative input
     */
    static Hit circleCircleHit(float x, float y, float r, float vx, float vy,
                                      float ox, float oy, float or) {
        Earliest e = SweptPairs.circleCircleEntry(x, y, r, vx, vy, ox, oy, or);
        if (!e.found() && !(Float.isFinite(x) && Float.isFinite(y) && r >= 0 && Float.isFinite(vx) && Float.isFinite(vy)
                && Float.isFinite(ox) && Float.isFinite(oy) && or >= 0 && Float.isFinite(r) && Float.isFinite(or))) {
            return null;  // bad input: no hit, as documented
        }
        double g = SweptPairs.slack(x, vx) + SweptPairs.slack(y, vy);
        Earliest grown = SweptPairs.decided(e) ? e
                : SweptPairs.circleCircleGrown(x, y, r, vx, vy, ox, oy, or, g);
        float t = SweptPairs.answer(e, grown, SweptPairs.circleCircleAt(x, y, r, vx, vy, ox, oy, or),
                x, vx, y, vy);
        return SweptPairs.hit(t, e, grown, false);
    }

    /**
     * Where does a moving circle first run into a standing rectangle? The fast ball against a
     * thin wall.
     *
     * <p>The circle's inside overlaps the rectangle's while its centre is inside the rectangle
     * grown by the radius, a box with rounded corners; the centre's straight path is tested
     * against the two crossing boxes and the four corner circles that make it up. A hit on a
     * face gives that face's normal, turned into the rectangle; a hit on a corner gives the
     * normal pointing from the centre to the corner.
     *
     * @param cx the circle's centre x at the start
     * @param cy the circle's centre y at the start
     * @param r  the circle's radius
     * @param vx the circle's motion this frame, x part
     * @param vy the circle's motion this frame, y part
     * @param rectX the rectangle's left edge
     * @param rectY the rectangle's top edge
     * @param rectW the rectangle's width
     * @param rectH the rectangle's height
     * @return the hit ({@code t = 0} with {@link Side#NONE} if {@link Collide#circleRect}
     *         says they already overlap), or null if they do not start to overlap within the
     *         motion, or for NaN, infinite or negative input
     */
    static Hit circleRectHit(float cx, float cy, float r, float vx, float vy,
                                    float rectX, float rectY, float rectW, float rectH) {
        Earliest e = SweptPairs.circleRectEntry(cx, cy, r, vx, vy, rectX, rectY, rectW, rectH);
        if (!e.found() && (Check.notFinite(cx, cy, r, vx, vy) || Check.notFinite(rectX, rectY, rectW, rectH, 0)
                || r < 0 || rectW < 0 || rectH < 0)) {
            return null;  // bad input: no hit, as documented
        }
        Earliest grown = SweptPairs.decided(e) ? e
                : SweptPairs.circleRectGrown(SweptPairs.grownEntry(), cx, cy, r, SweptPairs.slack(cx, vx), SweptPairs.slack(cy, vy),
                vx, vy, rectX, rectY, rectW, rectH);
        float t = SweptPairs.answer(e, grown, SweptPairs.circleRectAt(cx, cy, r, vx, vy, rectX, rectY, rectW, rectH),
                cx, vx, cy, vy);
        return SweptPairs.hit(t, e, grown, false);
    }

    /**
     * Where does a moving rectangle first run into a standing segment (a thin wall or a
     * slope)?
     *
     * <p>The segment is closed, so it is hit as soon as it reaches the rectangle's inside. The
     * insides are tested on three axes (x, y and the segment's normal), each giving an
     * interval of time, as in the separating axis test. A rectangle of width or height 0 has
     * no inside and never hits a segment.
     *
     * @param x  the rectangle's left edge at the start
     * @param y  the rectangle's top edge at the start
     * @param w  the rectangle's width
     * @param h  the rectangle's height
     * @param vx the rectangle's motion this frame, x part
     * @param vy the rectangle's motion this frame, y part
     * @param x1 the segment's first end, x
     * @param y1 the segment's first end, y
     * @param x2 the segment's second end, x
     * @param y2 the segment's second end, y
     * @return the hit, or null if the segment does not reach the rectangle's inside within
     *         the motion, or for NaN, infinite or negative input
     */
    static Hit rectSegmentHit(float x, float y, float w, float h, float vx, float vy,
                                     float x1, float y1, float x2, float y2) {
        Earliest e = SweptPairs.rectSegmentEntry(x, y, w, h, vx, vy, x1, y1, x2, y2);
        Earliest grown = SweptPairs.decided(e) ? e
                : SweptPairs.rectSegmentEntry(x, y, w, h, vx, vy, x1, y1, x2, y2,
                SweptPairs.slack(x, vx), SweptPairs.slack(y, vy));
        float t = SweptPairs.answer(e, grown, SweptPairs.rectSegmentAt(x, y, w, h, vx, vy, x1, y1, x2, y2),
                x, vx, y, vy);
        return SweptPairs.hit(t, e, grown, false);
    }

    /**
     * Where does a moving circle first run into a standing segment?
     *
     * <p>The circle's inside reaches the closed segment while its centre is inside the capsule
     * around the segment: a box along the segment and a circle at each end. A circle of
     * radius 0 is a point and never hits a segment.
     *
     * @param cx the circle's centre x at the start
     * @param cy the circle's centre y at the start
     * @param r  the circle's radius
     * @param vx the circle's motion this frame, x part
     * @param vy the circle's motion this frame, y part
     * @param x1 the segment's first end, x
     * @param y1 the segment's first end, y
     * @param x2 the segment's second end, x
     * @param y2 the segment's second end, y
     * @return the hit, or null if the circle does not reach the segment within the motion,
     *         or for NaN, infinite or negative input
     */
    static Hit circleSegmentHit(float cx, float cy, float r, float vx, float vy,
                                       float x1, float y1, float x2, float y2) {
        Earliest e = SweptPairs.circleSegmentEntry(cx, cy, r, vx, vy, x1, y1, x2, y2);
        Earliest grown = SweptPairs.decided(e) ? e
                : SweptPairs.circleSegmentEntry(cx, cy, r, vx, vy, x1, y1, x2, y2,
                SweptPairs.slack(cx, vx), SweptPairs.slack(cy, vy));
        float t = SweptPairs.answer(e, grown, SweptPairs.circleSegmentAt(cx, cy, r, vx, vy, x1, y1, x2, y2),
                cx, vx, cy, vy);
        return SweptPairs.hit(t, e, grown, false);
    }

    // ---------------------------------------------------------------- on shapes

    /**
     * Where does a moving segment first run into a standing rectangle? The rectangle moving
     * by {@code (-vx, -vy)} into the segment; the normal points from the segment into the
     * rectangle.
     *
     * @param mover    the moving segment, where it starts, not null
     * @param vx       its motion this frame, x part
     * @param vy       its motion this frame, y part
     * @param obstacle the standing rectangle, not null
     * @return the hit, or null if there is none within the motion
     * @throws IllegalArgumentException if a shape is null or the velocity is NaN or infinite
     */
    private static Hit timeOfImpact(Segment mover, float vx, float vy, Rect obstacle) {
        checkArgs(mover, vx, vy, obstacle);
        float x1 = mover.x1(), y1 = mover.y1(), x2 = mover.x2(), y2 = mover.y2();
        float rectX = obstacle.x(), rectY = obstacle.y(), rectW = obstacle.w(), rectH = obstacle.h();
        Earliest e = SweptPairs.rectSegmentEntry(rectX, rectY, rectW, rectH, -vx, -vy, x1, y1, x2, y2);
        Earliest grown = SweptPairs.decided(e) ? e
                : SweptPairs.rectSegmentEntry(rectX, rectY, rectW, rectH, -vx, -vy, x1, y1, x2, y2,
                Math.max(SweptPairs.slack(x1, vx), SweptPairs.slack(x2, vx)), Math.max(SweptPairs.slack(y1, vy), SweptPairs.slack(y2, vy)));
        float t = SweptPairs.answer(e, grown,
                SweptPairs.segmentRectAt(x1, y1, x2, y2, vx, vy, rectX, rectY, rectW, rectH),
                x1, vx, y1, vy, x2, vx, y2, vy);
        return SweptPairs.hit(t, e, grown, true);
    }

    /**
     * Where does a moving segment first run into a standing circle? The circle moving by
     * {@code (-vx, -vy)} into the segment; the normal points from the segment into the
     * circle.
     *
     * @param mover    the moving segment, where it starts, not null
     * @param vx       its motion this frame, x part
     * @param vy       its motion this frame, y part
     * @param obstacle the standing circle, not null
     * @return the hit, or null if there is none within the motion
     * @throws IllegalArgumentException if a shape is null or the velocity is NaN or infinite
     */
    private static Hit timeOfImpact(Segment mover, float vx, float vy, Circle obstacle) {
        checkArgs(mover, vx, vy, obstacle);
        float x1 = mover.x1(), y1 = mover.y1(), x2 = mover.x2(), y2 = mover.y2();
        float cx = obstacle.x(), cy = obstacle.y(), r = obstacle.r();
        Earliest e = SweptPairs.circleSegmentEntry(cx, cy, r, -vx, -vy, x1, y1, x2, y2);
        Earliest grown = SweptPairs.decided(e) ? e
                : SweptPairs.circleSegmentEntry(cx, cy, r, -vx, -vy, x1, y1, x2, y2,
                Math.max(SweptPairs.slack(x1, vx), SweptPairs.slack(x2, vx)), Math.max(SweptPairs.slack(y1, vy), SweptPairs.slack(y2, vy)));
        float t = SweptPairs.answer(e, grown,
                SweptPairs.segmentCircleAt(x1, y1, x2, y2, vx, vy, cx, cy, r),
                x1, vx, y1, vy, x2, vx, y2, vy);
        return SweptPairs.hit(t, e, grown, true);
    }

    /**
     * Where does a moving shape first run into a standing one, for every pair of shapes.
     * Circles, rectangles and segments (but two segments) have exact swept tests, the methods
     * above, and so do two convex polygons, a rectangle moving into a convex polygon (the
     * motion as a ray against their Minkowski difference, whose faces are the two shapes'
     * edges; the normal is the face entered), and a circle moving into any polygon (the
     * circle against each edge, as against a segment). Every other pair (a concave polygon with
     * anything but a moving circle, ellipses
     * aligned or turned, capsules, two segments, a polygon moving into a rectangle) is found
     * by conservative advancement along
     * separating directions over the shapes' convex pieces (never later than the real
     * entry, so nothing is passed through), the normal being the separating direction found
     * there, to about 1e-6 radians. Then, as for the exact pairs, the float t promised by
     * {@link Hit}: the largest at which the mover, moved by {@code t * (vx, vy)} in float,
     * does not overlap while at the next float up it does; the normal points from the mover
     * into the obstacle.
     *
     * @param mover    the moving shape, where it starts, not null
     * @param vx       its motion this frame, x part
     * @param vy       its motion this frame, y part
     * @param obstacle the standing shape, not null
     * @return the hit, or null if there is none within the motion
     * @throws IllegalArgumentException if a shape is null or the velocity is NaN or infinite
     */
    public static Hit timeOfImpact(Shape mover, float vx, float vy, Shape obstacle) {
        checkArgs(mover, vx, vy, obstacle);
        // The exact pairs by their own methods; everything else (polygons, ellipses, capsules,
        // two segments) by convex pieces. One small method per mover kind, so that this one
        // stays small enough for the JIT to inline into a caller's loop.
        return switch (ShapeKind.of(mover)) {
            case RECT -> {
                Rect r = (Rect) mover;
                yield rectInto(r, r.x(), r.y(), r.w(), r.h(), vx, vy, obstacle);
            }
            case CIRCLE -> {
                Circle c = (Circle) mover;
                yield circleInto(c, c.x(), c.y(), c.r(), vx, vy, obstacle);
            }
            case SEGMENT -> segmentInto((Segment) mover, vx, vy, obstacle);
            case ELLIPSE, CAPSULE, POLYGON -> ConvexSweep.timeOfImpact(mover, vx, vy, obstacle);
        };
    }

    /**
     * {@link #timeOfImpact(Shape, float, float, Shape)} as numbers, making no {@code Hit}: for
     * the world's mover, which asks it of every candidate of every leg and keeps one.
     *
     * @param out given the hit's t, nx and ny (untouched for no hit)
     * @return the side met ({@link Side#NONE} if the shapes overlap at the start), or null
     *         for no hit within the motion
     */
    static Side timeOfImpact(Shape mover, float vx, float vy, Shape obstacle, float[] out) {
        boolean recording = SweptPairs.recording(true);
        Hit h;
        try {
            h = timeOfImpact(mover, vx, vy, obstacle);
        } finally {
            SweptPairs.recording(recording);  // a bad argument's exception leaves it as it was
        }
        return SweptPairs.recorded(h, out);
    }

    /**
     * {@link #timeOfImpact(Shape, float, float, Shape)} for a rectangle mover (x, y, w, h),
     * valid values, as numbers: its {@code Rect} given if made, else null (a world's walk
     * moves a box as numbers), made only for a pair answered on shapes.
     */
    static Hit rectInto(Rect made, float x, float y, float w, float h, float vx, float vy, Shape obstacle) {
        return switch (ShapeKind.of(obstacle)) {
            case RECT -> {
                Rect o = (Rect) obstacle;
                yield rectRectHit(x, y, w, h, vx, vy, o.x(), o.y(), o.w(), o.h());
            }
            case CIRCLE -> {
                Circle o = (Circle) obstacle;
                yield rectCircle(x, y, w, h, vx, vy, o.x(), o.y(), o.r());
            }
            case SEGMENT -> {
                Segment o = (Segment) obstacle;
                yield rectSegmentHit(x, y, w, h, vx, vy, o.x1(), o.y1(), o.x2(), o.y2());
            }
            case ELLIPSE, CAPSULE, POLYGON -> ConvexSweep.rectTimeOfImpact(made, x, y, w, h, vx, vy, obstacle);
        };
    }

    /**
     * {@link #timeOfImpact(Shape, float, float, Shape)} for a circle mover at (x, y) of radius
     * r, valid values, as numbers: its {@code Circle} given if made, else null, made only for
     * a pair answered on shapes.
     */
    static Hit circleInto(Circle made, float x, float y, float r, float vx, float vy, Shape obstacle) {
        return switch (ShapeKind.of(obstacle)) {
            case CIRCLE -> {
                Circle o = (Circle) obstacle;
                yield circleCircleHit(x, y, r, vx, vy, o.x(), o.y(), o.r());
            }
            case RECT -> {
                Rect o = (Rect) obstacle;
                yield circleRectHit(x, y, r, vx, vy, o.x(), o.y(), o.w(), o.h());
            }
            case SEGMENT -> {
                Segment o = (Segment) obstacle;
                yield circleSegmentHit(x, y, r, vx, vy, o.x1(), o.y1(), o.x2(), o.y2());
            }
            case ELLIPSE, CAPSULE, POLYGON -> ConvexSweep.circleTimeOfImpact(made, x, y, r, vx, vy, obstacle);
        };
    }

    /**
     * {@link #rectInto(Rect, float, float, float, float, float, float, Shape)} into a box or a
     * circle given as numbers (a world's walk keeps both as numbers): the same kernels, kind
     * {@link ShapeKind#RECT} with (ox, oy, ow, oh) or {@link ShapeKind#CIRCLE} with (ox, oy,
     * ow as the radius).
     */
    static Hit rectInto(float x, float y, float w, float h, float vx, float vy, ShapeKind kind, float ox, float oy, float ow, float oh) {
        return kind == ShapeKind.RECT ? rectRectHit(x, y, w, h, vx, vy, ox, oy, ow, oh) : rectCircle(x, y, w, h, vx, vy, ox, oy, ow);
    }

    /** {@link #rectInto(float, float, float, float, float, float, ShapeKind, float, float, float, float)} for a circle mover. */
    static Hit circleInto(float x, float y, float r, float vx, float vy, ShapeKind kind, float ox, float oy, float ow, float oh) {
        return kind == ShapeKind.RECT ? circleRectHit(x, y, r, vx, vy, ox, oy, ow, oh) : circleCircleHit(x, y, r, vx, vy, ox, oy, ow);
    }

    /**
     * A moving rectangle into a standing circle: the same motion seen from the other shape,
     * the circle moving by {@code (-vx, -vy)} into the rectangle; the normal still points
     * from the mover (the rectangle) into the circle.
     */
    private static Hit rectCircle(float x, float y, float w, float h, float vx, float vy, float cx, float cy, float r) {
        Earliest e = SweptPairs.circleRectEntry(cx, cy, r, -vx, -vy, x, y, w, h);
        Earliest grown = SweptPairs.decided(e) ? e
                : SweptPairs.circleRectGrown(SweptPairs.grownEntry(), cx, cy, r, SweptPairs.slack(x, vx), SweptPairs.slack(y, vy),
                -vx, -vy, x, y, w, h);
        float t = SweptPairs.answer(e, grown, SweptPairs.rectCircleAt(x, y, w, h, vx, vy, cx, cy, r),
                x, vx, y, vy);
        return SweptPairs.hit(t, e, grown, true);
    }

    /** {@link #timeOfImpact(Shape, float, float, Shape)} for a segment mover, valid values. */
    private static Hit segmentInto(Segment mover, float vx, float vy, Shape obstacle) {
        return switch (ShapeKind.of(obstacle)) {
            case RECT -> timeOfImpact(mover, vx, vy, (Rect) obstacle);
            case CIRCLE -> timeOfImpact(mover, vx, vy, (Circle) obstacle);
            case SEGMENT, ELLIPSE, CAPSULE, POLYGON -> ConvexSweep.timeOfImpact(mover, vx, vy, obstacle);
        };
    }

    /**
     * Where does a convex polygon that moves <em>and turns</em> this frame first run into a
     * standing shape? At time t in [0, 1] the mover is turned by {@code t * turn} radians
     * about the pivot (clockwise on screen for a positive turn, as Processing's
     * {@code rotate}) and moved by {@code t * (vx, vy)}, the pivot with it: a spinning blade
     * turns about its hub. A straight sweep of a fast-turning thin shape misses what its tip
     * sweeps through; this one never does (conservative advancement: each step is shorter
     * than the gap left, so nothing is passed through). The hit is where the gap first falls
     * below {@code 1e-3} pixels while closing in (a mover turning away from what it touches
     * is not stopped): the mover at that t does not overlap the obstacle; its normal points
     * from the mover into the obstacle. Costs many support evaluations per step: use
     * it for a few fast movers, after a bounds test.
     *
     * @param mover    the turning shape where it starts, a convex polygon, not null
     * @param pivotX   the point it turns about, x
     * @param pivotY   the point it turns about, y
     * @param vx       the pivot's motion this frame, x part
     * @param vy       the pivot's motion this frame, y part
     * @param turn     how far it turns this frame, in radians
     * @param obstacle the standing shape, any kind (a concave polygon is taken as its convex
     *                 pieces), not null
     * @return the hit, {@link Hit#alreadyOverlapping() already overlapping} at t = 0, or null
     *         if there is none this frame
     * @throws IllegalArgumentException if a shape is null, the mover is not convex, or a
     *                                  number is NaN or infinite
     */
    public static Hit turningTimeOfImpact(Polygon mover, float pivotX, float pivotY, float vx, float vy, float turn,
                                          Shape obstacle) {
        checkArgs(mover, vx, vy, obstacle);
        Check.finite("pivotX", pivotX);
        Check.finite("pivotY", pivotY);
        Check.finite("turn", turn);
        if (!mover.isConvex()) {
            throw new IllegalArgumentException("mover must be a convex polygon; split a concave one into convex ones");
        }
        return TurningSweep.timeOfImpact(mover, pivotX, pivotY, vx, vy, turn, obstacle);
    }

    /**
     * Where do two polygons that both move <em>and turn</em> this frame first run into each
     * other? Each is turned by {@code t * turn} radians about its own pivot (clockwise on
     * screen for a positive turn) and moved by {@code t * (vx, vy)}, the pivot with it, as in
     * {@link #turningTimeOfImpact(Polygon, float, float, float, float, float, Shape)}: two
     * spinning blades, a spinning bar against a spinning box (dyn4j's fast rotation against
     * fast rotation). The same contract as that method: never tunnelling (conservative
     * advancement, each step shorter than the gap left divided by the fastest any point of
     * one can gain on the other, {@code |va - vb| + |turnA| Ra + |turnB| Rb} with R each
     * body's farthest vertex from its pivot); the hit is where the gap first falls below
     * {@code 1e-3} pixels while closing in, at a t at which the two, each placed there (turned
     * and moved as above in double precision, then rounded to floats), do not overlap; the
     * normal points from a into b. Swapping the two bodies gives the same t and the opposite
     * normal (to within that stopping rule).
     *
     * @param a       the first body where it starts, any polygon (a concave one is taken as
     *                its convex pieces), not null
     * @param pivotAX the point a turns about, x
     * @param pivotAY the point a turns about, y
     * @param vax     a's pivot's motion this frame, x part
     * @param vay     a's pivot's motion this frame, y part
     * @param turnA   how far a turns this frame, in radians
     * @param b       the second body where it starts, any polygon (a concave one is taken as
     *                its convex pieces), not null
     * @param pivotBX the point b turns about, x
     * @param pivotBY the point b turns about, y
     * @param vbx     b's pivot's motion this frame, x part
     * @param vby     b's pivot's motion this frame, y part
     * @param turnB   how far b turns this frame, in radians
     * @return the hit, {@link Hit#alreadyOverlapping() already overlapping} at t = 0, or null
     *         if there is none this frame (both at rest: none)
     * @throws IllegalArgumentException if a polygon is null or a number is NaN or infinite
     */
    public static Hit turningTimeOfImpact(Polygon a, float pivotAX, float pivotAY, float vax, float vay, float turnA,
                                          Polygon b, float pivotBX, float pivotBY, float vbx, float vby, float turnB) {
        Check.notNull("a", a);
        Check.notNull("b", b);
        Check.finite("pivotAX", pivotAX);
        Check.finite("pivotAY", pivotAY);
        Check.finite("vax", vax);
        Check.finite("vay", vay);
        Check.finite("turnA", turnA);
        Check.finite("pivotBX", pivotBX);
        Check.finite("pivotBY", pivotBY);
        Check.finite("vbx", vbx);
        Check.finite("vby", vby);
        Check.finite("turnB", turnB);
        return TurningSweep.timeOfImpact(a, pivotAX, pivotAY, vax, vay, turnA, b, pivotBX, pivotBY, vbx, vby, turnB);
    }

    // ---------------------------------------------------------------- move and slide

    /**
     * Moves a box through a level in one frame: it goes until it first hits an obstacle,
     * stops there touching it, and slides along it with the rest of the motion (the part
     * into the obstacle dropped), up to {@link #MAX_SLIDES} times.
     *
     * <p>The box never ends overlapping an obstacle it did not start in: an obstacle it
     * already overlaps at the start is ignored for this move, so a box stuck inside a wall
     * can walk out of it (push it out with a contact test if you want that instead). Sliding
     * along the top of a row of tiles never catches on the seams between them, because
     * touching is not colliding. Cost: the obstacles are looked at once per slide, so pass
     * the ones near the box.
     *
     * @param mover     the box, where it starts, not null
     * @param vx        its motion this frame, x part
     * @param vy        its motion this frame, y part
     * @param obstacles the standing boxes (walls, platforms, tiles), not null, no null element
     * @return where the box ends, the velocity to keep, and the sides it hit, never null
     * @throws IllegalArgumentException if an argument or an obstacle is null, or the velocity
     *                                  is NaN or infinite
     */
    public static Move move(Rect mover, float vx, float vy, Iterable<Rect> obstacles) {
        checkArgs(mover, vx, vy, "obstacles", obstacles);
        int i = 0;
        for (Rect o : obstacles) {
            if (o == null) {  // the name is built only for a refusal: this runs every frame
                Check.notNull("obstacles[" + i + "]", o);
            }
            i++;
        }
        return MoveAndSlide.move(mover, vx, vy, obstacles);
    }

    /**
     * Where {@link #move} left a box: its position, the velocity to keep for the next frame
     * and the sides of the obstacles it hit on the way. A move can hit several sides (a floor
     * and a wall), so it gives them as a set, {@link #sides()}, like {@link Edges} and
     * {@link Motion}; a result with one side gives it as {@code side()} (see
     * <a href="Side.html#results">the side of a result</a>).
     *
     * @param x     the box's left edge after the move
     * @param y     the box's top edge after the move
     * @param vx    the velocity to keep, x part: the one passed in, or 0 if a wall stopped it
     * @param vy    the velocity to keep, y part: the one passed in, or 0 if it landed or hit
     *              its head
     * @param sides the obstacle sides hit, an unmodifiable set (see
     *              <a href="Side.html#sets">several sides at once</a>), empty if none; read it
     *              with {@link #hit(Side)} or {@code contains}
     */
    public record Move(float x, float y, float vx, float vy, java.util.Set<Side> sides) {

        /**
         * Makes a move result, checking its values.
         *
         * @param x the box's left edge after the move
         * @param y the box's top edge after the move
         * @param vx the velocity to keep, x part: the one passed in, or 0 if a wall stopped it
         * @param vy the velocity to keep, y part: the one passed in, or 0 if it landed or hit its head
         * @param sides the obstacle sides hit, not null (kept as an unmodifiable set; {@link Side#NONE}
         *              in it names no side and is left out)
         *
         * @throws IllegalArgumentException if a value is NaN or infinite, or {@code sides} is
         *                                  null or holds null
         */
        public Move {
            Check.finite("x", x);
            Check.finite("y", y);
            Check.finite("vx", vx);
            Check.finite("vy", vy);
            sides = SideSets.of(SideSets.bits(Check.notNull("sides", sides)));
        }

        /**
         * Did the box hit this side of some obstacle?
         *
         * @param side the obstacle's side, not null
         * @return true if the box hit that side during the move ({@link Side#NONE}: true if
         *         it hit nothing)
         * @throws IllegalArgumentException if {@code side} is null
         */
        public boolean hit(Side side) {
            Check.notNull("side", side);
            return side == Side.NONE ? sides.isEmpty() : sides.contains(side);
        }

        /** @return true if the box came down on the top of an obstacle: it stands, and may jump */
        public boolean landed() {
            return hit(Side.TOP);
        }

        /** @return true if the box hit anything at all */
        public boolean hitAnything() {
            return !sides.isEmpty();
        }
    }

    private static void checkArgs(Object mover, float vx, float vy, Object obstacle) {
        checkArgs(mover, vx, vy, "obstacle", obstacle);
    }

    private static void checkArgs(Object mover, float vx, float vy, String obstacleName, Object obstacle) {
        Check.notNull("mover", mover);
        Check.finite("vx", vx);
        Check.finite("vy", vy);
        Check.notNull(obstacleName, obstacle);
    }
}
