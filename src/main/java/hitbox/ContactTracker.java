package hitbox;

import hitbox.internal.*;

import java.util.Comparator;
import java.util.List;
import java.util.function.BiConsumer;
import java.util.function.IntConsumer;

/**
 * The contacts of a {@link World}, kept from step to step: which pairs of bodies are in contact,
 * what began and what ended. Box2D v3's contact graph without its solver.
 *
 * <p><b>Nothing redone that did not change.</b> A step looks only at the bodies that moved,
 * turned, were added or had their layers changed since the last step ({@link #changed}), the
 * grids whose cells changed, the pairs a move met, and the pairs that were in contact last step
 * only because a move met them: each such body's contacts are tested again and the broad phase
 * is asked what its box meets now. A pair of bodies that stand keeps its contact and costs
 * nothing; a step in which nothing changed tests no pair and makes nothing.
 *
 * <p><b>Storage.</b> Contacts are slots in parallel arrays (reused through a free list), found
 * by their pair's key (the two bodies' serials) in a {@link PairSlots}, and threaded through
 * two lists per slot, one for each body (Box2D's contact edges), so a body's contacts are
 * walked without a search. Everything grows to the world's largest size and is then reused.
 */
final class ContactTracker {

    /** Orders events and pairs by the body added first, then the other. */
    static final Comparator<BodyEvent> BY_PAIR = (p, q) -> p.a().serial != q.a().serial
            ? Integer.compare(p.a().serial, q.a().serial) : Integer.compare(p.b().serial, q.b().serial);

    private final World world;
    private final BroadPhase broad;
    private final GridCollider cells;

    // The contact slots: the two bodies (the one added first in a), and per step marks.
    private Body[] ca = new Body[64];
    private Body[] cb = new Body[64];
    /** When the slot was last tested, met, entered and left in contact only by a meeting (step numbers). */
    private int[] checked = new int[64];
    private int[] metAt = new int[64];
    private int[] enteredAt = new int[64];
    private int[] lingerAt = new int[64];
    /**
     * The slot's STAY event, made the first time {@link World#step()} reports the contact as
     * going on and handed again every step after, until the contact ends: an event is a value
     * (its kind and its two bodies), so the same one serves, and a frame of resting contacts
     * makes no new object per contact.
     */
    private BodyEvent[] stay = new BodyEvent[64];
    /** The slot's two edges, 2c (in a's list) and 2c + 1 (in b's): the next and previous edge of the same body's list. */
    private int[] next = new int[128];
    private int[] prev = new int[128];
    private int slots;
    private int freeSlot = -1;
    private int live;
    private final PairSlots bySerials = new PairSlots();

    // Per body id: the first edge of its list, whether it waits to be looked at, when it was.
    private int[] head = filled(new int[64]);
    private int[] changedAt = new int[64];
    private int[] doneAt = new int[64];

    /** The bodies changed since the last step, in order; removed ones are skipped. */
    private Body[] changed = new Body[64];
    private int changedCount;

    /** The grids' bodies, and the count of changes of each grid when last looked at. */
    private Body[] grids = new Body[4];
    private int[] gridChanges = new int[4];
    private int gridCount;

    /** The slots in contact only because a move met them, at the last step and at this one. */
    private int[] lingering = new int[16];
    private int lingeringCount;
    private int[] nowLingering = new int[16];
    private int nowLingeringCount;

    /** The slots a move met during this step. */
    private int[] met = new int[16];
    private int metCount;

    /** The changes to report at the next step: ENTER and EXIT, in the order they happened. */
    private final java.util.ArrayList<BodyEvent> pending = new java.util.ArrayList<>();

    /**
     * The number of the next step, or of the step under way: marks equal to it were set for
     * it. (It starts at 2 so that no mark of 0 reads as the last step's.)
     */
    private int step = 2;

    /** How many pairs were tested for contact, since the world was made: an operation count for tests. */
    private long pairTests;

