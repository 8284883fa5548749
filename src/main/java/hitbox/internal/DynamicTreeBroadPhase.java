package hitbox.internal;

import hitbox.*;

import java.util.Arrays;
import java.util.function.IntConsumer;

/**
 * {@link BroadPhase#dynamicTree()}: a port of Box2D's {@code b2DynamicTree} (Erin Catto,
 * v2.4) to flat arrays. Leaves hold enlarged ("fat") boxes, inner nodes the union of their
 * children; a leaf goes where it enlarges the tree's boxes least (the perimeter heuristic),
 * and rotations keep the tree balanced, as an AVL tree.
 *
 * <p>A box that moves inside its fat box changes nothing in the tree. One that leaves it is
 * taken out and put back with a new fat box: the box grown by {@link #EXTENSION} on each
 * side and by {@link #MULTIPLIER} times its last move ahead of it. A fat box grown much too
 * large (the box was fast, now slow) is shrunk the same way.
 *
 * <p>Each node is one record of eight doubles: its box (fat for a leaf, the union of its
 * children's otherwise) as {@code minX, maxX, minY, maxY}, and for a leaf a copy of the stored
 * box, {@code x, right, y, bottom}, so the exact test reads the line the tree test just read;
 * and one record of four ints: its children (the first -1 for a leaf, the second then its
 * slot), its parent and its height. The fat boxes are computed in double and each holds its
 * box exactly, so a tree box test with strict comparisons never loses a pair.
 *
 * <p>Pairs, as Box2D's broad phase and contact list: a persistent list of candidates, the pairs
 * of leaves whose fat boxes overlap. A fat box changes only when its leaf is (re-)inserted or
 * removed, which marks the leaf; each {@link #pairs} call drops the candidates with a marked
 * leaf, finds the candidates with a marked leaf by walking the tree against itself, skipping
 * every pair of subtrees with no marked leaf (each node counts the marked leaves below it),
 * and then runs the exact test over the list. So every pair whose fat boxes overlap is in the
 * list, each once, and the walk costs in proportion to the leaves that left their fat boxes.
 *
 * <p>Nodes are made where a free slot is, so after many re-insertions a subtree's nodes are
 * spread all over memory. Once the leaves have been re-inserted about half as many times as
 * there are boxes, the next pairs() renumbers every node in depth-first order (into a second
 * set of arrays, swapped in), so that a subtree, and the leaves next to each other in space,
 * are next to each other in memory.
 *
 * <p>This class is longer than most (about 580 lines) because it is one data structure: the
 * tree's insertion, removal and rotations, the candidate list and the renumbering all read
 * and write the same flat node arrays, and are best read side by side with Box2D's
 * {@code b2DynamicTree}, which keeps them in one file too.
 */
public final class DynamicTreeBroadPhase extends AbstractBroadPhase {
    /** Pixels added on each side of a leaf's box (Box2D: 0.1 m, about 2 to 3 pixels at its usual scale). */
    public static final double EXTENSION = 2;
    /** How many frames of its last move a leaf's box is grown by ahead of it (Box2D 2.4: 4). */
    public static final double MULTIPLIER = 4;
    private static final int NONE = -1;
    // A node's record in nd (8 doubles) and nl (4 ints).
    private static final int BOX = 0;
    private static final int TIGHT = 4;
    private static final int CHILD1 = 0;
    private static final int CHILD2 = 1;
    private static final int PARENT = 2;
    private static final int HEIGHT = 3;

    /** Node n's box at 8n: minX, maxX, minY, maxY; a leaf's stored box at 8n + 4: x, right, y, bottom. */
    private double[] nd = new double[0];
    /** Node n's links at 4n: child1 (-1 for a leaf), child2 (a leaf's slot), parent, height (0 for a leaf, -1 free). */
    private int[] nl = new int[0];
    private int nodes;
    private int freeNode = NONE;
    private int root = NONE;

    private int[] leafOf = new int[0];

    // The candidate list: leaves pairA[i] and pairB[i], whose fat boxes overlap.
    private int[] pairA = new int[0];
    private int[] pairB = new int[0];
    private int pairCount;
    /** Nodes whose leaf was inserted, re-inserted or removed since the last pairs(), and their list. */
    private boolean[] marked = new boolean[0];
    private int[] markedList = new int[0];
    private int markedCount;
    /** How many marked leaves are in each node's subtree (a leaf: 1 if marked). */
    private int[] markedBelow = new int[0];

