package hitbox;

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
 * <p>The fat boxes are floats rounded outward, so each holds its box exactly; a tree box test
 * with strict comparisons then never loses a pair, and the leaves are decided by the exact
 * test on the stored boxes. Pairs come from walking the tree against itself, each pair of
 * subtrees once.
 */
final class DynamicTreeBroadPhase extends AbstractBroadPhase {
    /** Pixels added on each side of a leaf's box (Box2D: 0.1 m, about 2 to 3 pixels at its usual scale). */
    static final float EXTENSION = 2;
    /** How many frames of its last move a leaf's box is grown by ahead of it (Box2D 2.4: 4). */
    static final float MULTIPLIER = 4;
    private static final int NONE = -1;

    private float[] minX = new float[0];
    private float[] minY = new float[0];
    private float[] maxX = new float[0];
    private float[] maxY = new float[0];
    private int[] parent = new int[0];
    private int[] child1 = new int[0];
    private int[] child2 = new int[0];
    /** 0 for a leaf, -1 for a free node. */
    private int[] height = new int[0];
    private int[] slotOfLeaf = new int[0];
    private int nodes;
    private int freeNode = NONE;
    private int root = NONE;

    private int[] leafOf = new int[0];

    // ---------------------------------------------------------------- changes

    @Override
    void added(int slot) {
        int leaf = newNode();
        slotOfLeaf[leaf] = slot;
        leafOf[slot] = leaf;
        fatten(leaf, slot, 0, 0);
        insertLeaf(leaf);
    }

    @Override
    void moved(int slot, float oldX, float oldY) {
        int leaf = leafOf[slot];
        double dx = (double) xs[slot] - oldX, dy = (double) ys[slot] - oldY;
        if (holds(leaf, slot)) {
            // Still inside: nothing to do, unless the fat box is far larger than it would be now.
            double r = EXTENSION * 5;  // Box2D: the fat box it would get now, grown by 4 extensions more
            double hugeMinX = xs[slot] - r + Math.min(0, MULTIPLIER * dx), hugeMaxX = rights[slot] + r + Math.max(0, MULTIPLIER * dx);
            double hugeMinY = ys[slot] - r + Math.min(0, MULTIPLIER * dy), hugeMaxY = bottoms[slot] + r + Math.max(0, MULTIPLIER * dy);
            if (hugeMinX <= minX[leaf] && hugeMinY <= minY[leaf] && maxX[leaf] <= hugeMaxX && maxY[leaf] <= hugeMaxY) {
                return;
            }
        }
        removeLeaf(leaf);
        fatten(leaf, slot, dx, dy);
        insertLeaf(leaf);
    }

    private boolean holds(int leaf, int slot) {
        return minX[leaf] <= xs[slot] && minY[leaf] <= ys[slot] && rights[slot] <= maxX[leaf] && bottoms[slot] <= maxY[leaf];
    }

    /** The leaf's fat box: the slot's box grown by the extension and by the move ahead, rounded outward. */
    private void fatten(int leaf, int slot, double dx, double dy) {
        double left = (double) xs[slot] - EXTENSION, top = (double) ys[slot] - EXTENSION;
        double right = rights[slot] + EXTENSION, bottom = bottoms[slot] + EXTENSION;
        double ax = MULTIPLIER * dx, ay = MULTIPLIER * dy;
        if (ax < 0) {
            left += ax;
        } else {
            right += ax;
        }
        if (ay < 0) {
            top += ay;
        } else {
            bottom += ay;
        }
        minX[leaf] = down(left);
        minY[leaf] = down(top);
        maxX[leaf] = up(right);
        maxY[leaf] = up(bottom);
    }

    /** The largest float at or below v. */
    private static float down(double v) {
        float f = (float) v;
        return f > v ? Math.nextDown(f) : f;
    }

    /** The smallest float at or above v. */
    private static float up(double v) {
        float f = (float) v;
        return f < v ? Math.nextUp(f) : f;
    }

    @Override
    void removing(int slot) {
        int leaf = leafOf[slot];
        removeLeaf(leaf);
        freeNode(leaf);
    }

    @Override
    void relocated(int from, int to) {
        int leaf = leafOf[from];
        leafOf[to] = leaf;
        slotOfLeaf[leaf] = to;
    }

    @Override
    void cleared() {
        nodes = 0;
        freeNode = NONE;
        root = NONE;
    }

    @Override
    void grown(int capacity) {
        leafOf = Arrays.copyOf(leafOf, capacity);
    }

    // ---------------------------------------------------------------- the tree, as b2DynamicTree