    // A changed body's neighbours in the broad phase.
    private int[] near = new int[16];
    private int nearCount;
    private final IntConsumer collect = id -> {
        if (nearCount == near.length) {
            near = java.util.Arrays.copyOf(near, 2 * nearCount);
        }
        near[nearCount++] = id;
    };

    ContactTracker(World world, BroadPhase broad, GridCollider grids) {
        this.world = world;
        this.broad = broad;
        this.cells = grids;
    }

    private static int[] filled(int[] a) {
        java.util.Arrays.fill(a, -1);
        return a;
    }

    // ---------------------------------------------------------------- what the world tells it

    /** A body was added, moved, turned or had its layers changed: its contacts need a look at the next step. */
    void changed(Body b) {
        ensureId(b.id);
        if (changedAt[b.id] == step) {
            return;
        }
        changedAt[b.id] = step;
        if (changedCount == changed.length) {
            changed = java.util.Arrays.copyOf(changed, 2 * changedCount);
        }
        changed[changedCount++] = b;
    }

    /** A grid's body was added: its grid's changes are watched. */
    void addedGrid(Body g) {
        if (gridCount == grids.length) {
            grids = java.util.Arrays.copyOf(grids, 2 * gridCount);
            gridChanges = java.util.Arrays.copyOf(gridChanges, 2 * gridCount);
        }
        grids[gridCount] = g;
        gridChanges[gridCount] = g.grid.changes();
        gridCount++;
    }

    /** A body is being removed: its contacts end now (EXIT at the next step) and its id is free. */
    void removed(Body b) {
        ensureId(b.id);
        for (int e = head[b.id]; e >= 0; ) {
            int c = e >> 1;
            e = next[e];
            end(c);
        }
        changedAt[b.id] = 0;  // its entry in the changed list is skipped (the body is dead)
        for (int i = 0; i < gridCount; i++) {
            if (grids[i] == b) {
                grids[i] = grids[--gridCount];
                gridChanges[i] = gridChanges[gridCount];
                grids[gridCount] = null;
                break;
            }
        }
    }

    // ---------------------------------------------------------------- the step

    /**
     * Ends the frame: the pairs the moves met ({@code met}, the world's collisions since the
     * last step, or null) are in contact, every changed body's contacts are tested again and
     * its new ones found. The changes (ENTER and EXIT) go into {@code out}, and with
     * {@code stays} a STAY for every other contact; all ordered by pair.
     */
    void step(List<Collision> metBy, List<BodyEvent> out, boolean stays) {
        metCount = 0;
        if (metBy != null) {
            for (int i = 0, n = metBy.size(); i < n; i++) {
                Collision c = metBy.get(i);
                Body m = c.mover(), o = c.other();
                if (m.world == world && o.world == world && m.accepts(o)) {
                    meet(m, o);
                }
            }
        }
        for (int i = 0; i < gridCount; i++) {
            int now = grids[i].grid.changes();
            if (now != gridChanges[i]) {
                gridChanges[i] = now;
                changed(grids[i]);
            }
        }
        // The changed list may grow while it is walked (a grid marked above is in it already).
        for (int i = 0; i < changedCount; i++) {
            Body b = changed[i];
            changed[i] = null;
            if (b.world == world && doneAt[b.id] != step) {
                look(b);
            }
        }
        changedCount = 0;
        for (int i = 0; i < lingeringCount; i++) {
            int c = lingering[i];
            if (ca[c] != null && lingerAt[c] == step - 1 && checked[c] != step) {
                test(c);
            }
        }
        for (int i = 0; i < metCount; i++) {
            int c = met[i];
            if (ca[c] != null && checked[c] != step) {
                test(c);
            }
        }
        int[] t = lingering;
        lingering = nowLingering;
        lingeringCount = nowLingeringCount;
        nowLingering = t;
        nowLingeringCount = 0;
        int from = out.size();
        for (int i = 0, n = pending.size(); i < n; i++) {
            out.add(pending.get(i));  // not addAll, which copies even an empty list
        }
        pending.clear();
        if (stays) {
            for (int c = 0; c < slots; c++) {
                if (ca[c] != null && enteredAt[c] != step) {
                    if (stay[c] == null) {
                        stay[c] = new BodyEvent(BodyEvent.Kind.STAY, ca[c], cb[c]);
                    }
                    out.add(stay[c]);
                }
            }
        }
        if (out.size() - from > 1) {
            out.subList(from, out.size()).sort(BY_PAIR);
        }
        step++;
    }