    // Renumbering: the second set of node arrays, the new number of each node, and how many
    // insertions there have been since the last renumbering.
    private double[] ndSpare = new double[0];
    private int[] nlSpare = new int[0];
    private int[] renumbered = new int[0];
    private int insertions;

    // ---------------------------------------------------------------- changes

    @Override
    public void added(int slot) {
        int leaf = newNode();
        nl[4 * leaf + CHILD2] = slot;
        leafOf[slot] = leaf;
        copyBox(leaf, slot);
        fatten(leaf, 0, 0);
        mark(leaf);
        insertLeaf(leaf);
    }

    /** Marks a node's leaf as changed: before it goes into the tree, so the refit counts it above. */
    private void mark(int node) {
        markedBelow[node] = 1;
        if (!marked[node]) {
            marked[node] = true;
            if (markedCount == markedList.length) {
                markedList = Arrays.copyOf(markedList, Math.max(16, 2 * markedCount));
            }
            markedList[markedCount++] = node;
        }
    }

    @Override
    public void moved(int slot, float oldX, float oldY) {
        int leaf = leafOf[slot], k = 4 * slot;
        copyBox(leaf, slot);
        double dx = box[k] - oldX, dy = box[k + 2] - oldY;
        if (holds(leaf)) {
            // Still inside: nothing to do, unless the fat box is far larger than it would be now.
            double r = EXTENSION * 5;  // Box2D: the fat box it would get now, grown by 4 extensions more
            int f = 8 * leaf;
            if (box[k] - r + Math.min(0, MULTIPLIER * dx) <= nd[f] && nd[f + 1] <= box[k + 1] + r + Math.max(0, MULTIPLIER * dx)
                    && box[k + 2] - r + Math.min(0, MULTIPLIER * dy) <= nd[f + 2] && nd[f + 3] <= box[k + 3] + r + Math.max(0, MULTIPLIER * dy)) {
                return;
            }
        }
        removeLeaf(leaf);
        fatten(leaf, dx, dy);
        mark(leaf);
        insertLeaf(leaf);
    }

    private void copyBox(int leaf, int slot) {
        System.arraycopy(box, 4 * slot, nd, 8 * leaf + TIGHT, 4);
    }

    /** Is the leaf's stored box inside its fat box? */
    private boolean holds(int leaf) {
        int f = 8 * leaf, t = f + TIGHT;
        return nd[f] <= nd[t] && nd[t + 1] <= nd[f + 1] && nd[f + 2] <= nd[t + 2] && nd[t + 3] <= nd[f + 3];
    }

    /**
     * The leaf's fat box: its stored box grown by the extension and by the move ahead. In double,
     * where x - 2 can only round towards x, never past it: the fat box always holds the box.
     */
    private void fatten(int leaf, double dx, double dy) {
        int f = 8 * leaf, t = f + TIGHT;
        double ax = MULTIPLIER * dx, ay = MULTIPLIER * dy;
        nd[f] = nd[t] - EXTENSION + Math.min(0, ax);
        nd[f + 1] = nd[t + 1] + EXTENSION + Math.max(0, ax);
        nd[f + 2] = nd[t + 2] - EXTENSION + Math.min(0, ay);
        nd[f + 3] = nd[t + 3] + EXTENSION + Math.max(0, ay);
    }

    @Override
    public void removing(int slot) {
        int leaf = leafOf[slot];
        removeLeaf(leaf);
        freeNode(leaf);
        mark(leaf);  // its candidates go at the next pairs
    }

    @Override
    public void relocated(int from, int to) {
        int leaf = leafOf[from];
        leafOf[to] = leaf;
        nl[4 * leaf + CHILD2] = to;
    }

    @Override
    public void cleared() {
        nodes = 0;
        freeNode = NONE;
        root = NONE;
        pairCount = 0;
        insertions = 0;
        for (int i = 0; i < markedCount; i++) {
            marked[markedList[i]] = false;
        }
        markedCount = 0;
    }

    @Override
    public void grown(int capacity) {
        leafOf = Arrays.copyOf(leafOf, capacity);
    }

    // ---------------------------------------------------------------- the tree, as b2DynamicTree

