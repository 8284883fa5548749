package hitbox.internal;

import hitbox.*;

import java.util.Arrays;
import java.util.function.IntConsumer;

/**
 * {@link BroadPhase#quadtree()}: a loose quadtree over the {@link Lattice}, with squares of
 * 2^-16 pixels at level 0 and each level's squares twice the size of the one below.
 *
 * <p>A node is a square at some level, named by its cell there. A box belongs in any node whose
 * square holds its top-left corner and whose level is at least the box's own (the level at
 * which its edges are at most one cell apart): so the box lies inside the node's square
 * doubled to the right and down, the loose square. A node holds its boxes in a linked list
 * through the slots. A node that is not divided keeps every box that reaches it; one holding
 * more than {@link #SPLIT} boxes is divided, and its boxes that fit a child go down (a divided
 * node keeps only the boxes too large for its children). A divided node whose part of the tree
 * holds {@link #MERGE} or fewer boxes takes them all back. The root grows upward to take in any
 * box, and gives way to its only child when it holds nothing of its own.
 *
 * <p>Pairs come from one walk: within each node, each node's boxes against its part of the
 * tree below, and each pair of neighbouring subtrees of the same level against each other. A
 * box and a node can only hold overlapping boxes if the node's cell is within one of the box's
 * cells at that level, by the Lattice argument, so subtrees are skipped by integer tests.
 *
 * <p>This class is longer than most (about 600 lines) because it is one data structure: the
 * placing, splitting and merging of nodes and the walks for pairs, boxes and rays all share
 * the same node arrays and slot links; the cell arithmetic they rest on is already apart, in
 * {@link Lattice}.
 */
public final class QuadtreeBroadPhase extends AbstractBroadPhase {
    /** A node holding more boxes than this divides. */
    public static final int SPLIT = 8;
    /** A divided node whose subtree holds this many boxes or fewer merges. */
    public static final int MERGE = 4;
    private static final double CELL = 1.0 / 65536;
    private static final double PER_CELL = 65536;
    private static final int NONE = -1;

    // Nodes.
    private int[] level = new int[0];
    private long[] na = new long[0];
    private long[] nb = new long[0];
    private int[] parent = new int[0];
    private int[] child = new int[0];
    private int[] head = new int[0];
    private int[] own = new int[0];
    private int[] total = new int[0];
    private boolean[] divided = new boolean[0];
    private int nodes;
    private int freeNode = NONE;
    private int root = NONE;

    // Slots: the node, the list, and the cells of the box's edges at level 0.
    private int[] nodeOf = new int[0];
    private int[] next = new int[0];
    private int[] prev = new int[0];
    private int[] boxLevel = new int[0];
    private long[] x0 = new long[0];
    private long[] x1 = new long[0];
    private long[] y0 = new long[0];
    private long[] y1 = new long[0];

    // ---------------------------------------------------------------- changes

    @Override
    public void added(int slot) {
        cellsOf(slot);
        place(slot);
    }

    @Override
    public void moved(int slot, float oldX, float oldY) {
        cellsOf(slot);
        int node = nodeOf[slot];
        boolean stays = fits(node, slot) && (!divided[node] || boxLevel[slot] == level[node]);
        if (!stays) {
            unplace(slot);
            place(slot);
        }
    }

    @Override
    public void removing(int slot) {
        unplace(slot);
    }

    @Override
    public void relocated(int from, int to) {
        nodeOf[to] = nodeOf[from];
        next[to] = next[from];
        prev[to] = prev[from];
        boxLevel[to] = boxLevel[from];
        x0[to] = x0[from];
        x1[to] = x1[from];
        y0[to] = y0[from];
        y1[to] = y1[from];
        if (prev[to] != NONE) {
            next[prev[to]] = to;
        } else {
            head[nodeOf[to]] = to;
        }
        if (next[to] != NONE) {
            prev[next[to]] = to;
        }
    }

    @Override
    public void cleared() {
        nodes = 0;
        freeNode = NONE;
        root = NONE;
    }

    @Override
    public void grown(int capacity) {
        nodeOf = Arrays.copyOf(nodeOf, capacity);
        next = Arrays.copyOf(next, capacity);
        prev = Arrays.copyOf(prev, capacity);
        boxLevel = Arrays.copyOf(boxLevel, capacity);
        x0 = Arrays.copyOf(x0, capacity);
        x1 = Arrays.copyOf(x1, capacity);
        y0 = Arrays.copyOf(y0, capacity);
        y1 = Arrays.copyOf(y1, capacity);
    }

