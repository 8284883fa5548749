package hitbox.bench;

import java.util.Arrays;
import java.util.Random;

import hitbox.Collide;

/**
 * The broad-phase workload: n boxes moving 0 to 2 pixels a frame in a 2000 x 2000 world,
 * bouncing off walls. One frame moves every box; the contenders then put every box and count
 * every overlapping pair.
 *
 * <ul>
 *   <li>{@code uniform}: sizes 2 to 10 pixels (width and height each), anywhere in the world.</li>
 *   <li>{@code clustered}: the same boxes in 16 squares of 250 x 250 pixels at random places
 *       (a quarter of the world: about 4 times as dense), each box bouncing inside its own
 *       square, so the clusters stay clustered however long the run.</li>
 *   <li>{@code heavy}: heavy-tailed sizes, Pareto with minimum 2 and exponent 1.5, capped at
 *       400: the width is the drawn size, the height half to all of it. The mean is near the
 *       uniform world's; one box in a hundred is over 40 pixels, a few are hundreds.</li>
 * </ul>
 */
final class BroadPhaseWorld {
    static final float SIDE = 2000;

    final int n;
    final float[] x;
    final float[] y;
    final float[] w;
    final float[] h;
    final float[] vx;
    final float[] vy;
    /** The walls each box bounces off: the world's, or its cluster's. */
    private final float[] left;
    private final float[] top;
    private final float[] right;
    private final float[] bottom;

    BroadPhaseWorld(String kind, int n, long seed) {
        this.n = n;
        x = new float[n];
        y = new float[n];
        w = new float[n];
        h = new float[n];
        vx = new float[n];
        vy = new float[n];
        left = new float[n];
        top = new float[n];
        right = new float[n];
        bottom = new float[n];
        Random random = new Random(seed);
        float[] clusterX = new float[16], clusterY = new float[16];
        for (int c = 0; c < 16; c++) {
            clusterX[c] = random.nextFloat() * (SIDE - 250);
            clusterY[c] = random.nextFloat() * (SIDE - 250);
        }
        for (int i = 0; i < n; i++) {
            switch (kind) {
                case "uniform":
                case "clustered":
                    w[i] = 2 + 8 * random.nextFloat();
                    h[i] = 2 + 8 * random.nextFloat();
                    break;
                case "heavy":
                    float s = (float) Math.min(400, 2 / Math.pow(1 - random.nextDouble(), 1 / 1.5));
                    w[i] = s;
                    h[i] = Math.max(2, s * (0.5f + 0.5f * random.nextFloat()));
                    break;
                default:
                    throw new IllegalArgumentException("no world " + kind);
            }
            if (kind.equals("clustered")) {
                int c = random.nextInt(16);
                left[i] = clusterX[c];
                top[i] = clusterY[c];
                right[i] = clusterX[c] + 250;
                bottom[i] = clusterY[c] + 250;
            } else {
                right[i] = SIDE;
                bottom[i] = SIDE;
            }
            x[i] = left[i] + random.nextFloat() * (right[i] - left[i] - w[i]);
            y[i] = top[i] + random.nextFloat() * (bottom[i] - top[i] - h[i]);
            double speed = 2 * random.nextDouble(), angle = 2 * Math.PI * random.nextDouble();
            vx[i] = (float) (speed * Math.cos(angle));
            vy[i] = (float) (speed * Math.sin(angle));
        }
    }

    /** One frame of motion: every box moves, and turns back from a wall it went past. */
    void step() {
        for (int i = 0; i < n; i++) {
            float nx = x[i] + vx[i], ny = y[i] + vy[i];
            if (nx < left[i] || nx + w[i] > right[i]) {
                vx[i] = -vx[i];
            } else {
                x[i] = nx;
            }
            if (ny < top[i] || ny + h[i] > bottom[i]) {
                vy[i] = -vy[i];
            } else {
                y[i] = ny;
            }
        }
    }

    /** Do boxes i and j overlap? The library's test, the one every contender must agree with. */
    boolean overlap(int i, int j) {
        return Collide.rectRect(x[i], y[i], w[i], h[i], x[j], y[j], w[j], h[j]);
    }

    /** The number of overlapping pairs, by a plain sort and sweep written here, for checking the contenders. */
    long referencePairs() {
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        Arrays.sort(order, (a, b) -> Float.compare(x[a], x[b]));
        long pairs = 0;
        for (int k = 0; k < n; k++) {
            int i = order[k];
            for (int m = k + 1; m < n && x[order[m]] < (double) x[i] + w[i]; m++) {
                if (overlap(i, order[m])) {
                    pairs++;
                }
            }
        }
        return pairs;
    }
}