    private int newNode() {
        int node;
        if (freeNode != NONE) {
            node = freeNode;
            freeNode = nl[4 * node + PARENT];
        } else {
            if (nodes == nl.length / 4) {
                int capacity = Math.max(16, 2 * nodes);
                nd = Arrays.copyOf(nd, 8 * capacity);
                nl = Arrays.copyOf(nl, 4 * capacity);
                ndSpare = new double[8 * capacity];
                nlSpare = new int[4 * capacity];
                renumbered = new int[capacity];
                marked = Arrays.copyOf(marked, capacity);
                markedBelow = Arrays.copyOf(markedBelow, capacity);
            }
            node = nodes++;
        }
        int l = 4 * node;
        nl[l + CHILD1] = NONE;
        nl[l + CHILD2] = NONE;
        nl[l + PARENT] = NONE;
        nl[l + HEIGHT] = 0;
        markedBelow[node] = 0;
        return node;
    }

    private void freeNode(int node) {
        nl[4 * node + PARENT] = freeNode;
        nl[4 * node + HEIGHT] = -1;
        freeNode = node;
    }

    private boolean isLeaf(int node) {
        return nl[4 * node + CHILD1] == NONE;
    }

    private int child1(int node) {
        return nl[4 * node + CHILD1];
    }

    private int child2(int node) {
        return nl[4 * node + CHILD2];
    }

    private int parent(int node) {
        return nl[4 * node + PARENT];
    }

    private int height(int node) {
        return nl[4 * node + HEIGHT];
    }

    private static double perimeter(double minX, double maxX, double minY, double maxY) {
        return 2 * ((maxX - minX) + (maxY - minY));
    }

    private double perimeter(int node) {
        int f = 8 * node;
        return perimeter(nd[f], nd[f + 1], nd[f + 2], nd[f + 3]);
    }

    /** The perimeter of the union of node's box and the given one. */
    private double unionPerimeter(int node, double minX, double maxX, double minY, double maxY) {
        int f = 8 * node;
        return perimeter(Math.min(nd[f], minX), Math.max(nd[f + 1], maxX), Math.min(nd[f + 2], minY), Math.max(nd[f + 3], maxY));
    }

    private void insertLeaf(int leaf) {
        insertions++;
        if (root == NONE) {
            root = leaf;
            nl[4 * leaf + PARENT] = NONE;
            return;
        }
        int f = 8 * leaf;
        double lx0 = nd[f], lx1 = nd[f + 1], ly0 = nd[f + 2], ly1 = nd[f + 3];
        int index = root;
        while (!isLeaf(index)) {
            int c1 = child1(index), c2 = child2(index);
            double area = perimeter(index);
            double combined = unionPerimeter(index, lx0, lx1, ly0, ly1);
            double cost = 2 * combined;                 // a new parent for this node and the leaf
            double inheritance = 2 * (combined - area);  // the least cost of going further down
            double cost1 = descentCost(c1, lx0, lx1, ly0, ly1) + inheritance;
            double cost2 = descentCost(c2, lx0, lx1, ly0, ly1) + inheritance;
            if (cost < cost1 && cost < cost2) {
                break;
            }
            index = cost1 < cost2 ? c1 : c2;
        }
        int sibling = index;
        int oldParent = parent(sibling);
        int newParent = newNode();
        nl[4 * newParent + PARENT] = oldParent;
        if (oldParent != NONE) {
            replaceChild(oldParent, sibling, newParent);
        } else {
            root = newParent;
        }
        nl[4 * newParent + CHILD1] = sibling;
        nl[4 * newParent + CHILD2] = leaf;
        nl[4 * sibling + PARENT] = newParent;
        nl[4 * leaf + PARENT] = newParent;
        refit(newParent);
    }

    private double descentCost(int c, double minX, double maxX, double minY, double maxY) {
        double grown = unionPerimeter(c, minX, maxX, minY, maxY);
        return isLeaf(c) ? grown : grown - perimeter(c);
    }

    private void replaceChild(int node, int old, int now) {
        int l = 4 * node;
        if (nl[l + CHILD1] == old) {
            nl[l + CHILD1] = now;
        } else {
            nl[l + CHILD2] = now;
        }
    }

    private void removeLeaf(int leaf) {
        if (leaf == root) {
            root = NONE;
            return;
        }
        int up = parent(leaf);
        int grandParent = parent(up);
        int sibling = child1(up) == leaf ? child2(up) : child1(up);
        if (grandParent != NONE) {
            replaceChild(grandParent, up, sibling);
            nl[4 * sibling + PARENT] = grandParent;
            freeNode(up);
            refit(grandParent);
        } else {
            root = sibling;
            nl[4 * sibling + PARENT] = NONE;
            freeNode(up);
        }
    }

