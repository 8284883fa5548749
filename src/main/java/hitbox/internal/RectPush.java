package hitbox.internal;

import hitbox.*;

/**
 * The rectangle push-out, in one place: the four ways a box can leave another box, how far
 * each is, which is shortest, and where the box stands afterwards, touching. {@link Snap}
 * places the box with it, {@link Contacts#rectRect} reports it as a normal and a depth, and
 * {@link Sweep#move} stands a box against the face it hit.
 *
 * <p>The ways out are named by the obstacle's side the mover ends up against:
 * {@link Side#TOP} (pushed up, onto it), {@link Side#BOTTOM}, {@link Side#LEFT},
 * {@link Side#RIGHT}. Depths are sums of floats in double, so they are exact, and so are
 * ties: equal depths go in the order TOP, BOTTOM, LEFT, RIGHT (vertical first, so landing
 * exactly on a corner lands), which is the tie rule of {@link Contact} for the four axis
 * normals.
 */
public final class RectPush {
    private RectPush() {
    }

    /** The ways out in tie order; a constant so the loop allocates nothing. */
    private static final Side[] WAYS_OUT = {Side.TOP, Side.BOTTOM, Side.LEFT, Side.RIGHT};

    /** The side with the shortest way out of the obstacle; ties in the order TOP, BOTTOM, LEFT, RIGHT. */
    public static Side leastOverlap(float x, float y, float w, float h, float ox, float oy, float ow, float oh) {
        Side best = WAYS_OUT[0];
        double bestDepth = depth(best, x, y, w, h, ox, oy, ow, oh);
        for (int i = 1; i < WAYS_OUT.length; i++) {
            double d = depth(WAYS_OUT[i], x, y, w, h, ox, oy, ow, oh);
            if (d < bestDepth) {
                best = WAYS_OUT[i];
                bestDepth = d;
            }
        }
        return best;
    }

    /** How far the mover must move to leave the obstacle through its {@code side} (exact). */
    public static double depth(Side side, float x, float y, float w, float h, float ox, float oy, float ow, float oh) {
        return switch (side) {
            case TOP -> (double) y + h - oy;
            case BOTTOM -> (double) oy + oh - y;
            case LEFT -> (double) x + w - ox;
            case RIGHT -> (double) ox + ow - x;
            case NONE -> throw new IllegalStateException("no way out through NONE");
        };
    }

    /**
     * The unit normal from the mover into the obstacle when the mover stands against the
     * obstacle's {@code side}: TOP (0, 1), BOTTOM (0, -1), LEFT (1, 0), RIGHT (-1, 0).
     */
    public static float normalX(Side side) {
        return side == Side.LEFT ? 1 : side == Side.RIGHT ? -1 : 0;
    }

    /** The y part of {@link #normalX}'s normal. */
    public static float normalY(Side side) {
        return side == Side.TOP ? 1 : side == Side.BOTTOM ? -1 : 0;
    }

    /**
     * The mover's new left edge when it stands against the obstacle's {@code side} (its x
     * unchanged for TOP and BOTTOM).
     */
    public static float placedX(Side side, float x, float w, float ox, float ow) {
        return switch (side) {
            case LEFT -> touchBefore(ox, w);
            case RIGHT -> touchAfter((double) ox + ow);
            default -> x;
        };
    }

    /** The mover's new top edge when it stands against the obstacle's {@code side}. */
    public static float placedY(Side side, float y, float h, float oy, float oh) {
        return switch (side) {
            case TOP -> touchBefore(oy, h);
            case BOTTOM -> touchAfter((double) oy + oh);
            default -> y;
        };
    }

    /**
     * The float that puts a box of this size right before the edge, touching, not over it:
     * its far end {@code p + size}, added in double as {@link Collide} does, is at most
     * {@code edge}. That is {@code edge - size} when it is a float (it is for whole numbers);
     * else the rounded start may sit a hair past, and the loop steps down (once at most).
     * NaN gives NaN.
     */
    public static float touchBefore(float edge, float size) {
        float p = (float) ((double) edge - size);
        while ((double) p + size > edge) {
            p = Math.nextDown(p);
        }
        return p;
    }

    /** The float at or right after the edge: a start that meets the edge from beyond. NaN gives NaN. */
    public static float touchAfter(double edge) {
        float p = (float) edge;
        while (p < edge) {
            p = Math.nextUp(p);
        }
        return p;
    }
}