    /** A pair a move met during the step: in contact now, whatever it overlaps. */
    private void meet(Body m, Body o) {
        Body a = m.serial < o.serial ? m : o, b = a == m ? o : m;
        int c = bySerials.get(PairSlots.key(a.serial, b.serial));
        if (c < 0) {
            c = begin(a, b);
        }
        metAt[c] = step;
        if (metCount == met.length) {
            met = java.util.Arrays.copyOf(met, 2 * metCount);
        }
        met[metCount++] = c;
    }

    /** A changed body: its contacts tested again, and the bodies its box meets now tested for new ones. */
    private void look(Body b) {
        doneAt[b.id] = step;
        for (int e = head[b.id]; e >= 0; ) {
            int c = e >> 1;
            e = next[e];
            if (checked[c] != step) {
                test(c);
            }
        }
        nearCount = 0;
        double pad = World.pad(b.boxX, b.boxY, (double) b.boxX + b.boxW, (double) b.boxY + b.boxH);
        float x0 = (float) Math.max(-Float.MAX_VALUE, b.boxX - pad), y0 = (float) Math.max(-Float.MAX_VALUE, b.boxY - pad);
        float w = (float) Math.min(Float.MAX_VALUE, b.boxW + 2 * pad), h = (float) Math.min(Float.MAX_VALUE, b.boxH + 2 * pad);
        broad.query(x0, y0, w, h, collect);
        for (int i = 0; i < nearCount; i++) {
            if (near[i] != b.id && !world.mayMeet(b.id, near[i])) {
                continue;  // layers or tight boxes apart: no new contact, and the other body is not read
            }
            Body o = world.body(near[i]);
            if (o == b || o == null || doneAt[o.id] == step) {
                continue;  // a body looked at already this step tested its pair with b itself
            }
            Body first = b.serial < o.serial ? b : o, second = first == b ? o : b;
            if (bySerials.get(PairSlots.key(first.serial, second.serial)) >= 0) {
                continue;  // in contact: tested above
            }
            pairTests++;
            if (b.accepts(o) && overlap(b, o)) {
                int c = begin(first, second);  // (not checked[begin(..)]: begin may grow the array)
                checked[c] = step;
            }
        }
    }

    /** Tests a contact again: it goes on if the bodies still overlap or a move met them this step, else it ends. */
    private void test(int c) {
        checked[c] = step;
        Body a = ca[c], b = cb[c];
        pairTests++;
        if (a.accepts(b) && overlap(a, b)) {
            return;
        }
        if (metAt[c] == step && a.accepts(b)) {
            lingerAt[c] = step;
            if (nowLingeringCount == nowLingering.length) {
                nowLingering = java.util.Arrays.copyOf(nowLingering, 2 * nowLingeringCount);
            }
            nowLingering[nowLingeringCount++] = c;
            return;
        }
        end(c);
    }

    /** A new contact (ENTER): a slot, its key, its two edges. */
    private int begin(Body a, Body b) {
        int c;
        if (freeSlot >= 0) {
            c = freeSlot;
            freeSlot = next[2 * c];
        } else {
            c = slots++;
            if (c == ca.length) {
                int n = 2 * c;
                ca = java.util.Arrays.copyOf(ca, n);
                cb = java.util.Arrays.copyOf(cb, n);
                checked = java.util.Arrays.copyOf(checked, n);
                metAt = java.util.Arrays.copyOf(metAt, n);
                enteredAt = java.util.Arrays.copyOf(enteredAt, n);
                lingerAt = java.util.Arrays.copyOf(lingerAt, n);
                stay = java.util.Arrays.copyOf(stay, n);
                next = java.util.Arrays.copyOf(next, 2 * n);
                prev = java.util.Arrays.copyOf(prev, 2 * n);
            }
        }
        ca[c] = a;
        cb[c] = b;
        checked[c] = 0;
        metAt[c] = 0;
        lingerAt[c] = 0;
        enteredAt[c] = step;
        ensureId(Math.max(a.id, b.id));
        link(2 * c, a.id);
        link(2 * c + 1, b.id);
        bySerials.add(PairSlots.key(a.serial, b.serial), c);
        live++;
        pending.add(new BodyEvent(BodyEvent.Kind.ENTER, a, b));
        return c;
    }

