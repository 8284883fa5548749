package hitbox;

/**
 * Moving objects done exactly: when, during this frame's motion, does a moving shape first
 * run into an obstacle? A swept test never tunnels: a small object moving thousands of
 * pixels a frame still hits a wall one pixel thick.
 *
 * <p>The tutorial moves an object and then tests where it landed, so a fast object can jump
 * over a thin wall between two frames. A swept test looks at the whole motion instead: the
 * mover starts where it is and moves by {@code (vx, vy)} this frame; the answer is the
 * <em>time of impact</em> {@code t}, the fraction of the motion done when the mover's inside
 * starts to overlap the obstacle's, so {@code x + t * vx, y + t * vy} is where it touches.
 *
 * <p>The <a href="package-summary.html#touching">touching rule</a> holds throughout:
 * <ul>
 *   <li>Already overlapping at the start (exactly what {@link Collide} says): {@code t = 0}.</li>
 *   <li>Touching at the start and moving into the obstacle: the insides start to overlap at
 *       once, so {@code t = 0} too.</li>
 *   <li>Touching at the start and moving away, or sliding along the obstacle's edge (a box
 *       moving sideways with its bottom level with a platform's top): the insides never
 *       overlap, so it is no hit.</li>
 *   <li>Only reaching the obstacle at the very end of the motion ({@code t = 1}, touching):
 *       no hit this frame.</li>
 * </ul>
 * No hit is {@link Float#POSITIVE_INFINITY} for the {@code float} methods and {@code null}
 * for the {@link Hit} methods, so {@code t <= 1} reads "it hits this frame".
 *
 * <p>Three levels, as elsewhere in the library: {@link #rectRect} and {@link #circleCircle}
 * return only {@code t} and allocate nothing; the {@code ...Hit} methods on plain floats and
 * the {@code timeOfImpact} methods on shapes return a {@link Hit} with the surface normal and
 * the {@link Side} hit; {@link #move} walks a box through a list of obstacles, sliding along
 * what it hits. Entry and exit times are computed in {@code double}: for whole-number
 * coordinates and velocities every decision (hit or not, which side) is exact. The float
 * methods check nothing: NaN or an infinite velocity gives "no hit".
 *
 * <p>Reference: Christer Ericson, <i>Real-Time Collision Detection</i> (2005), 5.5
 * "Dynamic Intersection Tests" (moving sphere against sphere, moving sphere against AABB as
 * a rounded box, moving AABB against AABB).
 */
public final class Sweep {

    /** How many times {@link #move} stops at an obstacle and slides on before giving up. */
    public static final int MAX_SLIDES = 4;

    static final double INF = Double.POSITIVE_INFINITY;

    /** The answer when the shapes already overlap at the start. */
    private static final Hit OVERLAPPING = new Hit(0, 0, 0, Side.NONE);

    private Sweep() {
    }

    // ---------------------------------------------------------------- time only, no allocation

    /**
     * When does a moving rectangle first overlap a standing one? Swept box against box.
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
     * @return the time of impact in [0, 1]; 0 if the rectangles already overlap (exactly when
     *         {@link Collide#rectRect} says so) or touch and the mover moves in;
     *         {@link Float#POSITIVE_INFINITY} if their insides do not start to overlap within
     *         the motion
     */
    public static float rectRect(float x, float y, float w, float h, float vx, float vy,
                                 float ox, float oy, float ow, float oh) {
        return (float) rectRectTime(x, y, w, h, vx, vy, ox, oy, ow, oh);
    }

