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
        double[] b = box;  // a local: the callback could change a field, so it would be read again after each
        int[] id = ids;
        for (int s = 0; s < n; s++) {
            for (int t = s + 1; t < n; t++) {
                if (overlap(b, 4 * s, b, 4 * t)) {
                    emit(out, id[s], id[t]);
                }
            }
        }
    }

    @Override
    void findBoxes(double x, double y, double right, double bottom, IntConsumer out) {
        tally += count;
        for (int s = 0; s < count; s++) {
            int k = 4 * s;
            if (overlap(x, right, y, bottom, box[k], box[k + 1], box[k + 2], box[k + 3])) {
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
