package hitbox.internal;

import hitbox.*;

/**
 * The swept pairs behind {@link Sweep}: each pair's entry into the obstacle in exact
 * {@code double} (slabs for boxes, discs for round parts), and the step from that exact
 * entry to the float {@code t} Sweep promises: the largest float at which the mover, moved
 * as a sketch moves it, does not overlap.
 *
 * <p>This class is longer than most (about 930 lines) because it holds both halves of every
 * swept pair, the exact entries (each also grown by the rounding slack of the float
 * positions) and the two ways from an entry to the promised float: visiting the float
 * positions one by one ({@link #answer}) and the walk ({@link Search}), with the thread's
 * entries, walk and overlap tests they work in, and the hit each sweep ends with (made, or
 * kept as numbers in the same scratch for a caller that asks many: {@link #recording});
 * split, each half would be a list of pairs that only the other half reads.
 */
public final class SweptPairs {
    private SweptPairs() {
    }

    /** The answer when the shapes already overlap at the start. */
    public static final Hit OVERLAPPING = new Hit(0, 0, 0, Side.NONE);

    // ---------------------------------------------------------------- a thread's scratch
    // A sweep makes nothing but its Hit: its entries, its walk and its overlap test are a
    // thread's own objects, reset for each sweep. An exact entry is always the thread's
    // exact one, a grown entry its grown one, so that a sweep holds both at once; nothing
    // here sweeps again while a caller holds them (a sweep's overlap tests do not sweep).

    /** A thread's exact and grown entries, its clip, its walk and its overlap test of a moved pair. */
    private static final class Scratch {
        final Earliest exact = new Earliest(), grown = new Earliest();
        final Slabs.Clip clip = new Slabs.Clip();
        final Search search = new Search(Slabs.INF, false);
        final Moved moved = new Moved();
        // The recorded answer (see recording).
        boolean recording;
        float t, nx, ny;
        Side side;
    }

    private static final ThreadLocal<Scratch> SCRATCH = ThreadLocal.withInitial(Scratch::new);

    /** The thread's exact entry, reset: found nothing yet (for an entry worked out elsewhere, as {@link #grownEntry}). */
    public static Earliest exactEntry() {
        return SCRATCH.get().exact.reset();
    }

    /** The thread's clip, emptied, for one entry to read at once ({@link Earliest#clip}). */
    private static Slabs.Clip clip() {
        return SCRATCH.get().clip.reset();
    }

    /** {@link Slabs#box} in the thread's clip. */
    private static Slabs.Clip box(double loX, double hiX, double loY, double hiY, double vx, double vy) {
        return Slabs.box(clip(), loX, hiX, loY, hiY, vx, vy);
    }

    /** The thread's grown entry, reset, for the entries grown by the rounding slack. */
    public static Earliest grownEntry() {
        return SCRATCH.get().grown.reset();
    }

    /**
     * The thread's walk, started from te as {@link Search#Search(double, boolean)} starts,
     * for a caller that writes the walk's loop out (no other walk may be in use meanwhile).
     */
    public static Search search(double te, boolean exactEntry) {
        return SCRATCH.get().search.reset(te, exactEntry);
    }

    // ---------------------------------------------------------------- the pairs, as entries
    // Each entry takes the thread's entry (exact or grown) and returns it with nothing found
    // for bad input, never null.

    /** Time of impact of two boxes in double, the motion given in double; 0 if overlapping. */
    public static double rectRectTime(float x, float y, float w, float h, double vx, double vy,
                               float ox, float oy, float ow, float oh) {
        if (!(w >= 0 && h >= 0 && ow >= 0 && oh >= 0)) {
            return Slabs.INF;  // a negative size (or NaN) is no box: no hit, as documented
        }
        if (RawTests.rectRect(x, y, w, h, ox, oy, ow, oh)) {
            return 0;
        }
        if (!Discs.finite(vx, vy)) {
            return Slabs.INF;
        }
        // The same sums as RawTests.rectRect, so the signs agree exactly with it.
        return Slabs.boxTime(ox - ((double) x + w), ((double) ox + ow) - x,
                oy - ((double) y + h), ((double) oy + oh) - y, vx, vy, 1);
    }

