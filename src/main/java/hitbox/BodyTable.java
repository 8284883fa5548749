package hitbox;

import hitbox.internal.*;

import java.util.ArrayList;
import java.util.List;
import java.util.function.IntConsumer;

/**
 * The bodies of a {@link World} with their poses and boxes: their ids (reused after removal)
 * and serials (the order added), the tight box of each (at or a hair outside its shape) and
 * the fat box the broad phase holds, the bodies whose fat box waits to be put there, and the
 * candidates of a box or a ray (the broad phase's answer, with the waiting bodies, in the order
 * added). Every change of a body's pose goes through here and tells the contact tracker.
 */
final class BodyTable {

    private final World world;
    private final BroadPhase broad;
    private final ContactTracker tracker;
    private Body[] byId = new Body[16];
    private int[] freeIds = new int[16];
    private int freeCount;
    private int nextId;
    private int size;
    private int serials;

    // Candidates of a query or a leg, by id.
    private int[] cand = new int[16];
    private int candCount;
    private final IntConsumer collect = id -> {
        if (candCount == cand.length) {
            cand = java.util.Arrays.copyOf(cand, 2 * candCount);
        }
        cand[candCount++] = id;
    };

    private final double[] scratch = new double[4];

    /**
     * Each id's tight box (x, y, w, h) and layers (category, mask), copies of the body's own,
     * side by side in memory: the pair scans reject most of the broad phase's pairs (five in
     * six in a crowd: it holds fat boxes) on these, without reading the two bodies from
     * wherever they lie in memory.
     */
    private float[] boxes = new float[64];
    private int[] layers = new int[32];

    BodyTable(World world, BroadPhase broad, ContactTracker tracker) {
        this.world = world;
        this.broad = broad;
        this.tracker = tracker;
    }

    /** A new body, placed by its pose; checked before anything changes. */
    Body add(Shape home, double px, double py, double tx, double ty, float angle, Grid grid) {
        turn(angle);
        double cos = trig[0], sin = trig[1];
        Poses.extents(home, px, py, cos, sin, scratch);
        float[] box = box(px + tx, py + ty, scratch, "x, y and angle");
        int id = freeCount > 0 ? freeIds[--freeCount] : nextId++;
        Body b = new Body(world, id, serials++, home, px, py, grid);
        b.pose(tx, ty, angle, cos, sin, scratch);
        if (id >= byId.length) {
            byId = java.util.Arrays.copyOf(byId, Math.max(2 * byId.length, id + 1));
        }
        byId[id] = b;
        if (4 * id + 4 > boxes.length) {
            boxes = java.util.Arrays.copyOf(boxes, Math.max(2 * boxes.length, 4 * id + 4));
            layers = java.util.Arrays.copyOf(layers, boxes.length / 2);
        }
        layers(b);
        size++;
        setBox(b, box[0], box[1], box[2], box[3]);
        if (grid != null) {
            tracker.addedGrid(b);
        }
        return b;
    }

    /** Takes a body out: its box, its contacts, its id (free for the next body). */
    void remove(Body body) {
        if (body.dirtyIndex >= 0) {
            undirty(body);
        }
        tracker.removed(body);
        broad.remove(body.id);
        byId[body.id] = null;
        if (freeCount == freeIds.length) {
            freeIds = java.util.Arrays.copyOf(freeIds, 2 * freeCount);
        }
        freeIds[freeCount++] = body.id;
        body.removed();
        size--;
    }

    /** @return how many bodies there are */
    int size() {
        return size;
    }

    /** The body of an id, or null. */
    Body body(int id) {
        return id < byId.length ? byId[id] : null;
    }

    /** The bodies, in the order added, into a new list. */
    List<Body> all() {
        List<Body> out = new ArrayList<>(size);
        for (int i = 0; i < nextId; i++) {
            if (i < byId.length && byId[i] != null) {
                out.add(byId[i]);
            }
        }
        out.sort((a, b) -> Integer.compare(a.serial, b.serial));
        return out;
    }

    /** Where a move left a body: its pose and shape, and its box (the pose's, grown to the shape's own extents). */
    void moved(Body m, Spot start, Spot end) {
        double ntx = m.tx + (end.refX() - start.refX()), nty = m.ty + (end.refY() - start.refY());
        float[] box = box(m.homePivotX + ntx, m.homePivotY + nty, m.extents, "dx and dy");
        // The shape's own extents too (no Rect made for them).
        float x0 = Math.min(box[0], Math.nextDown((float) end.minX())), y0 = Math.min(box[1], Math.nextDown((float) end.minY()));
        float x1 = Math.max(box[0] + box[2], Math.nextUp((float) end.maxX())), y1 = Math.max(box[1] + box[3], Math.nextUp((float) end.maxY()));
        end.placeInto(m, ntx, nty);
        setBox(m, x0, y0, Math.nextUp(x1 - x0), Math.nextUp(y1 - y0));
    }