    private void cellsOf(int slot) {
        int k = 4 * slot;
        x0[slot] = Lattice.cell(box[k], PER_CELL);
        x1[slot] = Lattice.cell(box[k + 1], PER_CELL);
        y0[slot] = Lattice.cell(box[k + 2], PER_CELL);
        y1[slot] = Lattice.cell(box[k + 3], PER_CELL);
        boxLevel[slot] = Math.max(Lattice.level(x0[slot], x1[slot]), Lattice.level(y0[slot], y1[slot]));
    }

    /** Does the box belong in this node's square at all (corner inside, not too large)? */
    private boolean fits(int node, int slot) {
        int m = level[node];
        return boxLevel[slot] <= m && x0[slot] >> m == na[node] && y0[slot] >> m == nb[node];
    }

    private void place(int slot) {
        if (root == NONE) {
            root = newNode(boxLevel[slot], x0[slot] >> boxLevel[slot], y0[slot] >> boxLevel[slot], NONE);
        }
        while (!fits(root, slot)) {
            int m = level[root] + 1;
            int up = newNode(m, na[root] >> 1, nb[root] >> 1, NONE);
            child[4 * up + quadrant(na[root], nb[root])] = root;
            parent[root] = up;
            total[up] = total[root];
            divided[up] = true;
            root = up;
        }
        int node = root;
        total[node]++;
        while (divided[node] && boxLevel[slot] < level[node]) {
            node = childFor(node, slot);
            total[node]++;
        }
        link(slot, node);
        if (!divided[node] && own[node] > SPLIT && level[node] > 0) {
            split(node);
        }
    }

    /** The child of a divided node that the box goes down to, made if missing. */
    private int childFor(int node, int slot) {
        int m = level[node] - 1;
        long a = x0[slot] >> m, b = y0[slot] >> m;
        int q = 4 * node + quadrant(a, b);
        if (child[q] == NONE) {
            int made = newNode(m, a, b, node);  // may grow the arrays: not child[q] = newNode(...)
            child[q] = made;
        }
        return child[q];
    }

    private static int quadrant(long a, long b) {
        return (int) (a & 1) | (int) (b & 1) << 1;
    }

    private void split(int node) {
        divided[node] = true;
        for (int s = head[node]; s != NONE; ) {
            int after = next[s];
            if (boxLevel[s] < level[node]) {
                unlink(s);
                int c = childFor(node, s);
                total[c]++;
                link(s, c);
            }
            s = after;
        }
        for (int q = 4 * node; q < 4 * node + 4; q++) {
            int c = child[q];
            if (c != NONE && own[c] > SPLIT && level[c] > 0) {
                split(c);
            }
        }
    }

    private void unplace(int slot) {
        int node = nodeOf[slot];
        unlink(slot);
        int top = NONE;
        for (int p = node; p != NONE; p = parent[p]) {
            total[p]--;
            if (divided[p] && total[p] <= MERGE) {
                top = p;
            }
        }
        if (top != NONE) {
            merge(top);  // frees the nodes below top, node perhaps among them
            node = top;
        }
        // Drop empty nodes upward, then let a root with nothing of its own give way to its only child.
        for (int p = node; p != NONE && total[p] == 0 && p != root; ) {
            int up = parent[p];
            if (up != NONE) {
                detach(up, p);
            }
            freeSubtree(p);
            p = up;
        }
        while (root != NONE && own[root] == 0) {
            if (total[root] == 0) {
                freeSubtree(root);
                root = NONE;
                break;
            }
            int only = NONE, children = 0;
            for (int q = 4 * root; q < 4 * root + 4; q++) {
                if (child[q] != NONE) {
                    only = child[q];
                    children++;
                }
            }
            if (children != 1) {
                break;
            }
            child[4 * root + quadrant(na[only], nb[only])] = NONE;
            free(root);
            root = only;
            parent[only] = NONE;
        }
    }

    /** Takes every box of the subtree into the node, which is no longer divided. */
    private void merge(int node) {
        for (int q = 4 * node; q < 4 * node + 4; q++) {
            int c = child[q];
            if (c != NONE) {
                gather(c, node);
                freeSubtree(c);
                child[q] = NONE;
            }
        }
        divided[node] = false;
    }

    private void gather(int from, int into) {
        for (int s = head[from]; s != NONE; ) {
            int after = next[s];
            unlink(s);
            link(s, into);
            s = after;
        }
        for (int q = 4 * from; q < 4 * from + 4; q++) {
            if (child[q] != NONE) {
                gather(child[q], into);
            }
        }
    }

    private void detach(int up, int node) {
        for (int q = 4 * up; q < 4 * up + 4; q++) {
            if (child[q] == node) {
                child[q] = NONE;
            }
        }
    }

