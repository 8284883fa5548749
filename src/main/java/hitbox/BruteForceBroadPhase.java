package hitbox;

import java.util.function.IntConsumer;

/** {@link BroadPhase#bruteForce()}: every pair, every box; no index at all. */
final class BruteForceBroadPhase extends AbstractBroadPhase {

    @Override
    void added(int slot) {
    }

    @Override
    void moved(int slot, float oldX, float oldY) {
    }

    @Override
    void removing(int slot) {
    }

    @Override
    void relocated(int from, int to) {
    }

    @Override
    void cleared() {
    }

    @Override
    void grown(int capacity) {
    }

    @Override
    void findPairs(PairConsumer out) {
        int n = count;
        tally += (long) n * (n - 1) / 2;
        for (int s = 0; s < n; s++) {
            for (int t = s + 1; t < n; t++) {
                if (overlapSlots(s, t)) {
                    emit(out, ids[s], ids[t]);
                }
            }
        }
    }

    @Override
    void findBoxes(double x, double y, double right, double bottom, IntConsumer out) {
        tally += count;
        for (int s = 0; s < count; s++) {
            if (overlap(x, right, y, bottom, xs[s], rights[s], ys[s], bottoms[s])) {
                out.accept(ids[s]);
            }
        }
    }

    @Override
    void findRayCandidates(RayCast ray) {
        for (int s = 0; s < count; s++) {
            ray.consider(s);
        }
    }

    @Override
    public String toString() {
        return "bruteForce";
    }
}