    /** Walks up from node to the root, balancing and refitting boxes and heights. */
    private void refit(int node) {
        for (int index = node; index != NONE; index = parent(index)) {
            index = balance(index);
            setFromChildren(index);
        }
    }

    private void setFromChildren(int node) {
        int c1 = child1(node), c2 = child2(node), f = 8 * node, f1 = 8 * c1, f2 = 8 * c2;
        nl[4 * node + HEIGHT] = 1 + Math.max(height(c1), height(c2));
        markedBelow[node] = markedBelow[c1] + markedBelow[c2];
        nd[f] = Math.min(nd[f1], nd[f2]);
        nd[f + 1] = Math.max(nd[f1 + 1], nd[f2 + 1]);
        nd[f + 2] = Math.min(nd[f1 + 2], nd[f2 + 2]);
        nd[f + 3] = Math.max(nd[f1 + 3], nd[f2 + 3]);
    }

    /**
     * If a is out of balance, rotates its taller child up into its place (Box2D's Balance):
     * that child keeps a as one child and the taller of its own children as the other, and a
     * takes the shorter one. Returns the node now in a's place.
     */
    private int balance(int a) {
        if (isLeaf(a) || height(a) < 2) {
            return a;
        }
        int b = child1(a), c = child2(a);
        int lean = height(c) - height(b);
        if (lean > 1) {
            return rotateUp(a, c, true);
        }
        if (lean < -1) {
            return rotateUp(a, b, false);
        }
        return a;
    }

    /** Rotates child {@code up} into a's place; {@code second} says it was a's second child. */
    private int rotateUp(int a, int up, boolean second) {
        int f = child1(up), g = child2(up);
        int aParent = parent(a);
        nl[4 * up + CHILD1] = a;
        nl[4 * up + PARENT] = aParent;
        nl[4 * a + PARENT] = up;
        if (aParent != NONE) {
            replaceChild(aParent, a, up);
        } else {
            root = up;
        }
        int taller = height(f) > height(g) ? f : g, shorter = taller == f ? g : f;
        nl[4 * up + CHILD2] = taller;
        nl[4 * a + (second ? CHILD2 : CHILD1)] = shorter;
        nl[4 * shorter + PARENT] = a;
        setFromChildren(a);
        setFromChildren(up);
        return up;
    }

    // ---------------------------------------------------------------- the questions

    @Override
    public void findPairs(PairConsumer out) {
        if (markedCount > 0) {
            updateCandidates();
        }
        double[] d = nd;  // locals: the callback could change a field, so it would be read again after each
        int[] a = pairA, b = pairB, links = nl;
        for (int i = 0, n = pairCount; i < n; i++) {
            int p = a[i], q = b[i];
            if (overlap(d, 8 * p + TIGHT, d, 8 * q + TIGHT)) {
                emit(out, ids[links[4 * p + CHILD2]], ids[links[4 * q + CHILD2]]);
            }
        }
        tally += pairCount;
    }

    /** Drops the candidates with a marked leaf, then finds those of the marked leaves. */
    private void updateCandidates() {
        int kept = 0;
        for (int i = 0; i < pairCount; i++) {
            int p = pairA[i], q = pairB[i];
            if (!marked[p] && !marked[q]) {
                pairA[kept] = p;
                pairB[kept++] = q;
            }
        }
        pairCount = kept;
        if (root != NONE) {
            selfMarked(root);
        }
        for (int i = 0; i < markedCount; i++) {
            int node = markedList[i];
            marked[node] = false;
            if (height(node) == 0) {  // still a leaf in the tree: take it off the counts above
                for (int up = node; up != NONE; up = parent(up)) {
                    markedBelow[up]--;
                }
            }
        }
        markedCount = 0;
        if (root != NONE && 2L * insertions > count) {
            renumber();
        }
    }