    private void freeSubtree(int node) {
        for (int q = 4 * node; q < 4 * node + 4; q++) {
            if (child[q] != NONE) {
                freeSubtree(child[q]);
            }
        }
        free(node);
    }

    private void link(int slot, int node) {
        nodeOf[slot] = node;
        prev[slot] = NONE;
        next[slot] = head[node];
        if (head[node] != NONE) {
            prev[head[node]] = slot;
        }
        head[node] = slot;
        own[node]++;
    }

    private void unlink(int slot) {
        int node = nodeOf[slot];
        if (prev[slot] != NONE) {
            next[prev[slot]] = next[slot];
        } else {
            head[node] = next[slot];
        }
        if (next[slot] != NONE) {
            prev[next[slot]] = prev[slot];
        }
        own[node]--;
    }

    private int newNode(int m, long a, long b, int up) {
        int node;
        if (freeNode != NONE) {
            node = freeNode;
            freeNode = parent[node];
        } else {
            if (nodes == level.length) {
                int capacity = Math.max(16, 2 * nodes);
                level = Arrays.copyOf(level, capacity);
                na = Arrays.copyOf(na, capacity);
                nb = Arrays.copyOf(nb, capacity);
                parent = Arrays.copyOf(parent, capacity);
                child = Arrays.copyOf(child, 4 * capacity);
                head = Arrays.copyOf(head, capacity);
                own = Arrays.copyOf(own, capacity);
                total = Arrays.copyOf(total, capacity);
                divided = Arrays.copyOf(divided, capacity);
            }
            node = nodes++;
        }
        level[node] = m;
        na[node] = a;
        nb[node] = b;
        parent[node] = up;
        Arrays.fill(child, 4 * node, 4 * node + 4, NONE);
        head[node] = NONE;
        own[node] = 0;
        total[node] = 0;
        divided[node] = false;
        return node;
    }

    private void free(int node) {
        parent[node] = freeNode;
        freeNode = node;
    }

    // ---------------------------------------------------------------- pairs

    @Override
    public void findPairs(PairConsumer out) {
        if (root == NONE) {
            return;
        }
        Aim outer = enter();
        try {
            self(root, out);
        } finally {
            restore(outer);
        }
    }

    /** Every pair within a subtree. */
    private void self(int node, PairConsumer out) {
        for (int s = head[node]; s != NONE; s = next[s]) {
            for (int t = next[s]; t != NONE; t = next[t]) {
                test(s, t, out);
            }
        }
        if (!divided[node]) {
            return;
        }
        int base = 4 * node;
        for (int s = head[node]; s != NONE; s = next[s]) {
            for (int q = base; q < base + 4; q++) {
                if (child[q] != NONE) {
                    down(s, child[q], out);
                }
            }
        }
        for (int q = base; q < base + 4; q++) {
            if (child[q] != NONE) {
                self(child[q], out);
                for (int r = q + 1; r < base + 4; r++) {
                    if (child[r] != NONE) {
                        cross(child[q], child[r], out);
                    }
                }
            }
        }
    }

    /** Every pair with one box in subtree a and one in subtree b: two nodes of one level, at most one cell apart. */
    private void cross(int a, int b, PairConsumer out) {
        for (int s = head[a]; s != NONE; s = next[s]) {
            for (int t = head[b]; t != NONE; t = next[t]) {
                test(s, t, out);
            }
        }
        if (divided[b]) {
            for (int s = head[a]; s != NONE; s = next[s]) {
                for (int q = 4 * b; q < 4 * b + 4; q++) {
                    if (child[q] != NONE) {
                        down(s, child[q], out);
                    }
                }
            }
        }
        if (divided[a]) {
            for (int t = head[b]; t != NONE; t = next[t]) {
                for (int q = 4 * a; q < 4 * a + 4; q++) {
                    if (child[q] != NONE) {
                        down(t, child[q], out);
                    }
                }
            }
            if (divided[b]) {
                for (int q = 4 * a; q < 4 * a + 4; q++) {
                    int ca = child[q];
                    if (ca == NONE) {
                        continue;
                    }
                    for (int r = 4 * b; r < 4 * b + 4; r++) {
                        int cb = child[r];
                        if (cb != NONE && Math.abs(na[ca] - na[cb]) <= 1 && Math.abs(nb[ca] - nb[cb]) <= 1) {
                            cross(ca, cb, out);
                        }
                    }
                }
            }
        }
    }

    private void test(int s, int t, PairConsumer out) {
        tally++;
        if (overlap(box, 4 * s, box, 4 * t)) {
            emit(out, ids[s], ids[t]);
        }
    }