    /** Box against box, with the face entered; the motion in double (the rest of a move). */
    public static Earliest rectRectEntry(float x, float y, float w, float h, double vx, double vy,
                                  float ox, float oy, float ow, float oh) {
        Earliest e = exactEntry();
        if (!(w >= 0 && h >= 0 && ow >= 0 && oh >= 0)) {
            return e;  // a negative size (or NaN) is no box: no entry, as documented
        }
        if (RawTests.rectRect(x, y, w, h, ox, oy, ow, oh)) {
            e.inside = true;
        } else if (Discs.finite(vx, vy)) {
            e.clip(box(ox - ((double) x + w), ((double) ox + ow) - x,
                    oy - ((double) y + h), ((double) oy + oh) - y, vx, vy), 1);
        }
        return e;
    }

    public static Earliest circleCircleEntry(float x, float y, float r, float vx, float vy,
                                              float ox, float oy, float or) {
        Earliest e = exactEntry();
        if (Check.notFinite(x, y, r, vx, vy) || Check.notFinite(ox, oy, or, 0, 0) || r < 0 || or < 0) {
            return e;  // no entry (a negative radius is no circle, as documented)
        }
        if (RawTests.circleCircle(x, y, r, ox, oy, or)) {
            e.inside = true;
        } else {
            e.disc((double) x - ox, (double) y - oy, vx, vy, (double) r + or, 1);
        }
        return e;
    }

    /**
     * Circle against circle with the summed radius grown by {@code grow}: the earliest time
     * the mover, displaced by up to grow, can overlap (see {@link #answer}); inside at the
     * start for a start already within grow.
     */
    public static Earliest circleCircleGrown(float x, float y, float r, float vx, float vy,
                                             float ox, float oy, float or, double grow) {
        Earliest e = grownEntry();
        e.disc((double) x - ox, (double) y - oy, vx, vy, (double) r + or + grow, 1);
        return e;
    }

    public static Earliest circleRectEntry(float cx, float cy, float r, float vx, float vy,
                                            float rx, float ry, float rw, float rh) {
        Earliest e = exactEntry();
        if (Check.notFinite(cx, cy, r, vx, vy) || Check.notFinite(rx, ry, rw, rh, 0) || r < 0 || rw < 0 || rh < 0) {
            return e;  // no entry (a negative size is no shape, as documented)
        }
        if (RawTests.circleRect(cx, cy, r, rx, ry, rw, rh)) {
            e.inside = true;
            return e;
        }
        return circleRectGrown(e, cx, cy, r, 0, 0, vx, vy, rx, ry, rw, rh);
    }

    /**
     * The entry into the rectangle grown by the radius {@code r}, into e; with gx, gy not 0,
     * into that rounded box grown by gx across and gy up and down (the corner discs by
     * gx + gy), for the earliest time a centre displaced that much can overlap (see
     * {@link #answer}).
     */
    public static Earliest circleRectGrown(Earliest e, float cx, float cy, float r, double gx, double gy,
                                           float vx, float vy, float rx, float ry, float rw, float rh) {
        double left = rx - gx, right = (double) rx + rw + gx, top = ry - gy, bottom = (double) ry + rh + gy;
        double rd = r + gx + gy;
        // The rounded box is the union of two crossing boxes and four corner circles; the
        // first entry into the union is the first entry into any of them. Where a box and a
        // corner circle are entered at the same moment the point is where the circle meets
        // the box's real face, so the circles go first (ties keep the first), and each box
        // puts its real faces first: the wide box's are left and right, the tall box's top
        // and bottom.
        double cl = (double) rx, cr = (double) rx + rw, ct = ry, cb = (double) ry + rh;
        e.disc(cx - cl, cy - ct, vx, vy, rd, 1);
        e.disc(cx - cr, cy - ct, vx, vy, rd, 1);
        e.disc(cx - cl, cy - cb, vx, vy, rd, 1);
        e.disc(cx - cr, cy - cb, vx, vy, rd, 1);
        e.clip(clip()
                .slab(left - r - cx, right + r - cx, vx, 1, 0)
                .slab(top - cy, bottom - cy, vy, 0, 1), 1);
        e.clip(clip()
                .slab(top - r - cy, bottom + r - cy, vy, 0, 1)
                .slab(left - cx, right - cx, vx, 1, 0), 1);
        return e;
    }

    public static Earliest rectSegmentEntry(float x, float y, float w, float h, float vx, float vy,
                                             float x1, float y1, float x2, float y2) {
        return rectSegmentEntry(exactEntry(), x, y, w, h, vx, vy, x1, y1, x2, y2, 0, 0);
    }