    /**
     * When does a moving circle first overlap a standing one? Swept circle against circle.
     *
     * <p>Solves {@code |d + t v| < r + or} for the earliest {@code t}, a quadratic in
     * {@code t}; a path that only touches the obstacle's outline is no hit.
     *
     * @param x  the mover's centre x at the start
     * @param y  the mover's centre y at the start
     * @param r  the mover's radius
     * @param vx the mover's motion this frame, x part
     * @param vy the mover's motion this frame, y part
     * @param ox the obstacle's centre x
     * @param oy the obstacle's centre y
     * @param or the obstacle's radius
     * @return the time of impact in [0, 1]; 0 if the circles already overlap (exactly when
     *         {@link Collide#circleCircle} says so) or touch and the mover moves in;
     *         {@link Float#POSITIVE_INFINITY} if they do not start to overlap within the motion
     */
    public static float circleCircle(float x, float y, float r, float vx, float vy,
                                     float ox, float oy, float or) {
        if (Collide.circleCircle(x, y, r, ox, oy, or)) {
            return 0;
        }
        double t = discEntry((double) x - ox, (double) y - oy, vx, vy, (double) r + or, 1);
        return t < 0 ? 0 : (float) t;
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
     * @return the hit, or null if the insides do not start to overlap within the motion
     */
    public static Hit rectRectHit(float x, float y, float w, float h, float vx, float vy,
                                  float ox, float oy, float ow, float oh) {
        return rectRectHit(x, y, w, h, (double) vx, vy, ox, oy, ow, oh);
    }

    /**
     * Where does a moving circle first run into a standing one?
     *
     * <p>Same time as {@link #circleCircle}; the normal points from the obstacle's centre to
     * the mover's at the impact, and the side is the one the normal mostly faces.
     *
     * @param x  the mover's centre x at the start
     * @param y  the mover's centre y at the start
     * @param r  the mover's radius
     * @param vx the mover's motion this frame, x part
     * @param vy the mover's motion this frame, y part
     * @param ox the obstacle's centre x
     * @param oy the obstacle's centre y
     * @param or the obstacle's radius
     * @return the hit, or null if the circles do not start to overlap within the motion
     */
    public static Hit circleCircleHit(float x, float y, float r, float vx, float vy,
                                      float ox, float oy, float or) {
        if (Collide.circleCircle(x, y, r, ox, oy, or)) {
            return OVERLAPPING;
        }
        Best best = new Best();
        best.disc((double) x - ox, (double) y - oy, vx, vy, (double) r + or, 1);
        return best.hit();
    }

    /**
     * Where does a moving circle first run into a standing rectangle? The fast ball against a
     * thin wall.
     *
     * <p>The circle's inside overlaps the rectangle's while its centre is inside the rectangle
     * grown by the radius, a box with rounded corners; the centre's straight path is tested
     * against the two crossing boxes and the four corner circles that make it up. A hit on a
     * face gives that face's normal; a hit on a corner gives the normal pointing from the
     * corner to the centre.
     *
     * @param cx the circle's centre x at the start
     * @param cy the circle's centre y at the start
     * @param r  the circle's radius
     * @param vx the circle's motion this frame, x part
     * @param vy the circle's motion this frame, y part
     * @param rx the rectangle's left edge
     * @param ry the rectangle's top edge
     * @param rw the rectangle's width
     * @param rh the rectangle's height
     * @return the hit ({@code t = 0} with {@link Side#NONE} if {@link Collide#circleRect}
     *         says they already overlap), or null if they do not start to overlap within the
     *         motion
     */
    public static Hit circleRectHit(float cx, float cy, float r, float vx, float vy,
                                    float rx, float ry, float rw, float rh) {
        if (Collide.circleRect(cx, cy, r, rx, ry, rw, rh)) {
            return OVERLAPPING;
        }
        if (!finite(vx, vy)) {
            return null;
        }
        Best best = new Best();
        double left = rx, right = (double) rx + rw, top = ry, bottom = (double) ry + rh;
        // The rounded box is the union of two crossing boxes and four corner circles; the
        // first entry into the union is the first entry into any of them. Where a box and a
        // corner circle are entered at the same moment the point is where the circle meets
        // the box's real face, so the circles go first (ties keep the first), and each box
        // puts its real faces first: the wide box's are left and right, the tall box's top
        // and bottom.
        best.disc(cx - left, cy - top, vx, vy, r, 1);
        best.disc(cx - right, cy - top, vx, vy, r, 1);
        best.disc(cx - left, cy - bottom, vx, vy, r, 1);
        best.disc(cx - right, cy - bottom, vx, vy, r, 1);
        best.clip(new Clip()
                .slab(left - r - cx, right + r - cx, vx, 1, 0)
                .slab(top - cy, bottom - cy, vy, 0, 1), 1);
        best.clip(new Clip()
                .slab(top - r - cy, bottom + r - cy, vy, 0, 1)
                .slab(left - cx, right - cx, vx, 1, 0), 1);
        return best.hit();
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
     *         the motion
     */
    public static Hit rectSegmentHit(float x, float y, float w, float h, float vx, float vy,
                                     float x1, float y1, float x2, float y2) {
        if (!(w > 0 && h > 0) || !finite(vx, vy)) {
            return null;
        }
        double left = x, right = (double) x + w, top = y, bottom = (double) y + h;
        Clip clip = new Clip()
                .slab(Math.min(y1, y2) - bottom, Math.max(y1, y2) - top, vy, 0, 1)
                .slab(Math.min(x1, x2) - right, Math.max(x1, x2) - left, vx, 1, 0);
        double ex = (double) x2 - x1, ey = (double) y2 - y1;
        if (ex != 0 || ey != 0) {
            // Across the segment: n = (-ey, ex). The segment projects to one value, the box
            // to an interval found from its corners.
            double nx = -ey, ny = ex;
            double s = nx * x1 + ny * y1;
            double base = nx * left + ny * top;
            double lo = base + Math.min(0, nx * w) + Math.min(0, ny * h);
            double hi = base + Math.max(0, nx * w) + Math.max(0, ny * h);
            double len = Math.hypot(ex, ey);
            clip.slab(s - hi, s - lo, nx * vx + ny * vy, nx / len, ny / len);
        }
        Best best = new Best();
        best.clip(clip, 1);
        return best.hit();
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
     * @return the hit, or null if the circle does not reach the segment within the motion
     */
    public static Hit circleSegmentHit(float cx, float cy, float r, float vx, float vy,
                                       float x1, float y1, float x2, float y2) {
        if (!(r > 0) || !finite(vx, vy)) {
            return null;
        }
        Best best = new Best();
        // End circles first: at a tie the point is where an end circle meets the face, and
        // the circle's normal is the true one there.
        best.disc((double) cx - x1, (double) cy - y1, vx, vy, r, 1);
        best.disc((double) cx - x2, (double) cy - y2, vx, vy, r, 1);
        double ex = (double) x2 - x1, ey = (double) y2 - y1;
        double len2 = ex * ex + ey * ey;
        if (len2 > 0) {
            double len = Math.sqrt(len2);
            double px = (double) cx - x1, py = (double) cy - y1;
            double across = -ey * px + ex * py;
            double along = ex * px + ey * py;
            double half = r * len;
            best.clip(new Clip()
                    .slab(-half - across, half - across, -ey * vx + ex * vy, -ey / len, ex / len)
                    .slab(-along, len2 - along, ex * vx + ey * vy, ex / len, ey / len), 1);
        }
        return best.hit();
    }

    // ---------------------------------------------------------------- on shapes

    /**
     * Where does a moving rectangle first run into a standing one? Same as
     * {@link #rectRectHit}.
     *
     * @param mover    the moving rectangle, where it starts
     * @param vx       its motion this frame, x part
     * @param vy       its motion this frame, y part
     * @param obstacle the standing rectangle
     * @return the hit, or null if there is none within the motion
     * @throws IllegalArgumentException if a shape is null or the velocity is NaN or infinite
     */
    public static Hit timeOfImpact(Rect mover, float vx, float vy, Rect obstacle) {
        checkArgs(mover, vx, vy, obstacle);
        return rectRectHit(mover.x(), mover.y(), mover.w(), mover.h(), vx, vy,
                obstacle.x(), obstacle.y(), obstacle.w(), obstacle.h());
    }

    /**
     * Where does a moving circle first run into a standing one? Same as
     * {@link #circleCircleHit}.
     *
     * @param mover    the moving circle, where it starts
     * @param vx       its motion this frame, x part
     * @param vy       its motion this frame, y part
     * @param obstacle the standing circle
     * @return the hit, or null if there is none within the motion
     * @throws IllegalArgumentException if a shape is null or the velocity is NaN or infinite
     */
    public static Hit timeOfImpact(Circle mover, float vx, float vy, Circle obstacle) {
        checkArgs(mover, vx, vy, obstacle);
        return circleCircleHit(mover.x(), mover.y(), mover.r(), vx, vy,
                obstacle.x(), obstacle.y(), obstacle.r());
    }

    /**
     * Where does a moving circle first run into a standing rectangle? Same as
     * {@link #circleRectHit}.
     *
     * @param mover    the moving circle, where it starts
     * @param vx       its motion this frame, x part
     * @param vy       its motion this frame, y part
     * @param obstacle the standing rectangle
     * @return the hit, or null if there is none within the motion
     * @throws IllegalArgumentException if a shape is null or the velocity is NaN or infinite
     */
    public static Hit timeOfImpact(Circle mover, float vx, float vy, Rect obstacle) {
        checkArgs(mover, vx, vy, obstacle);
        return circleRectHit(mover.x(), mover.y(), mover.r(), vx, vy,
                obstacle.x(), obstacle.y(), obstacle.w(), obstacle.h());
    }

    /**
     * Where does a moving rectangle first run into a standing circle? The same motion seen
     * from the other shape: the circle moving by {@code (-vx, -vy)} into the rectangle, with
     * the normal turned round so it is the circle's.
     *
     * @param mover    the moving rectangle, where it starts
     * @param vx       its motion this frame, x part
     * @param vy       its motion this frame, y part
     * @param obstacle the standing circle
     * @return the hit, or null if there is none within the motion
     * @throws IllegalArgumentException if a shape is null or the velocity is NaN or infinite
     */
    public static Hit timeOfImpact(Rect mover, float vx, float vy, Circle obstacle) {
        checkArgs(mover, vx, vy, obstacle);
        return reversed(circleRectHit(obstacle.x(), obstacle.y(), obstacle.r(), -vx, -vy,
                mover.x(), mover.y(), mover.w(), mover.h()));
    }

    /**
     * Where does a moving rectangle first run into a standing segment? Same as
     * {@link #rectSegmentHit}.
     *
     * @param mover    the moving rectangle, where it starts
     * @param vx       its motion this frame, x part
     * @param vy       its motion this frame, y part
     * @param obstacle the standing segment
     * @return the hit, or null if there is none within the motion
     * @throws IllegalArgumentException if a shape is null or the velocity is NaN or infinite
     */
    public static Hit timeOfImpact(Rect mover, float vx, float vy, Segment obstacle) {
        checkArgs(mover, vx, vy, obstacle);
        return rectSegmentHit(mover.x(), mover.y(), mover.w(), mover.h(), vx, vy,
                obstacle.x1(), obstacle.y1(), obstacle.x2(), obstacle.y2());
    }

    /**
     * Where does a moving segment first run into a standing rectangle? The rectangle moving
     * by {@code (-vx, -vy)} into the segment, with the normal turned round.
     *
     * @param mover    the moving segment, where it starts
     * @param vx       its motion this frame, x part
     * @param vy       its motion this frame, y part
     * @param obstacle the standing rectangle
     * @return the hit, or null if there is none within the motion
     * @throws IllegalArgumentException if a shape is null or the velocity is NaN or infinite
     */
    public static Hit timeOfImpact(Segment mover, float vx, float vy, Rect obstacle) {
        checkArgs(mover, vx, vy, obstacle);
        return reversed(rectSegmentHit(obstacle.x(), obstacle.y(), obstacle.w(), obstacle.h(),
                -vx, -vy, mover.x1(), mover.y1(), mover.x2(), mover.y2()));
    }

    /**
     * Where does a moving circle first run into a standing segment? Same as
     * {@link #circleSegmentHit}.
     *
     * @param mover    the moving circle, where it starts
     * @param vx       its motion this frame, x part
     * @param vy       its motion this frame, y part
     * @param obstacle the standing segment
     * @return the hit, or null if there is none within the motion
     * @throws IllegalArgumentException if a shape is null or the velocity is NaN or infinite
     */
    public static Hit timeOfImpact(Circle mover, float vx, float vy, Segment obstacle) {
        checkArgs(mover, vx, vy, obstacle);
        return circleSegmentHit(mover.x(), mover.y(), mover.r(), vx, vy,
                obstacle.x1(), obstacle.y1(), obstacle.x2(), obstacle.y2());
    }

    /**
     * Where does a moving segment first run into a standing circle? The circle moving by
     * {@code (-vx, -vy)} into the segment, with the normal turned round.
     *
     * @param mover    the moving segment, where it starts
     * @param vx       its motion this frame, x part
     * @param vy       its motion this frame, y part
     * @param obstacle the standing circle
     * @return the hit, or null if there is none within the motion
     * @throws IllegalArgumentException if a shape is null or the velocity is NaN or infinite
     */
    public static Hit timeOfImpact(Segment mover, float vx, float vy, Circle obstacle) {
        checkArgs(mover, vx, vy, obstacle);
        return reversed(circleSegmentHit(obstacle.x(), obstacle.y(), obstacle.r(), -vx, -vy,
                mover.x1(), mover.y1(), mover.x2(), mover.y2()));
    }

    /**
     * Where does a moving shape first run into a standing one, for any pair that has a swept
     * test: circles, rectangles and segments, except a segment against a segment.
     *
     * @param mover    the moving shape, where it starts
     * @param vx       its motion this frame, x part
     * @param vy       its motion this frame, y part
     * @param obstacle the standing shape
     * @return the hit, or null if there is none within the motion
     * @throws IllegalArgumentException if a shape is null, the velocity is NaN or infinite,
     *                                  or the pair has no swept test (polygons, two segments)
     */
    public static Hit timeOfImpact(Shape mover, float vx, float vy, Shape obstacle) {
        checkArgs(mover, vx, vy, obstacle);
        if (mover instanceof Rect a) {
            if (obstacle instanceof Rect b) {
                return timeOfImpact(a, vx, vy, b);
            }
            if (obstacle instanceof Circle b) {
                return timeOfImpact(a, vx, vy, b);
            }
            if (obstacle instanceof Segment b) {
                return timeOfImpact(a, vx, vy, b);
            }
        } else if (mover instanceof Circle a) {
            if (obstacle instanceof Circle b) {
                return timeOfImpact(a, vx, vy, b);
            }
            if (obstacle instanceof Rect b) {
                return timeOfImpact(a, vx, vy, b);
            }
            if (obstacle instanceof Segment b) {
                return timeOfImpact(a, vx, vy, b);
            }
        } else if (mover instanceof Segment a) {
            if (obstacle instanceof Rect b) {
                return timeOfImpact(a, vx, vy, b);
            }
            if (obstacle instanceof Circle b) {
                return timeOfImpact(a, vx, vy, b);
            }
        }
        throw new IllegalArgumentException("Sweep has no time of impact for a moving "
                + mover.getClass().getSimpleName() + " and a " + obstacle.getClass().getSimpleName()
                + " yet; sweep their bounds() instead");
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
     * @param mover     the box, where it starts
     * @param vx        its motion this frame, x part
     * @param vy        its motion this frame, y part
     * @param obstacles the standing boxes (walls, platforms, tiles)
     * @return where the box ends, the velocity to keep, and the sides it hit
     * @throws IllegalArgumentException if an argument or an obstacle is null, or the velocity
     *                                  is NaN or infinite
     */
    public static Move move(Rect mover, float vx, float vy, Iterable<Rect> obstacles) {
        checkArgs(mover, vx, vy, "obstacles", obstacles);
        for (Rect o : obstacles) {
            Check.notNull("every obstacle", o);
        }
        final float x0 = mover.x(), y0 = mover.y(), w = mover.w(), h = mover.h();
        float x = x0, y = y0;
        double mx = vx, my = vy;  // the motion still to do this frame
        float keepVx = vx, keepVy = vy;
        int sides = 0;
        for (int stop = 0; stop < MAX_SLIDES && (mx != 0 || my != 0); stop++) {
            double first = INF;
            Rect hitRect = null;
            for (Rect o : obstacles) {
                if (!Collide.rectRect(x0, y0, w, h, o.x(), o.y(), o.w(), o.h())) {
                    double t = rectRectTime(x, y, w, h, mx, my, o.x(), o.y(), o.w(), o.h());
                    if (t < first) {
                        first = t;
                        hitRect = o;
                    }
                }
            }
            if (hitRect == null) {
                float[] end = safeAlong(x, y, w, h, mx, my, 1, (float) (x + mx), (float) (y + my), x0, y0, obstacles);
                x = end[0];
                y = end[1];
                break;
            }
            Hit hit = rectRectHit(x, y, w, h, mx, my, hitRect.x(), hitRect.y(), hitRect.w(), hitRect.h());
            Side side = hit == null ? Side.NONE : hit.side();
            if (side == Side.NONE) {
                break;  // cannot happen: the box is never left overlapping an obstacle it did not start in
            }
            // Stand exactly against the face hit (rounding could leave it a hair inside),
            // the other coordinate where the motion had got to.
            float tx = (float) (x + first * mx), ty = (float) (y + first * my);
            switch (side) {
                case LEFT -> tx = touchBefore(hitRect.x(), w);
                case RIGHT -> tx = touchAfter((double) hitRect.x() + hitRect.w());
                case TOP -> ty = touchBefore(hitRect.y(), h);
                default -> ty = touchAfter((double) hitRect.y() + hitRect.h());
            }
            float[] at = safeAlong(x, y, w, h, mx, my, first, tx, ty, x0, y0, obstacles);
            x = at[0];
            y = at[1];
            mx *= 1 - first;
            my *= 1 - first;
            if (side.isWall()) {
                mx = 0;
                keepVx = 0;
            } else {
                my = 0;
                keepVy = 0;
            }
            sides |= Move.bit(side);
        }
        return new Move(x, y, keepVx, keepVy, sides);
    }

    /**
     * Where {@link #move} left a box: its position, the velocity to keep for the next frame
     * and the sides of the obstacles it hit on the way.
     *
     * @param x     the box's left edge after the move
     * @param y     the box's top edge after the move
     * @param vx    the velocity to keep, x part: the one passed in, or 0 if a wall stopped it
     * @param vy    the velocity to keep, y part: the one passed in, or 0 if it landed or hit
     *              its head
     * @param sides the obstacle sides hit, one bit {@code 1 << side.ordinal()} per
     *              {@link Side}; read it with {@link #hit(Side)}
     */
    public record Move(float x, float y, float vx, float vy, int sides) {

        /**
         * Makes a move result, checking its values.
         *
         * @param x the box's left edge after the move
         * @param y the box's top edge after the move
         * @param vx the velocity to keep, x part: the one passed in, or 0 if a wall stopped it
         * @param vy the velocity to keep, y part: the one passed in, or 0 if it landed or hit its head
         * @param sides the obstacle sides hit, one bit {@code 1 << side.ordinal()} per {@link Side}; read it with {@link #hit(Side)}
         *
         * @throws IllegalArgumentException if a value is NaN or infinite, or {@code sides}
         *                                  has a bit that names no side
         */
        public Move {
            Check.finite("x", x);
            Check.finite("y", y);
            Check.finite("vx", vx);
            Check.finite("vy", vy);
            int all = bit(Side.TOP) | bit(Side.BOTTOM) | bit(Side.LEFT) | bit(Side.RIGHT);
            if ((sides & ~all) != 0) {
                throw new IllegalArgumentException("sides must only have the bits of TOP, BOTTOM, LEFT and RIGHT, was " + sides);
            }
        }

        /**
         * Did the box hit this side of some obstacle?
         *
         * @param side the obstacle's side, not null
         * @return true if the box hit that side during the move ({@link Side#NONE}: true if
         *         it hit nothing)
         */
        public boolean hit(Side side) {
            Check.notNull("side", side);
            return side == Side.NONE ? sides == 0 : (sides & bit(side)) != 0;
        }

        /** @return true if the box came down on the top of an obstacle: it stands, and may jump */
        public boolean landed() {
            return hit(Side.TOP);
        }

        /** @return true if the box went up into the bottom of an obstacle */
        public boolean hitHead() {
            return hit(Side.BOTTOM);
        }

        /** @return true if the box ran into the left or right side of an obstacle */
        public boolean hitWall() {
            return hit(Side.LEFT) || hit(Side.RIGHT);
        }

        /** @return true if the box hit anything at all */
        public boolean hitAnything() {
            return sides != 0;
        }

        static int bit(Side side) {
            return 1 << side.ordinal();
        }
    }

    // ---------------------------------------------------------------- the shared machinery

    /** Time of impact of two boxes, the motion given in double (the rest of a move). */
    static double rectRectTime(float x, float y, float w, float h, double vx, double vy,
                               float ox, float oy, float ow, float oh) {
        if (Collide.rectRect(x, y, w, h, ox, oy, ow, oh)) {
            return 0;
        }
        if (!finite(vx, vy)) {
            return INF;
        }
        // The same sums as Collide.rectRect, so the signs agree exactly with it.
        double loX = ox - ((double) x + w), hiX = ((double) ox + ow) - x;
        double loY = oy - ((double) y + h), hiY = ((double) oy + oh) - y;
        double enter = Math.max(slabEnter(loX, hiX, vx), slabEnter(loY, hiY, vy));
        double exit = Math.min(slabExit(loX, hiX, vx), slabExit(loY, hiY, vy));
        return firstTime(enter, exit, 1);
    }

    private static Hit rectRectHit(float x, float y, float w, float h, double vx, double vy,
                                   float ox, float oy, float ow, float oh) {
        if (Collide.rectRect(x, y, w, h, ox, oy, ow, oh)) {
            return OVERLAPPING;
        }
        if (!finite(vx, vy)) {
            return null;
        }
        // y first: a corner hit, where both axes are entered at once, counts as top or bottom.
        Clip clip = new Clip()
                .slab(oy - ((double) y + h), ((double) oy + oh) - y, vy, 0, 1)
                .slab(ox - ((double) x + w), ((double) ox + ow) - x, vx, 1, 0);
        Best best = new Best();
        best.clip(clip, 1);
        return best.hit();
    }

    /**
     * When does {@code t * v} enter the open interval (lo, hi)? -infinity if it is always
     * inside ({@code v = 0}), +infinity if never, NaN for NaN input.
     */
    static double slabEnter(double lo, double hi, double v) {
        if (v > 0) {
            return lo / v;
        }
        if (v < 0) {
            return hi / v;
        }
        if (v == 0) {
            return lo < 0 && 0 < hi ? Double.NEGATIVE_INFINITY : INF;
        }
        return Double.NaN;
    }

    /** When does {@code t * v} leave the open interval (lo, hi)? See {@link #slabEnter}. */
    static double slabExit(double lo, double hi, double v) {
        if (v > 0) {
            return hi / v;
        }
        if (v < 0) {
            return lo / v;
        }
        if (v == 0) {
            return lo < 0 && 0 < hi ? INF : Double.NEGATIVE_INFINITY;
        }
        return Double.NaN;
    }

    /**
     * The start of the open time interval (enter, exit) clipped to [0, limit): the time of
     * impact, or +infinity if the interval is empty, over before 0, or starts at the limit
     * or later.
     */
    static double firstTime(double enter, double exit, double limit) {
        return enter < exit && exit > 0 && enter < limit ? Math.max(enter, 0) : INF;
    }

    /**
     * When does the point {@code d + t v} enter the open disc of radius {@code reach} around
     * the origin, for t in [0, limit)? -infinity if it starts inside, +infinity if it never
     * enters (a path that only touches the outline does not).
     */
    static double discEntry(double dx, double dy, double vx, double vy, double reach, double limit) {
        if (!(reach > 0) || !finite(vx, vy)) {
            return INF;  // a point has no inside to enter
        }
        double c = dx * dx + dy * dy - reach * reach;
        if (c < 0) {
            return Double.NEGATIVE_INFINITY;
        }
        double b = dx * vx + dy * vy;
        if (!(b < 0)) {
            return INF;  // moving away, sideways along the outline, not at all, or NaN
        }
        double a = vx * vx + vy * vy;
        double disc = b * b - a * c;
        if (!(disc > 0)) {
            return INF;  // the path misses the disc or only touches it
        }
        if (c == 0) {
            return 0;  // touching and moving in
        }
        // The entry t1 is before the limit when the point is inside at the limit, or when
        // the closest approach (-b / a) comes before it; decided without the square root.
        boolean beforeLimit = limit == INF || a * limit * limit + 2 * b * limit + c < 0 || -b < a * limit;
        if (!beforeLimit) {
            return INF;
        }
        // t1 = (-b - sqrt(disc)) / a, written without cancellation.
        return Math.min(c / (Math.sqrt(disc) - b), limit);
    }

    static boolean finite(double vx, double vy) {
        return Math.abs(vx) < INF && Math.abs(vy) < INF;
    }

    /**
     * The float that puts a box of this size right before the edge, touching, not over it:
     * its far end {@code p + size}, added in double as {@link Collide} does, is at most
     * {@code edge}. That is {@code edge - size} when it is a float (it is for whole numbers);
     * else the rounded start may sit a hair past, and the loop steps down (once at most).
     */
    static float touchBefore(float edge, float size) {
        float p = (float) ((double) edge - size);
        while ((double) p + size > edge) {
            p = Math.nextDown(p);
        }
        return p;
    }

    /** The float at or right after the edge: a start that meets the edge from beyond. */
    static float touchAfter(double edge) {
        float p = (float) edge;
        while (p < edge) {
            p = Math.nextUp(p);
        }
        return p;
    }

    /**
     * The wanted stop (tx, ty) if it overlaps no obstacle (except those the box started in);
     * otherwise, which only rounding can cause, the farthest point along the motion before
     * {@code t} that is clear, found by halving. The start (x, y) is always clear.
     */
    private static float[] safeAlong(float x, float y, float w, float h, double mx, double my, double t,
                                     float tx, float ty, float x0, float y0, Iterable<Rect> obstacles) {
        if (clear(tx, ty, w, h, x0, y0, obstacles)) {
            return new float[] {tx, ty};
        }
        float bestX = x, bestY = y;
        double lo = 0, hi = t;
        for (int i = 0; i < 64 && lo < hi; i++) {
            double mid = (lo + hi) / 2;
            float px = (float) (x + mid * mx), py = (float) (y + mid * my);
            if (clear(px, py, w, h, x0, y0, obstacles)) {
                lo = mid;
                bestX = px;
                bestY = py;
            } else {
                hi = mid;
            }
        }
        return new float[] {bestX, bestY};
    }

    private static boolean clear(float x, float y, float w, float h, float x0, float y0, Iterable<Rect> obstacles) {
        for (Rect o : obstacles) {
            if (Collide.rectRect(x, y, w, h, o.x(), o.y(), o.w(), o.h())
                    && !Collide.rectRect(x0, y0, w, h, o.x(), o.y(), o.w(), o.h())) {
                return false;
            }
        }
        return true;
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

    /** The hit seen from the other shape: same time, the normal turned round. */
    private static Hit reversed(Hit hit) {
        if (hit == null || hit.alreadyOverlapping()) {
            return hit;
        }
        return hit(hit.t(), -hit.nx(), -hit.ny());
    }

    /** A hit at time t with the normal (nx, ny) made unit length, and the side it faces. */
    static Hit hit(double t, double nx, double ny) {
        double len = Math.hypot(nx, ny);
        double ux = len > 0 ? nx / len : 0, uy = len > 0 ? ny / len : 0;
        return new Hit((float) Math.min(Math.max(t, 0), 1), (float) ux, (float) uy, sideOf(ux, uy));
    }

    /** The side of an obstacle whose outward normal is (nx, ny); ties go to top or bottom. */
    static Side sideOf(double nx, double ny) {
        if (nx == 0 && ny == 0) {
            return Side.NONE;
        }
        if (Math.abs(ny) >= Math.abs(nx)) {
            return ny < 0 ? Side.TOP : Side.BOTTOM;
        }
        return nx < 0 ? Side.LEFT : Side.RIGHT;
    }

    /**
     * A point moving through the intersection of open slabs {@code lo < t * v < hi}, one per
     * axis: the time it is inside all of them, and the normal of the face entered last.
     * Cyrus-Beck clipping; box against box is two slabs, box against segment three.
     */
    static final class Clip {
        double enter = Double.NEGATIVE_INFINITY;
        double exit = INF;
        double nx;
        double ny;

        /**
         * Adds the slab {@code lo < t * v < hi} across the unit axis (ax, ay). Entering it
         * from below means coming in against the axis, so the face's normal is -axis.
         */
        Clip slab(double lo, double hi, double v, double ax, double ay) {
            double in = slabEnter(lo, hi, v);
            double out = slabExit(lo, hi, v);
            if (in > enter || Double.isNaN(in)) {
                enter = in;
                nx = v > 0 ? -ax : ax;
                ny = v > 0 ? -ay : ay;
            }
            if (out < exit || Double.isNaN(out)) {
                exit = out;
            }
            return this;
        }

        /** Is the point inside every slab at t = 0? */
        boolean insideAtStart() {
            return enter < 0 && exit > 0;
        }
    }

    /** The earliest of several candidate entries, and whether any started inside already. */
    static final class Best {
        double t = INF;
        double nx;
        double ny;
        boolean inside;

        void clip(Clip clip, double limit) {
            if (clip.insideAtStart()) {
                inside = true;
            }
            offer(firstTime(clip.enter, clip.exit, limit), clip.nx, clip.ny);
        }

        /** A point {@code d + t v} entering the open disc of radius reach around the origin. */
        void disc(double dx, double dy, double vx, double vy, double reach, double limit) {
            double te = discEntry(dx, dy, vx, vy, reach, limit);
            if (te == Double.NEGATIVE_INFINITY) {
                inside = true;
            } else {
                offer(te, dx + te * vx, dy + te * vy);
            }
        }

        void offer(double te, double ex, double ey) {
            if (te < t) {
                t = te;
                nx = ex;
                ny = ey;
            }
        }

        Hit hit() {
            if (inside) {
                return OVERLAPPING;
            }
            return t == INF ? null : Sweep.hit(t, nx, ny);
        }
    }
}