    /**
     * The box a walk down the tree is made with: the box of a slot (pairs, to {@code pairs}) or
     * a query box (ids, to {@code ids}), its edges and their level-0 cells. A question asked
     * from inside a callback walks with an aim of its own, so the outer walk's is kept.
     */
    private static final class Aim {
        public double x;
        public double right;
        public double y;
        public double bottom;
        public long x0;
        public long x1;
        public long y0;
        public long y1;
        public int slot;
        public PairConsumer pairs;
        public IntConsumer ids;
    }

    private Aim aim = new Aim();
    private Aim spareAim;

    /** Swaps in a fresh aim for this question; returns the outer one, to give back to {@link #restore}. */
    private Aim enter() {
        Aim outer = aim;
        aim = spareAim != null ? spareAim : new Aim();
        spareAim = null;
        return outer;
    }

    private void restore(Aim outer) {
        spareAim = aim;
        aim = outer;
    }

    /** Walks down with the box of slot s, reporting pairs. */
    private void down(int s, int node, PairConsumer out) {
        Aim q = aim;
        int k = 4 * s;
        q.x = box[k];
        q.right = box[k + 1];
        q.y = box[k + 2];
        q.bottom = box[k + 3];
        q.x0 = x0[s];
        q.x1 = x1[s];
        q.y0 = y0[s];
        q.y1 = y1[s];
        q.slot = s;
        q.pairs = out;
        down(node, q);
    }

    /**
     * The aimed box against a subtree. Skips the node unless its cell is within one of the
     * box's cells at the node's level.
     */
    private void down(int node, Aim q) {
        int m = level[node];
        if (na[node] < (q.x0 >> m) - 1 || na[node] > q.x1 >> m || nb[node] < (q.y0 >> m) - 1 || nb[node] > q.y1 >> m) {
            return;
        }
        for (int t = head[node]; t != NONE; t = next[t]) {
            tally++;
            int k = 4 * t;
            if (overlap(q.x, q.right, q.y, q.bottom, box[k], box[k + 1], box[k + 2], box[k + 3])) {
                if (q.pairs != null) {
                    emit(q.pairs, ids[q.slot], ids[t]);
                } else {
                    q.ids.accept(ids[t]);
                }
            }
        }
        if (divided[node]) {
            for (int c = 4 * node; c < 4 * node + 4; c++) {
                if (child[c] != NONE) {
                    down(child[c], q);
                }
            }
        }
    }

    // ---------------------------------------------------------------- queries and rays

    @Override
    public void findBoxes(double x, double y, double right, double bottom, IntConsumer out) {
        if (root == NONE) {
            return;
        }
        Aim outer = enter();
        try {
            Aim q = aim;
            q.x = x;
            q.right = right;
            q.y = y;
            q.bottom = bottom;
            q.x0 = Lattice.cell(x, PER_CELL);
            q.x1 = Lattice.cell(right, PER_CELL);
            q.y0 = Lattice.cell(y, PER_CELL);
            q.y1 = Lattice.cell(bottom, PER_CELL);
            q.pairs = null;
            q.ids = out;
            down(root, q);
        } finally {
            restore(outer);
        }
    }

    @Override
    public void findRayCandidates(RayCast ray) {
        if (root != NONE) {
            rayDown(root, ray);
        }
    }

    private void rayDown(int node, RayCast ray) {
        int m = level[node];
        if (!ray.mayEnter(Lattice.edge(na[node], m, CELL), Lattice.edge(nb[node], m, CELL),
                Lattice.edge(na[node] + 2, m, CELL), Lattice.edge(nb[node] + 2, m, CELL))) {
            return;
        }
        for (int s = head[node]; s != NONE; s = next[s]) {
            ray.consider(s);
        }
        for (int q = 4 * node; q < 4 * node + 4; q++) {
            if (child[q] != NONE) {
                rayDown(child[q], ray);
            }
        }
    }

    @Override
    public void findCells(BoxConsumer out) {
        if (root != NONE) {
            cellsDown(root, 0, out);
        }
    }

    private void cellsDown(int node, int depth, BoxConsumer out) {
        int m = level[node];
        double left = Lattice.edge(na[node], m, CELL), right = Lattice.edge(na[node] + 1, m, CELL);
        double top = Lattice.edge(nb[node], m, CELL), bottom = Lattice.edge(nb[node] + 1, m, CELL);
        out.box(depth, (float) left, (float) top, (float) (right - left), (float) (bottom - top));
        for (int q = 4 * node; q < 4 * node + 4; q++) {
            if (child[q] != NONE) {
                cellsDown(child[q], depth + 1, out);
            }
        }
    }

    @Override
    public String toString() {
        return "quadtree";
    }
}