    /**
     * Renumbers the nodes in depth-first order, into the spare arrays, and swaps them in; the
     * free nodes are dropped. Only between pairs() updates: no leaf is marked, every candidate
     * is a leaf in the tree.
     */
    private void renumber() {
        int n = number(root, 0);
        for (int old = 0; old < nodes; old++) {
            if (height(old) < 0) {
                continue;  // free
            }
            int now = renumbered[old], l = 4 * old, m = 4 * now;
            System.arraycopy(nd, 8 * old, ndSpare, 8 * now, 8);
            boolean leaf = nl[l + CHILD1] == NONE;
            nlSpare[m + CHILD1] = leaf ? NONE : renumbered[nl[l + CHILD1]];
            nlSpare[m + CHILD2] = leaf ? nl[l + CHILD2] : renumbered[nl[l + CHILD2]];
            nlSpare[m + PARENT] = nl[l + PARENT] == NONE ? NONE : renumbered[nl[l + PARENT]];
            nlSpare[m + HEIGHT] = nl[l + HEIGHT];
            if (leaf) {
                leafOf[nl[l + CHILD2]] = now;
            }
        }
        for (int i = 0; i < pairCount; i++) {
            pairA[i] = renumbered[pairA[i]];
            pairB[i] = renumbered[pairB[i]];
        }
        double[] d = nd;
        nd = ndSpare;
        ndSpare = d;
        int[] l = nl;
        nl = nlSpare;
        nlSpare = l;
        root = renumbered[root];
        nodes = n;
        freeNode = NONE;
        insertions = 0;
        Arrays.fill(markedBelow, 0, n, 0);  // no leaf is marked now; a freed node's old count must not carry over
    }

    /** Numbers the subtree from {@code next} on, node before children; returns the next free number. */
    private int number(int node, int next) {
        renumbered[node] = next++;
        if (!isLeaf(node)) {
            next = number(child1(node), next);
            next = number(child2(node), next);
        }
        return next;
    }

    /** The new candidates within a subtree: none if it has no marked leaf. */
    private void selfMarked(int node) {
        if (isLeaf(node) || markedBelow[node] == 0) {
            return;
        }
        int c1 = child1(node), c2 = child2(node);
        selfMarked(c1);
        selfMarked(c2);
        crossMarked(c1, c2);
    }

    /** The new candidates with one leaf under a and one under b, at least one of them marked. */
    private void crossMarked(int a, int b) {
        if (markedBelow[a] + markedBelow[b] == 0 || !overlap(nd, 8 * a + BOX, nd, 8 * b + BOX)) {
            return;
        }
        boolean leafA = isLeaf(a), leafB = isLeaf(b);
        if (leafA && leafB) {
            if (pairCount == pairA.length) {
                int capacity = Math.max(64, 2 * pairCount);
                pairA = Arrays.copyOf(pairA, capacity);
                pairB = Arrays.copyOf(pairB, capacity);
            }
            pairA[pairCount] = a;
            pairB[pairCount++] = b;
        } else if (leafB || (!leafA && height(a) >= height(b))) {
            crossMarked(child1(a), b);
            crossMarked(child2(a), b);
        } else {
            crossMarked(a, child1(b));
            crossMarked(a, child2(b));
        }
    }

    @Override
    public void findBoxes(double x, double y, double right, double bottom, IntConsumer out) {
        if (root != NONE) {
            query(root, x, y, right, bottom, out);
        }
    }

    private void query(int node, double x, double y, double right, double bottom, IntConsumer out) {
        int f = 8 * node;
        if (!overlap(nd[f], nd[f + 1], nd[f + 2], nd[f + 3], x, right, y, bottom)) {
            return;
        }
        if (isLeaf(node)) {
            tally++;
            if (overlap(x, right, y, bottom, nd[f + TIGHT], nd[f + TIGHT + 1], nd[f + TIGHT + 2], nd[f + TIGHT + 3])) {
                out.accept(ids[child2(node)]);
            }
            return;
        }
        query(child1(node), x, y, right, bottom, out);
        query(child2(node), x, y, right, bottom, out);
    }

    @Override
    public void findRayCandidates(RayCast ray) {
        if (root != NONE) {
            rayDown(root, ray);
        }
    }

    private void rayDown(int node, RayCast ray) {
        int f = 8 * node;
        if (!ray.mayEnter(nd[f], nd[f + 2], nd[f + 1], nd[f + 3])) {
            return;
        }
        if (isLeaf(node)) {
            ray.consider(child2(node));
        } else {
            rayDown(child1(node), ray);
            rayDown(child2(node), ray);
        }
    }

    @Override
    public void findCells(BoxConsumer out) {
        if (root != NONE) {
            cellsDown(root, 0, out);
        }
    }

    private void cellsDown(int node, int depth, BoxConsumer out) {
        int f = 8 * node;
        out.box(depth, (float) nd[f], (float) nd[f + 2], (float) (nd[f + 1] - nd[f]), (float) (nd[f + 3] - nd[f + 2]));
        if (!isLeaf(node)) {
            cellsDown(child1(node), depth + 1, out);
            cellsDown(child2(node), depth + 1, out);
        }
    }

    @Override
    public String toString() {
        return "dynamicTree";
    }
}
