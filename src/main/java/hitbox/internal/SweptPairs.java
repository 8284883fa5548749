package hitbox.internal;

import hitbox.*;

/**
 * The swept pairs behind {@link Sweep}: each pair's entry into the obstacle in exact
 * {@code double} (slabs for boxes, discs for round parts), and the step from that exact
 * entry to the float {@code t} Sweep promises: the largest float at which the mover, moved
 * as a sketch moves it, does not overlap.
 */
public final class SweptPairs {
    private SweptPairs() {
    }

    /** The answer when the shapes already overlap at the start. */
    public static final Hit OVERLAPPING = new Hit(0, 0, 0, Side.NONE);

    // ---------------------------------------------------------------- the pairs, as entries
    // Each entry makes its one Earliest first and returns it with nothing found for bad
    // input, never null: one allocation and no merge with null, so the JIT, inlining the
    // entry and the search into the Sweep method, can keep it in registers.

    /** Time of impact of two boxes in double, the motion given in double; 0 if overlapping. */
    public static double rectRectTime(float x, float y, float w, float h, double vx, double vy,
                               float ox, float oy, float ow, float oh) {
        if (!(w >= 0 && h >= 0 && ow >= 0 && oh >= 0)) {
            return Slabs.INF;  // a negative size (or NaN) is no box: no hit, as documented
        }
        if (Collide.rectRect(x, y, w, h, ox, oy, ow, oh)) {
            return 0;
        }
        if (!Discs.finite(vx, vy)) {
            return Slabs.INF;
        }
        // The same sums as Collide.rectRect, so the signs agree exactly with it.
        return Slabs.boxTime(ox - ((double) x + w), ((double) ox + ow) - x,
                oy - ((double) y + h), ((double) oy + oh) - y, vx, vy, 1);
    }

    /** Box against box, with the face entered; the motion in double (the rest of a move). */
    public static Earliest rectRectEntry(float x, float y, float w, float h, double vx, double vy,
                                  float ox, float oy, float ow, float oh) {
        Earliest e = new Earliest();
        if (!(w >= 0 && h >= 0 && ow >= 0 && oh >= 0)) {
            return e;  // a negative size (or NaN) is no box: no entry, as documented
        }
        if (Collide.rectRect(x, y, w, h, ox, oy, ow, oh)) {
            e.inside = true;
        } else if (Discs.finite(vx, vy)) {
            e.clip(Slabs.box(ox - ((double) x + w), ((double) ox + ow) - x,
                    oy - ((double) y + h), ((double) oy + oh) - y, vx, vy), 1);
        }
        return e;
    }

    public static Earliest circleCircleEntry(float x, float y, float r, float vx, float vy,
                                              float ox, float oy, float or) {
        Earliest e = new Earliest();
        if (Check.notFinite(x, y, r, vx, vy) || Check.notFinite(ox, oy, or, 0, 0) || r < 0 || or < 0) {
            return e;  // no entry (a negative radius is no circle, as documented)
        }
        if (Collide.circleCircle(x, y, r, ox, oy, or)) {
            e.inside = true;
        } else {
            e.disc((double) x - ox, (double) y - oy, vx, vy, (double) r + or, 1);
        }
        return e;
    }

    public static Earliest circleRectEntry(float cx, float cy, float r, float vx, float vy,
                                            float rx, float ry, float rw, float rh) {
        Earliest e = new Earliest();
        if (Check.notFinite(cx, cy, r, vx, vy) || Check.notFinite(rx, ry, rw, rh, 0) || r < 0 || rw < 0 || rh < 0) {
            return e;  // no entry (a negative size is no shape, as documented)
        }
        if (Collide.circleRect(cx, cy, r, rx, ry, rw, rh)) {
            e.inside = true;
            return e;
        }
        double left = rx, right = (double) rx + rw, top = ry, bottom = (double) ry + rh;
        // The rounded box is the union of two crossing boxes and four corner circles; the
        // first entry into the union is the first entry into any of them. Where a box and a
        // corner circle are entered at the same moment the point is where the circle meets
        // the box's real face, so the circles go first (ties keep the first), and each box
        // puts its real faces first: the wide box's are left and right, the tall box's top
        // and bottom.
        e.disc(cx - left, cy - top, vx, vy, r, 1);
        e.disc(cx - right, cy - top, vx, vy, r, 1);
        e.disc(cx - left, cy - bottom, vx, vy, r, 1);
        e.disc(cx - right, cy - bottom, vx, vy, r, 1);
        e.clip(new Slabs.Clip()
                .slab(left - r - cx, right + r - cx, vx, 1, 0)
                .slab(top - cy, bottom - cy, vy, 0, 1), 1);
        e.clip(new Slabs.Clip()
                .slab(top - r - cy, bottom + r - cy, vy, 0, 1)
                .slab(left - cx, right - cx, vx, 1, 0), 1);
        return e;
    }