    private int newNode() {
        int node;
        if (freeNode != NONE) {
            node = freeNode;
            freeNode = parent[node];
        } else {
            if (nodes == parent.length) {
                int capacity = Math.max(16, 2 * nodes);
                minX = Arrays.copyOf(minX, capacity);
                minY = Arrays.copyOf(minY, capacity);
                maxX = Arrays.copyOf(maxX, capacity);
                maxY = Arrays.copyOf(maxY, capacity);
                parent = Arrays.copyOf(parent, capacity);
                child1 = Arrays.copyOf(child1, capacity);
                child2 = Arrays.copyOf(child2, capacity);
                height = Arrays.copyOf(height, capacity);
                slotOfLeaf = Arrays.copyOf(slotOfLeaf, capacity);
            }
            node = nodes++;
        }
        parent[node] = NONE;
        child1[node] = NONE;
        child2[node] = NONE;
        height[node] = 0;
        slotOfLeaf[node] = NONE;
        return node;
    }

    private void freeNode(int node) {
        parent[node] = freeNode;
        height[node] = -1;
        freeNode = node;
    }

    private boolean isLeaf(int node) {
        return child1[node] == NONE;
    }

    private static float perimeter(float x0, float y0, float x1, float y1) {
        return 2 * ((x1 - x0) + (y1 - y0));
    }

    /** The perimeter of the union of node's box and the given one. */
    private float unionPerimeter(int node, float x0, float y0, float x1, float y1) {
        return perimeter(Math.min(minX[node], x0), Math.min(minY[node], y0), Math.max(maxX[node], x1), Math.max(maxY[node], y1));
    }

    private void insertLeaf(int leaf) {
        if (root == NONE) {
            root = leaf;
            parent[leaf] = NONE;
            return;
        }
        float lx0 = minX[leaf], ly0 = minY[leaf], lx1 = maxX[leaf], ly1 = maxY[leaf];
        int index = root;
        while (!isLeaf(index)) {
            int c1 = child1[index], c2 = child2[index];
            float area = perimeter(minX[index], minY[index], maxX[index], maxY[index]);
            float combined = unionPerimeter(index, lx0, ly0, lx1, ly1);
            float cost = 2 * combined;                 // a new parent for this node and the leaf
            float inheritance = 2 * (combined - area);  // the least cost of going further down
            float cost1 = descentCost(c1, lx0, ly0, lx1, ly1) + inheritance;
            float cost2 = descentCost(c2, lx0, ly0, lx1, ly1) + inheritance;
            if (cost < cost1 && cost < cost2) {
                break;
            }
            index = cost1 < cost2 ? c1 : c2;
        }
        int sibling = index;
        int oldParent = parent[sibling];
        int newParent = newNode();
        parent[newParent] = oldParent;
        minX[newParent] = Math.min(lx0, minX[sibling]);
        minY[newParent] = Math.min(ly0, minY[sibling]);
        maxX[newParent] = Math.max(lx1, maxX[sibling]);
        maxY[newParent] = Math.max(ly1, maxY[sibling]);
        height[newParent] = height[sibling] + 1;
        if (oldParent != NONE) {
            replaceChild(oldParent, sibling, newParent);
        } else {
            root = newParent;
        }
        child1[newParent] = sibling;
        child2[newParent] = leaf;
        parent[sibling] = newParent;
        parent[leaf] = newParent;
        refit(parent[leaf]);
    }

    private float descentCost(int c, float x0, float y0, float x1, float y1) {
        float grown = unionPerimeter(c, x0, y0, x1, y1);
        return isLeaf(c) ? grown : grown - perimeter(minX[c], minY[c], maxX[c], maxY[c]);
    }

    private void replaceChild(int node, int old, int now) {
        if (child1[node] == old) {
            child1[node] = now;
        } else {
            child2[node] = now;
        }
    }

    private void removeLeaf(int leaf) {
        if (leaf == root) {
            root = NONE;
            return;
        }
        int up = parent[leaf];
        int grandParent = parent[up];
        int sibling = child1[up] == leaf ? child2[up] : child1[up];
        if (grandParent != NONE) {
            replaceChild(grandParent, up, sibling);
            parent[sibling] = grandParent;
            freeNode(up);
            refit(grandParent);
        } else {
            root = sibling;
            parent[sibling] = NONE;
            freeNode(up);
        }
    }

    /** Walks up from node to the root, balancing and refitting boxes and heights. */
    private void refit(int node) {
        for (int index = node; index != NONE; index = parent[index]) {
            index = balance(index);
            setFromChildren(index);
        }
    }

