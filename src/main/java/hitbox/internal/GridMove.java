package hitbox.internal;

import hitbox.*;

import java.util.ArrayList;
import java.util.List;

/**
 * A box moving in pixels through a {@link Grid}'s solid cells: the tutorial's hybrid approach
 * ("store your obstacles in a grid, but your player's position in terms of pixels"), behind
 * {@link Grid#move}.
 *
 * <p>{@link MoveAndSlide} (the walk behind {@link Sweep#move}) does the moving, against the rectangles of the solid cells the move
 * can reach. It slides only towards where the motion goes, so the box never leaves the box
 * spanned by where it starts and where the whole motion would take it; the solid cells under
 * that box (widened by two float steps for rounding), in and beyond the grid, taken row by row,
 * are all that {@code Sweep.move} needs. The cells left out are never hit, never overlapped at
 * the start and never in the way, so the result is the same as against every solid cell in
 * the same row-by-row order, ties included.
 */
public final class GridMove {

    /** The most cells one move may look at: a box and a move of a few cells a frame need a handful. */
    public static final long MAX_CELLS = 1 << 22;

    private GridMove() {
    }

    /** See {@link Grid#move}. */
    public static Sweep.Move move(Grid grid, Rect mover, float vx, float vy) {
        return MoveAndSlide.move(mover, vx, vy, obstacles(grid, mover, vx, vy));
    }

    /**
     * The solid cells {@link Grid#move} looks at for this move, as rectangles, row by row: the
     * solid cells (in the grid or beyond its edges) under the box spanned by where the mover
     * starts and where the whole motion would take it.
     */
    public static List<Rect> obstacles(Grid grid, Rect mover, float vx, float vy) {
        Check.notNull("mover", mover);
        Check.finite("vx", vx);
        Check.finite("vy", vy);
        double x = mover.x();
        double y = mover.y();
        double left = Math.min(x, x + vx);
        double right = Math.max(x, x + vx) + mover.w();
        double top = Math.min(y, y + vy);
        double bottom = Math.max(y, y + vy) + mover.h();
        // Sweep.move moves the box in float (x + t * vx), which can land a few float steps
        // from these double sums: a margin of a few steps of the largest magnitude involved
        // keeps every cell the float path can touch (a cell touched only at the end still
        // ends the move's speed on that axis).
        double padX = 4 * Math.ulp((float) Math.max(Math.max(Math.abs(left), Math.abs(right)), Math.max(Math.abs(vx), mover.w())));
        double padY = 4 * Math.ulp((float) Math.max(Math.max(Math.abs(top), Math.abs(bottom)), Math.max(Math.abs(vy), mover.h())));
        int c0 = grid.colAt((float) (left - padX));
        int c1 = grid.colAt((float) (right + padX));
        int r0 = grid.rowAt((float) (top - padY));
        int r1 = grid.rowAt((float) (bottom + padY));
        if (saturated(c0) || saturated(c1) || saturated(r0) || saturated(r1)) {
            throw new IllegalArgumentException("a move of " + mover + " by (vx, vy) = (" + vx + ", " + vy + ") goes more than "
                    + Integer.MAX_VALUE + " cells from the grid");
        }
        long cells = ((long) c1 - c0 + 1) * ((long) r1 - r0 + 1);
        if (cells > MAX_CELLS) {
            throw new IllegalArgumentException("a move of " + mover + " by (" + vx + ", " + vy + ") sweeps "
                    + ((long) c1 - c0 + 1) + " x " + ((long) r1 - r0 + 1) + " cells, more than the " + MAX_CELLS
                    + " that Grid.move looks at: it is made for boxes and moves of a few cells a frame");
        }
        List<Rect> solid = new ArrayList<>();
        for (int row = r0; row <= r1; row++) {
            for (int col = c0; col <= c1; col++) {
                if (grid.isSolid(col, row)) {
                    solid.add(grid.cellRect(col, row));
                }
            }
        }
        return solid;
    }

    /** Is a column or row at the end of the int range, where colAt and rowAt stop counting? */
    private static boolean saturated(int i) {
        return i == Integer.MIN_VALUE || i == Integer.MAX_VALUE;
    }
}
