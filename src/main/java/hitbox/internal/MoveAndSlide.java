package hitbox.internal;

import hitbox.*;
import java.util.Arrays;

/**
 * The walk behind {@link Sweep#move}: a box goes until it first hits an obstacle, stands
 * against the face it hit, and slides on with the rest of its motion, the part into that
 * face dropped. Arguments are checked by {@code Sweep.move}.
 */
public final class MoveAndSlide {
    private MoveAndSlide() {
    }

    /**
     * Told of each stop of a walk, for a caller that reports what was hit (the world's move):
     * the index of the obstacle in the order given, the time of impact within that leg of the
     * walk, the obstacle's side hit, and where the box stands against it.
     */
    public interface Stops {
        void stop(int index, double t, Side side, float x, float y);
    }

    public static Sweep.Move move(Rect mover, float vx, float vy, Iterable<Rect> obstacles) {
        return move(mover, vx, vy, obstacles, null);
    }

    /** {@link #move(Rect, float, float, Iterable)}, telling {@code stops} (if not null) of each stop. */
    public static Sweep.Move move(Rect mover, float vx, float vy, Iterable<Rect> obstacles, Stops stops) {
        float[] end = new float[4];
        float[] boxes = new float[16];
        int count = 0;
        for (Rect o : obstacles) {
            if (4 * count == boxes.length) {
                boxes = Arrays.copyOf(boxes, 2 * boxes.length);
            }
            boxes[4 * count] = o.x();
            boxes[4 * count + 1] = o.y();
            boxes[4 * count + 2] = o.w();
            boxes[4 * count + 3] = o.h();
            count++;
        }
        int sides = walk(mover.x(), mover.y(), mover.w(), mover.h(), vx, vy, boxes, count, stops, end);
        return new Sweep.Move(end[0], end[1], end[2], end[3], SideSets.of(sides));
    }

    /**
     * The walk of {@link #move(Rect, float, float, Iterable, Stops)} with no object made, for
     * the world's moves, which make their own: the box at (x0, y0) of size w by h, the
     * obstacles' boxes as numbers (x, y, w, h each, {@code count} of them); where the box
     * ends and the velocity to keep are written into {@code end} (x, y, vx, vy), and the
     * sides hit returned as {@link SideSets} bits.
     */
    public static int walk(float x0, float y0, float w, float h, float vx, float vy, float[] boxes, int count,
                           Stops stops, float[] end) {
        float x = x0, y = y0;
        double mx = vx, my = vy;  // the motion still to do this frame
        float keepVx = vx, keepVy = vy;
        int sides = 0;
        for (int stop = 0; stop < Sweep.MAX_SLIDES && (mx != 0 || my != 0); stop++) {
            double first = Slabs.INF;
            int hitIndex = -1;
            for (int i = 0; i < count; i++) {
                float ox = boxes[4 * i], oy = boxes[4 * i + 1], ow = boxes[4 * i + 2], oh = boxes[4 * i + 3];
                if (!RawTests.rectRect(x0, y0, w, h, ox, oy, ow, oh)) {
                    double t = SweptPairs.rectRectTime(x, y, w, h, mx, my, ox, oy, ow, oh);
                    if (t < first) {
                        first = t;
                        hitIndex = i;
                    }
                }
            }
            if (hitIndex < 0) {
                safeAlong(x, y, w, h, mx, my, 1, (float) (x + mx), (float) (y + my), x0, y0, boxes, count, end);
                x = end[0];
                y = end[1];
                break;
            }
            float hx = boxes[4 * hitIndex], hy = boxes[4 * hitIndex + 1], hw = boxes[4 * hitIndex + 2], hh = boxes[4 * hitIndex + 3];
            Earliest e = SweptPairs.rectRectEntry(x, y, w, h, mx, my, hx, hy, hw, hh);
            // The entry's normal is the face's outward one; the side is the face it points out of.
            Side side = e.inside ? Side.NONE : Side.ofNormal(-e.nx, -e.ny);
            if (side == Side.NONE) {
                break;  // cannot happen: the box is never left overlapping an obstacle it did not start in
            }
            // Stand exactly against the face hit (rounding could leave it a hair inside),
            // the other coordinate where the motion had got to.
            float tx = (float) (x + first * mx), ty = (float) (y + first * my);
            tx = RectPush.placedX(side, tx, w, hx, hw);
            ty = RectPush.placedY(side, ty, h, hy, hh);
            safeAlong(x, y, w, h, mx, my, first, tx, ty, x0, y0, boxes, count, end);
            x = end[0];
            y = end[1];
            if (stops != null) {
                stops.stop(hitIndex, first, side, x, y);
            }
            mx *= 1 - first;
            my *= 1 - first;
            if (side == Side.LEFT || side == Side.RIGHT) {
                mx = 0;
                keepVx = 0;
            } else {
                my = 0;
                keepVy = 0;
            }
            sides |= SideSets.bit(side);
        }
        end[0] = x;
        end[1] = y;
        end[2] = keepVx;
        end[3] = keepVy;
        return sides;
    }

    /**
     * The wanted stop (tx, ty) if it overlaps no obstacle (except those the box started in);
     * otherwise, which only rounding can cause, the farthest point along the motion before
     * {@code t} that is clear, found by halving. The start (x, y) is always clear. Written
     * into {@code at}[0] and [1].
     */
    private static void safeAlong(float x, float y, float w, float h, double mx, double my, double t,
                                  float tx, float ty, float x0, float y0, float[] boxes, int count, float[] at) {
        if (clear(tx, ty, w, h, x0, y0, boxes, count)) {
            at[0] = tx;
            at[1] = ty;
            return;
        }
        float bestX = x, bestY = y;
        double lo = 0, hi = t;
        for (int i = 0; i < 64 && lo < hi; i++) {
            double mid = (lo + hi) / 2;
            float px = (float) (x + mid * mx), py = (float) (y + mid * my);
            if (clear(px, py, w, h, x0, y0, boxes, count)) {
                lo = mid;
                bestX = px;
                bestY = py;
            } else {
                hi = mid;
            }
        }
        at[0] = bestX;
        at[1] = bestY;
    }

    private static boolean clear(float x, float y, float w, float h, float x0, float y0, float[] boxes, int count) {
        for (int i = 0; i < count; i++) {
            float ox = boxes[4 * i], oy = boxes[4 * i + 1], ow = boxes[4 * i + 2], oh = boxes[4 * i + 3];
            if (RawTests.rectRect(x, y, w, h, ox, oy, ow, oh)
                    && !RawTests.rectRect(x0, y0, w, h, ox, oy, ow, oh)) {
                return false;
            }
        }
        return true;
    }
}