    /**
     * Box against segment with the box displaced by up to gx across and gy up and down (0, 0:
     * the exact entry): each axis's interval grown by what the displacement can move it, for
     * the earliest time a displaced box can meet the segment (see {@link #answer}).
     */
    public static Earliest rectSegmentEntry(float x, float y, float w, float h, float vx, float vy,
                                            float x1, float y1, float x2, float y2, double gx, double gy) {
        return rectSegmentEntry(grownEntry(), x, y, w, h, vx, vy, x1, y1, x2, y2, gx, gy);
    }

    private static Earliest rectSegmentEntry(Earliest e, float x, float y, float w, float h, float vx, float vy,
                                             float x1, float y1, float x2, float y2, double gx, double gy) {
        if (Check.notFinite(x, y, w, h, vx) || Check.notFinite(vy, x1, y1, x2, y2) || !(w > 0 && h > 0)) {
            return e;  // no entry
        }
        double left = x, right = (double) x + w, top = y, bottom = (double) y + h;
        Slabs.Clip clip = clip()
                .slab(Math.min(y1, y2) - bottom - gy, Math.max(y1, y2) - top + gy, vy, 0, 1)
                .slab(Math.min(x1, x2) - right - gx, Math.max(x1, x2) - left + gx, vx, 1, 0);
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
            double g = Math.abs(nx) * gx + Math.abs(ny) * gy;
            clip.slab(s - hi - g, s - lo + g, nx * vx + ny * vy, nx / len, ny / len);
        }
        e.clip(clip, 1);
        return e;
    }

    public static Earliest circleSegmentEntry(float cx, float cy, float r, float vx, float vy,
                                               float x1, float y1, float x2, float y2) {
        return circleSegmentEntry(exactEntry(), cx, cy, r, vx, vy, x1, y1, x2, y2, 0, 0);
    }

    /**
     * Circle against segment with the centre displaced by up to gx across and gy up and down
     * (0, 0: the exact entry): the end discs grown by gx + gy, the across and along slabs by
     * what the displacement can move them, for the earliest time a displaced circle can meet
     * the segment (see {@link #answer}).
     */
    public static Earliest circleSegmentEntry(float cx, float cy, float rf, float vx, float vy,
                                              float x1, float y1, float x2, float y2, double gx, double gy) {
        return circleSegmentEntry(grownEntry(), cx, cy, rf, vx, vy, x1, y1, x2, y2, gx, gy);
    }

    private static Earliest circleSegmentEntry(Earliest e, float cx, float cy, float rf, float vx, float vy,
                                               float x1, float y1, float x2, float y2, double gx, double gy) {
        if (Check.notFinite(cx, cy, rf, vx, vy) || Check.notFinite(x1, y1, x2, y2, 0) || !(rf > 0)) {
            return e;  // no entry
        }
        double r = rf;
        double rEnds = rf + gx + gy;
        // End circles first: at a tie the point is where an end circle meets the face, and
        // the circle's normal is the true one there.
        e.disc((double) cx - x1, (double) cy - y1, vx, vy, rEnds, 1);
        e.disc((double) cx - x2, (double) cy - y2, vx, vy, rEnds, 1);
        double ex = (double) x2 - x1, ey = (double) y2 - y1;
        double len2 = ex * ex + ey * ey;
        if (len2 > 0) {
            double len = Math.sqrt(len2);
            double px = (double) cx - x1, py = (double) cy - y1;
            double across = -ey * px + ex * py;
            double along = ex * px + ey * py;
            double half = r * len + Math.abs(ey) * gx + Math.abs(ex) * gy;
            double ga = Math.abs(ex) * gx + Math.abs(ey) * gy;
            e.clip(clip()
                    .slab(-half - across, half - across, -ey * vx + ex * vy, -ey / len, ex / len)
                    .slab(-along - ga, len2 - along + ga, ex * vx + ey * vy, ex / len, ey / len), 1);
        }
        return e;
    }

    /**
     * Circle (radius above 0) against a polygon's outline (no NaN, convex or not), into e: the earliest
     * of its entries into the capsules round the polygon's edges, each as
     * {@link #circleSegmentEntry(float, float, float, float, float, float, float, float, float, double, double)}
     * (with gx and gy the centre's displacement, 0 for the exact entry). A centre that starts
     * outside cannot come within the circle's radius of the polygon's inside without first
     * coming that close to its outline, so the earliest entry is the pair's; and a path
     * that reaches the polygon's inside crosses its outline inside some capsule, so the float
     * positions that overlap first come before the capsules' latest exit.
     */
    public static Earliest circlePolygonEntry(Earliest e, float cx, float cy, float r, float vx, float vy, float[] xy,
                                             double gx, double gy) {
        int n = xy.length / 2;
        for (int i = 0, h = n - 1; i < n; h = i++) {
            circleSegmentEntry(e, cx, cy, r, vx, vy, xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], gx, gy);
        }
        return e;
    }

    /**
     * Box against box with the Minkowski box's intervals grown by {@code gx} and {@code gy}
     * on both sides: the earliest time a box displaced by up to grow can overlap (see
     * {@link #answer}); inside at the start for a start already within grow.
     */
    public static Earliest rectRectGrown(float x, float y, float w, float h, float vx, float vy,
                                         float ox, float oy, float ow, float oh, double gx, double gy) {
        Earliest e = grownEntry();
        if (!(w >= 0 && h >= 0 && ow >= 0 && oh >= 0)) {
            return e;
        }
        e.clip(box(ox - ((double) x + w) - gx, ((double) ox + ow) - x + gx,
                oy - ((double) y + h) - gy, ((double) oy + oh) - y + gy, vx, vy), 1);
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

    /**
     * The overlap tests of the pairs on plain floats, as {@link #answer} asks them, written
     * once as a thread's object: set for one sweep by the methods below, it makes nothing a
     * lambda capturing the sweep's floats would (one per sweep; too big a method to inline,
     * {@link #answer} let it escape). Each test moves the mover's coordinates {@code x + u * vx},
     * {@code y + u * vy} in float, as a sketch moves them, and keeps the rest as given.
     */
    private static final class Moved implements OverlapAt {
        static final int CIRCLE_CIRCLE = 0, CIRCLE_RECT = 1, RECT_CIRCLE = 2, RECT_SEGMENT = 3,
                CIRCLE_SEGMENT = 4, SEGMENT_RECT = 5, SEGMENT_CIRCLE = 6, RECT_CONVEX = 7, CIRCLE_POLYGON = 8;
        private int pair;
        /** A standing polygon's outline (convex, with its winding, for RECT_CONVEX; any for CIRCLE_POLYGON); else null and 0. */
        private float[] outline;
        private int winding;
        /** The mover's moving coordinates (a segment's two ends) and its motion. */
        private float x, y, x2, y2, vx, vy;
        /** The standing arguments, in the order the test takes them. */
        private float f0, f1, f2, f3, f4, f5;

        Moved set(int pair, float x, float y, float x2, float y2, float vx, float vy,
                  float f0, float f1, float f2, float f3, float f4, float f5) {
            this.pair = pair;
            this.x = x;
            this.y = y;
            this.x2 = x2;
            this.y2 = y2;
            this.vx = vx;
            this.vy = vy;
            this.f0 = f0;
            this.f1 = f1;
            this.f2 = f2;
            this.f3 = f3;
            this.f4 = f4;
            this.f5 = f5;
            this.outline = null;
            this.winding = 0;
            return this;
        }

        @Override
        public boolean at(float u) {
            return switch (pair) {
                case CIRCLE_CIRCLE -> RawTests.circleCircle(x + u * vx, y + u * vy, f0, f1, f2, f3);
                case CIRCLE_RECT -> RawTests.circleRect(x + u * vx, y + u * vy, f0, f1, f2, f3, f4);
                case RECT_CIRCLE -> RawTests.circleRect(f0, f1, f2, x + u * vx, y + u * vy, f3, f4);
                case RECT_SEGMENT -> RawTests.lineRect(f0, f1, f2, f3, x + u * vx, y + u * vy, f4, f5);
                case CIRCLE_SEGMENT -> RawTests.lineCircle(f0, f1, f2, f3, x + u * vx, y + u * vy, f4);
                case SEGMENT_RECT -> RawTests.lineRect(x + u * vx, y + u * vy, x2 + u * vx, y2 + u * vy, f0, f1, f2, f3);
                case RECT_CONVEX -> Polygons.convexRectOverlap(outline, winding, x + u * vx, y + u * vy, f0, f1);
                case CIRCLE_POLYGON -> RawTests.polygonCircle(outline, x + u * vx, y + u * vy, f0);
                default -> RawTests.lineCircle(x + u * vx, y + u * vy, x2 + u * vx, y2 + u * vy, f0, f1, f2);
            };
        }
    }

    private static Moved moved() {
        return SCRATCH.get().moved;
    }

    /** A circle at (x, y) moved by u (vx, vy): does it overlap the circle (ox, oy, or)? The thread's test, set. */
    public static OverlapAt circleCircleAt(float x, float y, float r, float vx, float vy, float ox, float oy, float or) {
        return moved().set(Moved.CIRCLE_CIRCLE, x, y, 0, 0, vx, vy, r, ox, oy, or, 0, 0);
    }

    /** A circle at (cx, cy) moved by u (vx, vy) against a standing rectangle. */
    public static OverlapAt circleRectAt(float cx, float cy, float r, float vx, float vy,
                                         float rectX, float rectY, float rectW, float rectH) {
        return moved().set(Moved.CIRCLE_RECT, cx, cy, 0, 0, vx, vy, r, rectX, rectY, rectW, rectH, 0);
    }

    /** A rectangle at (x, y) moved by u (vx, vy) against a standing circle. */
    public static OverlapAt rectCircleAt(float x, float y, float w, float h, float vx, float vy, float cx, float cy, float r) {
        return moved().set(Moved.RECT_CIRCLE, x, y, 0, 0, vx, vy, cx, cy, r, w, h, 0);
    }

    /** A rectangle at (x, y) moved by u (vx, vy) against a standing segment. */
    public static OverlapAt rectSegmentAt(float x, float y, float w, float h, float vx, float vy,
                                          float x1, float y1, float x2, float y2) {
        return moved().set(Moved.RECT_SEGMENT, x, y, 0, 0, vx, vy, x1, y1, x2, y2, w, h);
    }

    /** A circle at (cx, cy) moved by u (vx, vy) against a standing segment. */
    public static OverlapAt circleSegmentAt(float cx, float cy, float r, float vx, float vy,
                                            float x1, float y1, float x2, float y2) {
        return moved().set(Moved.CIRCLE_SEGMENT, cx, cy, 0, 0, vx, vy, x1, y1, x2, y2, r, 0);
    }

    /** A segment moved by u (vx, vy) against a standing rectangle. */
    public static OverlapAt segmentRectAt(float x1, float y1, float x2, float y2, float vx, float vy,
                                          float rectX, float rectY, float rectW, float rectH) {
        return moved().set(Moved.SEGMENT_RECT, x1, y1, x2, y2, vx, vy, rectX, rectY, rectW, rectH, 0, 0);
    }

    /**
     * A rectangle with area at (x, y) moved by u (vx, vy) against a standing convex polygon
     * (its outline and its winding, not 0), tested with no rectangle made.
     */
    public static OverlapAt rectConvexAt(float x, float y, float w, float h, float vx, float vy,
                                         float[] outline, int winding) {
        Moved m = moved().set(Moved.RECT_CONVEX, x, y, 0, 0, vx, vy, w, h, 0, 0, 0, 0);
        m.outline = outline;
        m.winding = winding;
        return m;
    }

    /** A circle at (cx, cy) moved by u (vx, vy) against a standing polygon (its outline). */
    public static OverlapAt circlePolygonAt(float cx, float cy, float r, float vx, float vy, float[] outline) {
        Moved m = moved().set(Moved.CIRCLE_POLYGON, cx, cy, 0, 0, vx, vy, r, 0, 0, 0, 0, 0);
        m.outline = outline;
        return m;
    }

    /** A segment moved by u (vx, vy) against a standing circle. */
    public static OverlapAt segmentCircleAt(float x1, float y1, float x2, float y2, float vx, float vy,
                                            float cx, float cy, float r) {
        return moved().set(Moved.SEGMENT_CIRCLE, x1, y1, x2, y2, vx, vy, cx, cy, r, 0, 0, 0);
    }

    /** Does the mover, moved by {@code t} times its motion in float, overlap the obstacle? */
    @FunctionalInterface
    public interface OverlapAt {
        boolean at(float t);
    }

    /**
     * A hit at time t with the normal (nx, ny) made unit length, and the side it points into;
     * while the thread records ({@link #recording}), put in its scratch instead, and
     * {@link #RECORDED} handed back.
     */
    public static Hit hit(float t, double nx, double ny) {
        double len = Math.hypot(nx, ny);
        double ux = len > 0 ? nx / len : 0, uy = len > 0 ? ny / len : 0;
        Scratch s = SCRATCH.get();
        if (s.recording) {
            s.t = t;
            s.nx = (float) ux;
            s.ny = (float) uy;
            s.side = Side.ofNormal(ux, uy);
            return RECORDED;
        }
        return new Hit(t, (float) ux, (float) uy, Side.ofNormal(ux, uy));
    }

    // ---------------------------------------------------------------- answers kept as numbers
    // A caller that asks many sweeps for one answer (the world's mover asks every candidate
    // of every leg, and keeps the first) takes their answers as numbers: while the thread
    // records, a sweep's hit within the motion goes into the thread's scratch and RECORDED
    // is handed back in place of a new Hit (null and OVERLAPPING are handed back as ever).
    // A hit is made only as a sweep's last step; the one place that reads a sweep's Hit on
    // the way out (ConvexSweep's look back for two polygons) asks with recording off.

    /** The stand-in for a hit put in the thread's scratch: never handed to a user. */
    private static final Hit RECORDED = new Hit(1, 0, 0, Side.NONE);

    /**
     * Starts ({@code true}) or ends the thread's recording of sweep answers as numbers.
     *
     * @return whether it was recording before, to put back
     */
    public static boolean recording(boolean on) {
        Scratch s = SCRATCH.get();
        boolean was = s.recording;
        s.recording = on;
        return was;
    }

    /**
     * A sweep's answer as numbers: the Hit it handed back, or, for {@link #RECORDED}, the
     * one in the thread's scratch.
     *
     * @param h   the sweep's answer, null for no hit
     * @param out given t, nx and ny of the hit (untouched for no hit)
     * @return the side met ({@link Side#NONE} if the shapes overlapped at the start), or
     *         null for no hit
     */
    public static Side recorded(Hit h, float[] out) {
        if (h == null) {
            return null;
        }
        if (h == RECORDED) {
            Scratch s = SCRATCH.get();
            out[0] = s.t;
            out[1] = s.nx;
            out[2] = s.ny;
            return s.side;
        }
        out[0] = h.t();
        out[1] = h.nx();
        out[2] = h.ny();
        return h.side();
    }

    // ---------------------------------------------------------------- the float positions, visited

    /** The most float positions {@link #firstOverlap} visits before it leaves the rest to {@link Search}. */
    public static final int MAX_POSITIONS = 4096;

    /**
     * How far the float position {@code base + t * v} (t*v rounded, then the sum rounded) can
     * be from the exact {@code base + t v}, for t in [0, 1], at most: half a float step of
     * |v| (t*v lies between 0 and v) plus half a float step of the larger of |base| and
     * |base + v| (the sum lies between them). This bound sets how far back of the exact entry
     * {@link #firstOverlap} starts, and the positions it visits grow with it, so it is the
     * tight one rather than a generous one. +infinity where the sum could leave the float range.
     */
    public static double slack(float base, float v) {
        if (v == 0) {
            return 0;  // base + t * 0 is base, exactly
        }
        float end = Math.max(Math.abs(base), Math.abs(base + v));  // base + v rounded: same float step or the next up
        return 0.5 * Math.ulp(Math.abs(v)) + 0.5 * Math.ulp(end);
    }

    /**
     * {@link #slack} made generous, for the searched pairs (curved shapes, by pieces): a
     * whole float step of |v| and two of |base| + |v|. Their overlap tests decide within
     * their own rounding, which far from the origin reaches a good part of a float step at
     * the scene's largest coordinate, so a float position they call overlapping can lie
     * further from the exact path than the sums alone move it (an ellipse near
     * (954292, 2447025) and one near (-487638, 2192165), pinned in SweepFarFromOriginTest).
     */
    public static double searchedSlack(float base, float v) {
        if (v == 0) {
            return 0;
        }
        float big = 2 * (Math.abs(base) + Math.abs(v));
        return (double) Math.ulp(Math.abs(v)) + Math.ulp(big);
    }

    /**
     * The smallest float t' in (t, 1] at which {@code base + t' * v}, computed in float as a
     * sketch computes it, differs from its value at t; +infinity if none does. The float
     * position is a monotone step function of t, so a guess from the exact crossing of the
     * rounding boundary, corrected a float at a time, finds the step (halving by the bits if
     * the guess was far off).
     */
    public static float nextChange(float t, float base, float v) {
        if (v == 0) {
            return Float.POSITIVE_INFINITY;
        }
        float now = base + t * v;
        if (base + v == now) {
            return Float.POSITIVE_INFINITY;
        }
        float next = v > 0 ? Math.nextUp(now) : Math.nextDown(now);
        float g = (float) ((((double) now + next) / 2 - base) / v);
        g = !(g > t) ? Math.nextUp(t) : Math.min(g, 1f);
        if (base + g * v != now) {
            for (int i = 0; i < 64; i++) {
                float d = Math.nextDown(g);
                if (d <= t || base + d * v == now) {
                    return g;
                }
                g = d;
            }
        } else {
            for (int i = 0; i < 64; i++) {
                g = Math.nextUp(g);
                if (g > 1) {
                    return Float.POSITIVE_INFINITY;
                }
                if (base + g * v != now) {
                    return g;
                }
            }
        }
        int lo = Float.floatToRawIntBits(t), hi = Float.floatToRawIntBits(1f);
        while (hi - lo > 1) {
            int mid = (lo + hi) >>> 1;
            if (base + Float.intBitsToFloat(mid) * v == now) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return Float.intBitsToFloat(hi);
    }

    /** Are the float positions of the (up to) four coordinates the same at t and at u? */
    private static boolean samePosition(float t, float u, float b1, float v1, float b2, float v2,
                                        float b3, float v3, float b4, float v4) {
        return b1 + t * v1 == b1 + u * v1 && b2 + t * v2 == b2 + u * v2
                && b3 + t * v3 == b3 + u * v3 && b4 + t * v4 == b4 + u * v4;
    }

    /**
     * The first float t in [from, 1] at which the mover overlaps, visiting the float
     * positions one by one: every coordinate {@code b + t * v} of the mover (up to four; pass
     * 0, 0 for the unused) is a monotone step function of t, so between two steps of any of
     * them the position, and so the answer of the overlap test, stays the same. Each
     * position is asked about once, at the first float t that reaches it. +infinity if none
     * up to 1 (or up to {@code until}, after which none can) overlaps; NaN if more than {@link #MAX_POSITIONS} were visited without an
     * answer. {@code from} must be a time before which no float position can overlap (the
     * entry of the obstacle grown by the rounding slack); should the one at {@code from}
     * overlap after all, the first float of that position is returned.
     */
    public static float firstOverlap(double from, double until, OverlapAt o, float b1, float v1, float b2, float v2,
                                     float b3, float v3, float b4, float v4) {
        float t = (float) Math.max(from, 0);
        if (t > from) {
            t = Math.max(Math.nextDown(t), 0f);
        }
        if (t > 1) {
            return Float.POSITIVE_INFINITY;
        }
        if (o.at(t)) {
            // The first float with this position: halve on the bits between 0 and t.
            if (samePosition(0, t, b1, v1, b2, v2, b3, v3, b4, v4)) {
                return 0;
            }
            int lo = 0, hi = Float.floatToRawIntBits(t);
            while (hi - lo > 1) {
                int mid = (lo + hi) >>> 1;
                if (samePosition(Float.intBitsToFloat(mid), t, b1, v1, b2, v2, b3, v3, b4, v4)) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            return Float.intBitsToFloat(hi);
        }
        // Each coordinate's next step, worked out again only once the walk has reached it: a
        // coordinate that has not stepped has the same position, so the same next step.
        float n1 = nextChange(t, b1, v1), n2 = nextChange(t, b2, v2), n3 = nextChange(t, b3, v3), n4 = nextChange(t, b4, v4);
        for (int n = 0; n < MAX_POSITIONS; n++) {
            float next = Math.min(Math.min(n1, n2), Math.min(n3, n4));
            if (next > 1 || next > until) {
                return Float.POSITIVE_INFINITY;
            }
            t = next;
            if (o.at(t)) {
                return t;
            }
            n1 = n1 == t ? nextChange(t, b1, v1) : n1;
            n2 = n2 == t ? nextChange(t, b2, v2) : n2;
            n3 = n3 == t ? nextChange(t, b3, v3) : n3;
            n4 = n4 == t ? nextChange(t, b4, v4) : n4;
        }
        return Float.NaN;
    }

    /**
     * {@link #firstOverlap(double, double, OverlapAt, float, float, float, float, float, float,
     * float, float)} for a mover with any number of coordinates: {@code xy} holds them in
     * pairs, each x moving by {@code b + t * vx}, each y by {@code b + t * vy} (a shape moved
     * by {@link Shape#translated}). +infinity if none up to {@code until} (or 1) overlaps,
     * NaN past {@link #MAX_POSITIONS} positions.
     */
    public static float firstOverlap(double from, double until, OverlapAt o, float[] xy, float vx, float vy) {
        float t = (float) Math.max(from, 0);
        if (t > from) {
            t = Math.max(Math.nextDown(t), 0f);
        }
        if (t > 1 || t > until) {
            return Float.POSITIVE_INFINITY;
        }
        if (o.at(t)) {
            return Float.NaN;  // the bound was not one: leave it to the caller's walk
        }
        // Each coordinate's next step, worked out again only once the walk has reached it.
        float[] steps = new float[xy.length];
        for (int i = 0; i < xy.length; i++) {
            steps[i] = nextChange(t, xy[i], (i & 1) == 0 ? vx : vy);
        }
        for (int n = 0; n < MAX_POSITIONS; n++) {
            float next = Float.POSITIVE_INFINITY;
            for (float step : steps) {
                next = Math.min(next, step);
            }
            if (next > 1 || next > until) {
                return Float.POSITIVE_INFINITY;
            }
            t = next;
            if (o.at(t)) {
                return t;
            }
            for (int i = 0; i < xy.length; i++) {
                if (steps[i] == t) {
                    steps[i] = nextChange(t, xy[i], (i & 1) == 0 ? vx : vy);
                }
            }
        }
        return Float.NaN;
    }

    /**
     * The promised t (see {@link Sweep}), +infinity for no hit: 0 if the exact entry e is
     * inside at the start or at exactly 0 (touching and moving in); else the float just below
     * the first float position that overlaps, found by visiting the positions from the entry
     * of the obstacle grown by the rounding slack ({@code grown}: before it no float position
     * can overlap), so that no overlap rounding has shortened, moved or split is walked over;
     * +infinity if the exact path has no entry (hit or not is decided exactly); 1 if no
     * float position overlaps although the exact path enters (a graze). Where more float
     * positions lie between than {@link #MAX_POSITIONS} (a graze near the origin, at a float
     * step far below a pixel), the walk of {@link Search} from e decides.
     */
    public static float answer(Earliest e, Earliest grown, OverlapAt o, float b1, float v1, float b2, float v2,
                               float b3, float v3, float b4, float v4) {
        if (e.inside || e.found() && e.t == 0) {
            return 0;
        }
        if (!e.found()) {
            return Float.POSITIVE_INFINITY;  // hit or not is the exact path's decision (Sweep's class doc)
        }
        if (!grown.found()) {
            return lastClear(e.t, o);  // grown not computable: the walk
        }
        float f = firstOverlap(grown.inside ? 0 : grown.t, grown.until, o, b1, v1, b2, v2, b3, v3, b4, v4);
        if (Float.isNaN(f)) {
            return e.found() ? lastClear(e.t, o) : Float.POSITIVE_INFINITY;
        }
        if (f <= 1) {
            return f > 0 ? Math.nextDown(f) : 0;
        }
        return 1;
    }

    /**
     * Does e alone decide {@link #answer} (no entry, inside at the start, or touching and
     * moving in), so that the grown entry need not be worked out? Most sweeps miss.
     */
    public static boolean decided(Earliest e) {
        return !e.found() || e.inside || e.t == 0;
    }

    /** {@link #answer} for a mover with two coordinates moving. */
    public static float answer(Earliest e, Earliest grown, OverlapAt o, float bx, float vx, float by, float vy) {
        return answer(e, grown, o, bx, vx, by, vy, 0, 0, 0, 0);
    }

    /**
     * The hit for answer t (see {@link #answer}): null for +infinity, {@link #OVERLAPPING}
     * if e is inside at the start, else with e's normal, or the grown entry's where the
     * exact path has no entry (its float positions overlap all the same); the normal from
     * the mover into the obstacle, or the mover's own outward one when {@code swapped}.
     */
    public static Hit hit(float t, Earliest e, Earliest grown, boolean swapped) {
        if (t == Float.POSITIVE_INFINITY) {
            return null;
        }
        if (e.inside) {
            return OVERLAPPING;
        }
        Earliest n = e.found() ? e : grown;
        double sign = swapped ? 1 : -1;
        return hit(t, sign * n.nx, sign * n.ny);
    }

    /**
     * The largest float t in [0, 1] at which the mover does not overlap, while at the next
     * float up it does, searched near the exact entry {@code te} (see {@link Search}): for
     * callers whose overlap test is not worth writing out as the search's loop.
     */
    public static float lastClear(double te, OverlapAt overlapAt) {
        Search s = search(te, false);
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

        private float start;
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
            reset(te, exactEntry);
        }

        /** This walk started again, from te, as {@link #Search(double, boolean)} starts one; returns it. */
        public Search reset(double te, boolean exactEntry) {
            start = (float) Math.min(Math.max(te, 0), 1);
            d = Math.ulp(start);
            clear = 0;
            hit = 0;
            hitPast = false;
            t = te == Slabs.INF ? Float.POSITIVE_INFINITY : start;  // -infinity (and an exact 0) gave 0
            phase = te == Slabs.INF || te == Double.NEGATIVE_INFINITY || exactEntry && te == 0 ? DONE : START;
            return this;
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