    private void setFromChildren(int node) {
        int c1 = child1[node], c2 = child2[node];
        height[node] = 1 + Math.max(height[c1], height[c2]);
        minX[node] = Math.min(minX[c1], minX[c2]);
        minY[node] = Math.min(minY[c1], minY[c2]);
        maxX[node] = Math.max(maxX[c1], maxX[c2]);
        maxY[node] = Math.max(maxY[c1], maxY[c2]);
    }

    /**
     * If a is out of balance, rotates its taller child up into its place (Box2D's Balance):
     * that child keeps a as one child and the taller of its own children as the other, and a
     * takes the shorter one. Returns the node now in a's place.
     */
    private int balance(int a) {
        if (isLeaf(a) || height[a] < 2) {
            return a;
        }
        int b = child1[a], c = child2[a];
        int lean = height[c] - height[b];
        if (lean > 1) {
            return rotateUp(a, c, true);
        }
        if (lean < -1) {
            return rotateUp(a, b, false);
        }
        return a;
    }

    /** Rotates child up into a's place; {@code second} says child was a's second child. */
    private int rotateUp(int a, int up, boolean second) {
        int f = child1[up], g = child2[up];
        child1[up] = a;
        parent[up] = parent[a];
        parent[a] = up;
        if (parent[up] != NONE) {
            replaceChild(parent[up], a, up);
        } else {
            root = up;
        }
        int taller = height[f] > height[g] ? f : g, shorter = taller == f ? g : f;
        child2[up] = taller;
        if (second) {
            child2[a] = shorter;
        } else {
            child1[a] = shorter;
        }
        parent[shorter] = a;
        setFromChildren(a);
        setFromChildren(up);
        return up;
    }

    // ---------------------------------------------------------------- the questions

    /** Could boxes inside these two nodes' boxes overlap? Strict, as the exact test is. */
    private boolean touch(int a, int b) {
        return maxX[a] > minX[b] && minX[a] < maxX[b] && maxY[a] > minY[b] && minY[a] < maxY[b];
    }

    @Override
    void findPairs(PairConsumer out) {
        if (root != NONE) {
            self(root, out);
        }
    }

    private void self(int node, PairConsumer out) {
        if (isLeaf(node)) {
            return;
        }
        self(child1[node], out);
        self(child2[node], out);
        cross(child1[node], child2[node], out);
    }

    /** Every pair with one leaf under a and one under b. */
    private void cross(int a, int b, PairConsumer out) {
        if (!touch(a, b)) {
            return;
        }
        boolean leafA = isLeaf(a), leafB = isLeaf(b);
        if (leafA && leafB) {
            int s = slotOfLeaf[a], t = slotOfLeaf[b];
            tally++;
            if (overlapSlots(s, t)) {
                emit(out, ids[s], ids[t]);
            }
        } else if (leafB || (!leafA && height[a] >= height[b])) {
            cross(child1[a], b, out);
            cross(child2[a], b, out);
        } else {
            cross(a, child1[b], out);
            cross(a, child2[b], out);
        }
    }

    @Override
    void findBoxes(double x, double y, double right, double bottom, IntConsumer out) {
        if (root != NONE) {
            query(root, x, y, right, bottom, out);
        }
    }

    private void query(int node, double x, double y, double right, double bottom, IntConsumer out) {
        if (!(maxX[node] > x && minX[node] < right && maxY[node] > y && minY[node] < bottom)) {
            return;
        }
        if (isLeaf(node)) {
            int s = slotOfLeaf[node];
            tally++;
            if (overlap(x, right, y, bottom, xs[s], rights[s], ys[s], bottoms[s])) {
                out.accept(ids[s]);
            }
            return;
        }
        query(child1[node], x, y, right, bottom, out);
        query(child2[node], x, y, right, bottom, out);
    }

    @Override
    void findRayCandidates(RayCast ray) {
        if (root != NONE) {
            rayDown(root, ray);
        }
    }

    private void rayDown(int node, RayCast ray) {
        if (!ray.mayEnter(minX[node], minY[node], maxX[node], maxY[node])) {
            return;
        }
        if (isLeaf(node)) {
            ray.consider(slotOfLeaf[node]);
        } else {
            rayDown(child1[node], ray);
            rayDown(child2[node], ray);
        }
    }

    @Override
    void findCells(BoxConsumer out) {
        if (root != NONE) {
            cellsDown(root, 0, out);
        }
    }

    private void cellsDown(int node, int depth, BoxConsumer out) {
        out.box(depth, minX[node], minY[node], maxX[node] - minX[node], maxY[node] - minY[node]);
        if (!isLeaf(node)) {
            cellsDown(child1[node], depth + 1, out);
            cellsDown(child2[node], depth + 1, out);
        }
    }

    @Override
    public String toString() {
        return "dynamicTree";
    }
}
