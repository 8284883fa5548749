package hitbox.internal;

import hitbox.*;
import java.util.ArrayList;
import java.util.List;
import java.util.RandomAccess;

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
        List<Rect> list;
        if (obstacles instanceof List<Rect> l && l instanceof RandomAccess) {
            list = l;
        } else {
            list = new ArrayList<>();
            obstacles.forEach(list::add);
        }
        int sides = walk(mover, vx, vy, list, stops, end);
        return new Sweep.Move(end[0], end[1], end[2], end[3], SideSets.of(sides));
    }

    /**
     * The walk of {@link #move(Rect, float, float, Iterable, Stops)} with no result made, for
     * the world's moves, which make their own: where the box ends and the velocity to keep
     * are written into {@code end} (x, y, vx, vy), and the sides hit returned as
     * {@link SideSets} bits.
     */
    public static int walk(Rect mover, float vx, float vy, List<Rect> obstacles, Stops stops, float[] end) {
        final float x0 = mover.x(), y0 = mover.y(), w = mover.w(), h = mover.h();
        float x = x0, y = y0;
        double mx = vx, my = vy;  // the motion still to do this frame
        float keepVx = vx, keepVy = vy;
        int sides = 0;
        for (int stop = 0; stop < Sweep.MAX_SLIDES && (mx != 0 || my != 0); stop++) {
            double first = Slabs.INF;
            Rect hitRect = null;
            int index = 0, hitIndex = -1;
            for (int i = 0, n = obstacles.size(); i < n; i++) {  // by index: no iterator made per leg
                Rect o = obstacles.get(i);
                if (!RawTests.rectRect(x0, y0, w, h, o.x(), o.y(), o.w(), o.h())) {
                    double t = SweptPairs.rectRectTime(x, y, w, h, mx, my, o.x(), o.y(), o.w(), o.h());
                    if (t < first) {
                        first = t;
                        hitRect = o;
                        hitIndex = index;
                    }
                }
                index++;
            }
            if (hitRect == null) {
                safeAlong(x, y, w, h, mx, my, 1, (float) (x + mx), (float) (y + my), x0, y0, obstacles, end);
                x = end[0];
                y = end[1];
                break;
            }
            Earliest e = SweptPairs.rectRectEntry(x, y, w, h, mx, my, hitRect.x(), hitRect.y(), hitRect.w(), hitRect.h());
            // The entry's normal is the face's outward one; the side is the face it points out of.
            Side side = e.inside ? Side.NONE : Side.ofNormal(-e.nx, -e.ny);
            if (side == Side.NONE) {
                break;  // cannot happen: the box is never left overlapping an obstacle it did not start in
            }
            // Stand exactly against the face hit (rounding could leave it a hair inside),
            // the other coordinate where the motion had got to.
            float tx = (float) (x + first * mx), ty = (float) (y + first * my);
            tx = RectPush.placedX(side, tx, w, hitRect.x(), hitRect.w());
            ty = RectPush.placedY(side, ty, h, hitRect.y(), hitRect.h());
            safeAlong(x, y, w, h, mx, my, first, tx, ty, x0, y0, obstacles, end);
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
                                  float tx, float ty, float x0, float y0, List<Rect> obstacles, float[] at) {
        if (clear(tx, ty, w, h, x0, y0, obstacles)) {
            at[0] = tx;
            at[1] = ty;
            return;
        }
        float bestX = x, bestY = y;
        double lo = 0, hi = t;
        for (int i = 0; i < 64 && lo < hi; i++) {
            double mid = (lo + hi) / 2;
            float px = (float) (x + mid * mx), py = (float) (y + mid * my);
            if (clear(px, py, w, h, x0, y0, obstacles)) {
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

    private static boolean clear(float x, float y, float w, float h, float x0, float y0, List<Rect> obstacles) {
        for (int i = 0, n = obstacles.size(); i < n; i++) {
            Rect o = obstacles.get(i);
            if (RawTests.rectRect(x, y, w, h, o.x(), o.y(), o.w(), o.h())
                    && !RawTests.rectRect(x0, y0, w, h, o.x(), o.y(), o.w(), o.h())) {
                return false;
            }
        }
        return true;
    }
}