    /** A pose's cosine and sine, set by {@link #turn}. */
    private final double[] trig = new double[2];

    /**
     * The cosine and sine of a pose's angle into {@link #trig}: exactly 1 and 0 at angle 0,
     * else StrictMath's bits from one reduction for both ({@code Fdlibm.sinCos}, about a third
     * of the time of the two native calls: {@code TurnTrigBench}).
     */
    private void turn(float angle) {
        if (angle == 0) {
            trig[0] = 1;
            trig[1] = 0;
        } else {
            Fdlibm.sinCos(angle, trig);
        }
    }

    void teleport(Body b, double tx, double ty, float angle, String what) {
        if (b.grid != null) {
            throw new IllegalStateException("a grid's body does not move or turn");
        }
        double cos = b.cos, sin = b.sin;
        double[] ex = b.extents;
        if (angle != b.angle) {
            turn(angle);
            cos = trig[0];
            sin = trig[1];
            Poses.extents(b.home, b.homePivotX, b.homePivotY, cos, sin, scratch);
            ex = scratch;
        }
        float[] box = box(b.homePivotX + tx, b.homePivotY + ty, ex, what);
        b.pose(tx, ty, angle, cos, sin, ex);
        setBox(b, box[0], box[1], box[2], box[3]);
    }

    private final float[] boxOut = new float[4];