    public static Earliest rectSegmentEntry(float x, float y, float w, float h, float vx, float vy,
                                             float x1, float y1, float x2, float y2) {
        Earliest e = new Earliest();
        if (Check.notFinite(x, y, w, h, vx) || Check.notFinite(vy, x1, y1, x2, y2) || !(w > 0 && h > 0)) {
            return e;  // no entry
        }
        double left = x, right = (double) x + w, top = y, bottom = (double) y + h;
        Slabs.Clip clip = new Slabs.Clip()
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
        e.clip(clip, 1);
        return e;
    }

    public static Earliest circleSegmentEntry(float cx, float cy, float r, float vx, float vy,
                                               float x1, float y1, float x2, float y2) {
        Earliest e = new Earliest();
        if (Check.notFinite(cx, cy, r, vx, vy) || Check.notFinite(x1, y1, x2, y2, 0) || !(r > 0)) {
            return e;  // no entry
        }
        // End circles first: at a tie the point is where an end circle meets the face, and
        // the circle's normal is the true one there.
        e.disc((double) cx - x1, (double) cy - y1, vx, vy, r, 1);
        e.disc((double) cx - x2, (double) cy - y2, vx, vy, r, 1);
        double ex = (double) x2 - x1, ey = (double) y2 - y1;
        double len2 = ex * ex + ey * ey;
        if (len2 > 0) {
            double len = Math.sqrt(len2);
            double px = (double) cx - x1, py = (double) cy - y1;
            double across = -ey * px + ex * py;
            double along = ex * px + ey * py;
            double half = r * len;
            e.clip(new Slabs.Clip()
                    .slab(-half - across, half - across, -ey * vx + ex * vy, -ey / len, ex / len)
                    .slab(-along, len2 - along, ex * vx + ey * vy, ex / len, ey / len), 1);
        }
        return e;
    }

    /**
     * Is a box at (mx, my), moving by (vx, vy), past the obstacle box: beyond it on an axis
     * it moves along, by the sums {@link Collide#rectRect} makes? Then it does not overlap
     * it, and no later float position does (see {@link Search#answer(boolean, boolean)}).
     */
    public static boolean rectPast(float mx, float my, float w, float h, float vx, float vy,
                                   float ox, float oy, float ow, float oh) {
        return vx > 0 && !(mx < (double) ox + ow) || vx < 0 && !((double) mx + w > ox)
                || vy > 0 && !(my < (double) oy + oh) || vy < 0 && !((double) my + h > oy);
    }

    // ---------------------------------------------------------------- from entry to answer

    /** Does the mover, moved by {@code t} times its motion in float, overlap the obstacle? */
    @FunctionalInterface
    public interface OverlapAt {
        boolean at(float t);
    }

    /** A hit at time t with the normal (nx, ny) made unit length, and the side it points into. */
    public static Hit hit(float t, double nx, double ny) {
        double len = Math.hypot(nx, ny);
        double ux = len > 0 ? nx / len : 0, uy = len > 0 ? ny / len : 0;
        return new Hit(t, (float) ux, (float) uy, Side.ofNormal(ux, uy));
    }

    /**
     * The largest float t in [0, 1] at which the mover does not overlap, while at the next
     * float up it does, searched near the exact entry {@code te} (see {@link Search}): for
     * callers whose overlap test is not worth writing out as the search's loop.
     */
    public static float lastClear(double te, OverlapAt overlapAt) {
        Search s = new Search(te, false);
        while (s.searching()) {
            s.answer(overlapAt.at(s.t()));
        }
        return s.t();
    }

    /**
     * The search for the promised t, asked one float at a time, so that the caller's loop
     * holds its own overlap test: {@code while (s.searching()) s.answer(overlaps(s.t()));}
     * then {@code s.t()} is the answer ({@link Float#POSITIVE_INFINITY} for no entry), or
     * {@link #hit} the hit. Written as a loop in the caller, with no test object
     * handed in, the JIT inlines these small methods and keeps the search in registers: a
     * sweep allocates nothing but its answer (a shared search method taking the test as a
     * lambda grew too big to inline, and every call allocated the lambda).
     *
     * <p>The search: the largest float t in [0, 1] at which the mover does not overlap, while
     * at the next float up it does, searched near the exact entry {@code te}: down from it
     * while the float position overlaps, up from it while it does not, the distance from
     * {@code te} doubling from one float step, then halving the gap between a clear t and an
     * overlapping one (floats in [0, 1] are ordered like their bits). The steps grow from the
     * exact entry, not from 0, so they cannot jump over the time the mover spends inside a
     * thin obstacle (unless that time is shorter than the rounding of the float positions, a
     * graze, when no float position overlaps). The start is known to be clear. 1 if no float
     * position up to the end overlaps.
     */
    public static final class Search {
        private static final int START = 0, DOWN = 1, UP = 2, HALVE = 3, DONE = 4;

