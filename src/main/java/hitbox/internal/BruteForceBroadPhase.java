package hitbox.internal;

import hitbox.*;

import java.util.function.IntConsumer;

/** {@link BroadPhase#bruteForce()}: every pair, every box; no index at all. */
public final class BruteForceBroadPhase extends AbstractBroadPhase {

    @Override
    public void added(int slot) {
    }

    @Override
    public void moved(int slot, float oldX, float oldY) {
    }

    @Override
    public void removing(int slot) {
    }

    @Override
    public void relocated(int from, int to) {
    }

    @Override
    public void cleared() {
    }

    @Override
    public void grown(int capacity) {
    }

    @Override
    public void findPairs(PairConsumer out) {
        int n = count;
        tally += (long) n * (n - 1) / 2;
        double[] b = box;  // a local: the callback could change a field, so it would be read again after each
        int[] id = ids;
        for (int s = 0; s < n; s++) {
            int k = 4 * s;
            double x = b[k], right = b[k + 1], y = b[k + 2], bottom = b[k + 3];
            for (int t = s + 1; t < n; t++) {
                int j = 4 * t;
                if (overlap(x, right, y, bottom, b[j], b[j + 1], b[j + 2], b[j + 3])) {
                    emit(out, id[s], id[t]);
                }
            }
        }
    }

    @Override
    public void findBoxes(double x, double y, double right, double bottom, IntConsumer out) {
        tally += count;
        for (int s = 0; s < count; s++) {
            int k = 4 * s;
            if (overlap(x, right, y, bottom, box[k], box[k + 1], box[k + 2], box[k + 3])) {
                out.accept(ids[s]);
            }
        }
    }

    @Override
    public void findRayCandidates(RayCast ray) {
        for (int s = 0; s < count; s++) {
            ray.consider(s);
        }
    }

    @Override
    public String toString() {
        return "bruteForce";
    }
}