    /** A contact ends (EXIT): its key and edges go, its slot is free. */
    private void end(int c) {
        Body a = ca[c], b = cb[c];
        unlink(2 * c, a.id);
        unlink(2 * c + 1, b.id);
        bySerials.remove(PairSlots.key(a.serial, b.serial));
        ca[c] = null;
        cb[c] = null;
        stay[c] = null;
        lingerAt[c] = 0;
        next[2 * c] = freeSlot;
        freeSlot = c;
        live--;
        pending.add(new BodyEvent(BodyEvent.Kind.EXIT, a, b));
    }

    private void link(int e, int id) {
        int h = head[id];
        next[e] = h;
        prev[e] = -1;
        if (h >= 0) {
            prev[h] = e;
        }
        head[id] = e;
    }

    private void unlink(int e, int id) {
        int p = prev[e], n = next[e];
        if (p >= 0) {
            next[p] = n;
        } else {
            head[id] = n;
        }
        if (n >= 0) {
            prev[n] = p;
        }
    }

    private void ensureId(int id) {
        if (id >= head.length) {
            int n = Math.max(2 * head.length, id + 1);
            int old = head.length;
            head = java.util.Arrays.copyOf(head, n);
            java.util.Arrays.fill(head, old, n, -1);
            changedAt = java.util.Arrays.copyOf(changedAt, n);
            doneAt = java.util.Arrays.copyOf(doneAt, n);
        }
    }

    /** Do two bodies overlap now (a grid's body: one of its solid cells)? */
    boolean overlap(Body a, Body b) {
        // The tight boxes first (the broad phase holds fat ones): no shape is made for a pair
        // whose boxes are apart.
        if (a.boxX > (double) b.boxX + b.boxW || b.boxX > (double) a.boxX + a.boxW
                || a.boxY > (double) b.boxY + b.boxH || b.boxY > (double) a.boxY + a.boxH) {
            return false;
        }
        if (a.grid != null && b.grid != null) {
            return false;
        }
        if (a.grid != null) {
            return cells.meets(a.grid, b.shape());
        }
        if (b.grid != null) {
            return cells.meets(b.grid, a.shape());
        }
        // Both as numbers where they can be (no shape made for a body that moved); else the shapes.
        Placement pa = a.placement(), pb = pa == null ? null : b.placement();
        if (pb != null) {
            return PlacedOverlaps.test(pa, pb);
        }
        return a.shape().overlaps(b.shape());
    }

    // ---------------------------------------------------------------- reading the contacts

    /** @return how many pairs are in contact (as of the last step) */
    int count() {
        return live;
    }

    /** Visits every pair in contact, the body added first first. */
    void forEach(BiConsumer<Body, Body> out) {
        for (int c = 0; c < slots; c++) {
            if (ca[c] != null) {
                out.accept(ca[c], cb[c]);
            }
        }
    }

    /** Adds the bodies in contact with a body to a list. */
    void of(Body body, List<Body> out) {
        if (body.id >= head.length) {
            return;
        }
        for (int e = head[body.id]; e >= 0; e = next[e]) {
            int c = e >> 1;
            out.add((e & 1) == 0 ? cb[c] : ca[c]);
        }
    }

    /** Are two bodies in contact (as of the last step)? */
    boolean touching(Body a, Body b) {
        Body first = a.serial < b.serial ? a : b, second = first == a ? b : a;
        return bySerials.get(PairSlots.key(first.serial, second.serial)) >= 0;
    }

    /** How many pairs were tested for contact so far. */
    long pairTests() {
        return pairTests;
    }
}