        private final float start;
        /** How far from the start the next step down or up goes. */
        private double d;
        /**
         * The latest float known clear (and not past the obstacle), and the earliest known to
         * overlap or to be past it, as the walk finds them.
         */
        private float clear;
        private float hit;
        /** Was {@link #hit} found past the obstacle rather than overlapping it? */
        private boolean hitPast;
        private int phase;
        /** The float to ask about next; once done, the answer. */
        private float t;

        /**
         * A search from the entry te (clamped to [0, 1]); none for te = +infinity (no entry:
         * the answer is +infinity) or -infinity (inside at the start: the answer is 0). With
         * {@code exactEntry} (te from exact slabs and discs, where 0 means touching at the
         * start and moving in), none for te = 0 either: the answer is 0, decided here, not the
         * hair above 0 that the walk would find while the float positions have not yet moved
         * ({@link Hit}'s promise). A search from an entry only bounded (conservative
         * advancement) walks from 0 as from any entry; its caller turns a t at which the
         * mover has not moved into 0 itself.
         */
        public Search(double te, boolean exactEntry) {
            start = (float) Math.min(Math.max(te, 0), 1);
            d = Math.ulp(start);
            t = te == Slabs.INF ? Float.POSITIVE_INFINITY : start;  // -infinity (and an exact 0) gave 0
            phase = te == Slabs.INF || te == Double.NEGATIVE_INFINITY || exactEntry && te == 0 ? DONE : START;
        }

        /** A search from exact entry e (see {@link #Search(double, boolean)}), for {@link #hit}. */
        public Search(Earliest e) {
            this(!e.found() ? Slabs.INF : e.inside ? Double.NEGATIVE_INFINITY : e.t, true);
        }

        /**
         * The answer as a hit, once done, with entry e's normal (the entry searched from):
         * null for no entry, an already-overlapping hit if the shapes overlap at the start,
         * else the promised t and the normal from the mover into the obstacle. The entry's
         * normal is the obstacle's outward one, or, when the roles were swapped to compute it
         * ({@code swapped}), the mover's own outward one. (The entry is not kept in the
         * search: the JIT keeps one object in registers more readily than one held by another.)
         */
        public Hit hit(Earliest e, boolean swapped) {
            if (t == Float.POSITIVE_INFINITY) {
                return null;
            }
            if (e.inside) {
                return SweptPairs.OVERLAPPING;
            }
            double sign = swapped ? 1 : -1;
            return SweptPairs.hit(t, sign * e.nx, sign * e.ny);
        }

        /** Is there a float still to ask about (at {@link #t()})? */
        public boolean searching() {
            return phase != DONE;
        }

        /** The float to ask about next, or the answer once the search is done. */
        public float t() {
            return t;
        }

        /**
         * Does the mover, moved by {@link #t()} times its motion in float, overlap? One
         * method with no calls that take the search along, so that it inlines whole even
         * where a branch is rarely taken: a call left out of line would make the search
         * escape, and every sweep allocate it.
         */
        public void answer(boolean overlaps) {
            answer(overlaps, false);
        }

        /**
         * {@link #answer(boolean)} with more to go on: is the mover at {@link #t()}, if it does
         * not overlap, already <em>past</em> the obstacle (beyond it along an axis it moves
         * on, so that no later float position overlaps either)? A pair whose overlap is a
         * set of monotone conditions on the float positions (two boxes) overlaps on one
         * interval of floats, with "clear and not past" below it and "past" above it: the
         * walk then stops at a past position as at an overlapping one, and cannot jump over
         * an overlap that rounding of the positions has made much shorter than the exact one
         * (a box far from the origin, whose y moves in steps of 1/16). A search that ends
         * between a clear float and a past one found no overlapping float: a graze, 1.
         */
        public void answer(boolean overlaps, boolean past) {
            boolean above = overlaps || past;
            if (above) {
                hit = t;
                hitPast = !overlaps;
            } else {
                clear = t;
            }
            if (phase == START) {
                phase = above ? DOWN : UP;  // the first answer picks the walk's way
            } else if (phase == DOWN && above || phase == UP && !above) {
                d *= 2;  // the walk goes on, twice as far from the start
            } else {
                phase = HALVE;  // a clear t and an overlapping one: halve between them
            }
            if (phase == DOWN) {
                if (hit == 0) {
                    phase = DONE;  // overlapping at the start: callers rule that out
                    t = 0;
                } else {
                    float lower = (float) Math.max(start - d, 0);
                    t = lower >= hit ? Math.nextDown(hit) : lower;
                }
            } else if (phase == UP) {
                if (clear >= 1) {
                    phase = DONE;
                    t = 1;
                } else {
                    float higher = (float) Math.min(start + d, 1);
                    t = higher <= clear ? Math.nextUp(clear) : higher;
                }
            } else {
                int lo = Float.floatToRawIntBits(clear);
                int hi = Float.floatToRawIntBits(hit);
                if (hi - lo > 1) {
                    t = Float.intBitsToFloat((lo + hi) >>> 1);
                } else {
                    phase = DONE;
                    t = hitPast ? 1 : clear;
                }
            }
        }
    }
}