    /** The box of a pose, rounded outwards a float step more; checked before anything changes. */
    float[] box(double ox, double oy, double[] ex, String what) {
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
     * last move ahead, both kept in proportion for bodies of a pixel or two) is put at once if
     * the broad phase can take it with no work (the grid: the box stays in its cell), else
     * waits in the dirty list, which queries scan, until enough wait to put them all at once
     * (or the next {@link World#step()}): the grid rebuilds after a change of cell, so putting
     * one such box per move would rebuild it once per move.
     */
    void setBox(Body b, float x, float y, float w, float h) {
        tracker.changed(b);
        if (b.grid != null) {
            box(b, 0, 0, b.grid.width(), b.grid.height());
            b.fat(0, 0, b.grid.width(), b.grid.height());
            broad.put(b.id, 0, 0, b.boxW, b.boxH);
            return;
        }
        boolean fresh = !b.boxed;
        double ddx = fresh ? 0 : (double) x - b.boxX, ddy = fresh ? 0 : (double) y - b.boxY;
        box(b, x, y, w, h);
        if (!fresh && x >= b.fatX && y >= b.fatY && (double) x + w <= (double) b.fatX + b.fatW
                && (double) y + h <= (double) b.fatY + b.fatH) {
            return;
        }
        // Grown by an eighth of its size and a pixel (half its size, if under two pixels), and
        // ahead by four times its last move, up to its size: a fixed pixel, or a move far
        // ahead, would make a crowd of tiny bodies' fat boxes many times their size, and the
        // broad phase's pairs (its fat boxes meeting) many times the contacts.
        double size = Math.max(w, h);
        double m = Math.min(1, size / 2) + size / 8;
        double aheadX = Math.max(-size, Math.min(size, 4 * ddx)), aheadY = Math.max(-size, Math.min(size, 4 * ddy));
        double x0 = Math.max(-Float.MAX_VALUE, x - m + Math.min(0, aheadX));
        double y0 = Math.max(-Float.MAX_VALUE, y - m + Math.min(0, aheadY));
        double x1 = Math.min(Float.MAX_VALUE, (double) x + w + m + Math.max(0, aheadX));
        double y1 = Math.min(Float.MAX_VALUE, (double) y + h + m + Math.max(0, aheadY));
        // Never past the float range: a body near its edge gets a fat box that ends there.
        float fx = Math.min(x, Math.max(-Float.MAX_VALUE, Math.nextDown((float) x0)));
        float fy = Math.min(y, Math.max(-Float.MAX_VALUE, Math.nextDown((float) y0)));
        float fw = (float) Math.min(Float.MAX_VALUE, Math.nextUp(x1 - fx)), fh = (float) Math.min(Float.MAX_VALUE, Math.nextUp(y1 - fy));
        // A fat box the broad phase takes with no work (the grid: it stays in its cell, as
        // most do from one frame to the next) is put at once, and need not wait; not while a
        // carrier moves, whose refused move puts every box back as it was.
        if (!holdFlush && broad instanceof AbstractBroadPhase a && a.putInPlace(b.id, fx, fy, fw, fh)) {
            if (b.dirtyIndex >= 0) {
                undirty(b);
            }
            b.fat(fx, fy, fw, fh);
            return;
        }
        if (b.dirtyIndex < 0) {
            if (dirtyCount == dirty.length) {
                dirty = java.util.Arrays.copyOf(dirty, 2 * dirtyCount);
            }
            b.dirtyIndex(dirtyCount);
            dirty[dirtyCount++] = b;
        }
        b.fat(fx, fy, fw, fh);
        flushIfMany();
    }

    /** Sets a body's tight box, and its copy here. */
    void box(Body b, float x, float y, float w, float h) {
        b.box(x, y, w, h);
        int k = 4 * b.id;
        boxes[k] = x;
        boxes[k + 1] = y;
        boxes[k + 2] = w;
        boxes[k + 3] = h;
    }

    /** Copies a body's layers here (when added, and when they change). */
    void layers(Body b) {
        layers[2 * b.id] = b.category;
        layers[2 * b.id + 1] = b.mask;
    }

    /**
     * May the bodies of two ids meet: do their layers accept each other and their tight boxes
     * overlap (touching counts)? Read from the copies here, not from the bodies.
     */
    boolean mayMeet(int i, int j) {
        int li = 2 * i, lj = 2 * j;
        if ((layers[li] & layers[lj + 1]) == 0 || (layers[lj] & layers[li + 1]) == 0) {
            return false;
        }
        int p = 4 * i, q = 4 * j;
        float ax = boxes[p], ay = boxes[p + 1], bx = boxes[q], by = boxes[q + 1];
        return !(ax > (double) bx + boxes[q + 2] || bx > (double) ax + boxes[p + 2]
                || ay > (double) by + boxes[q + 3] || by > (double) ay + boxes[p + 3]);
    }

    private Body[] dirty = new Body[16];
    private int dirtyCount;
    /** Set while a carrier moves: no flush then, so a refused carrier's move can put every box back. */
    boolean holdFlush;

    /**
     * Puts the waiting boxes once more than {@code 32 + sqrt(n) / 2} wait (84 among 11,000
     * bodies): every query scans them all, every put of them rebuilds the grid (in time
     * proportional to n), and this balanced the two best on the movers' benchmark (1,000
     * movers among 10,000 standing bodies: 64 + 2 sqrt(n) gave 1.65 ms a frame for bodies
     * and 3.0 for characters, this 1.45 and 2.25; 16 + sqrt(n) / 4 or 8 + sqrt(n) / 4, no
     * better).
     */
    void flushIfMany() {
        if (!holdFlush && dirtyCount > 32 + Math.sqrt(size) / 2) {
            flush();
        }
    }

    /** Puts every waiting fat box into the broad phase. */
    void flush() {
        for (int i = 0; i < dirtyCount; i++) {
            Body b = dirty[i];
            broad.put(b.id, b.fatX, b.fatY, b.fatW, b.fatH);
            b.dirtyIndex(-1);
            dirty[i] = null;
        }
        dirtyCount = 0;
    }

    void undirty(Body b) {
        int i = b.dirtyIndex;
        Body last = dirty[--dirtyCount];
        dirty[i] = last;
        last.dirtyIndex(i);
        dirty[dirtyCount] = null;
        b.dirtyIndex(-1);
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

    /** The candidates of a ray: the bodies whose boxes it meets, in no particular order. */
    void rayCandidates(Ray ray) {
        candCount = 0;
        broad.raycast(ray, rayCollect);
        for (int i = 0; i < dirtyCount; i++) {
            Body b = dirty[i];
            // Only those whose fat box the ray goes into (the fat box holds the shape, with a
            // margin of a pixel at least): not every waiting body's shape cast each time.
            if (Ray.distanceToRect(ray.ox(), ray.oy(), ray.dx(), ray.dy(), ray.maxDistance(),
                    b.fatX, b.fatY, b.fatW, b.fatH) != Float.POSITIVE_INFINITY) {
                collect.accept(b.id);
            }
        }
    }

    private final RayVisitor rayCollect = (id, distance) -> {
        if (byId[id].dirtyIndex < 0) {
            collect.accept(id);  // a dirty body's box in the broad phase is stale: it is added after
        }
        return true;
    };

}
