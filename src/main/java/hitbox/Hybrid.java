package hitbox;

import hitbox.internal.*;

/**
 * The hybrid check: cheap tests first, the exact one only when it is needed.
 *
 * <p>Most pairs of objects in a game are far apart, and a precise test (a polygon, a
 * pixel mask) is wasted on them. So the check runs in three stages, and the first stage that
 * can say "apart" decides:
 * <ol>
 *   <li>{@link Stage#CIRCLES}: a circle around each shape's bounding box (centre the box's
 *       centre, radius half its diagonal). Circles further apart than their radii: apart.</li>
 *   <li>{@link Stage#BOXES}: the bounding boxes themselves. Boxes with a gap between them:
 *       apart.</li>
 *   <li>{@link Stage#PRECISE}: the exact test, {@link Shape#overlaps} or
 *       {@link PixelMask#overlaps}. Only this stage ever says "overlap".</li>
 * </ol>
 * The early stages only ever reject pairs that really are apart, so the answer is always the
 * precise test's answer; only the work differs. They are conservative: for shapes, boxes
 * that merely touch go on to the precise test (a segment touching another at its end is a
 * collision), and the circle test allows for rounding by a relative {@link #CIRCLE_SLACK}.
 * For masks the bounds are those of the solid pixels, and masks whose bounds only touch are
 * apart (no pixel is shared).
 *
 * <p>Every {@link Result} is one of four constants, so {@link #check} allocates nothing
 * ({@code check(a, b).overlaps()} is the answer alone); a {@link Counter} tallies which stage decided, to show how much
 * work the early stages save.
 *
 * <p>It shows the idea; it does not save time in Hitbox, whose precise tests already start
 * with the cheapest rejection ({@link PixelMask#overlaps} with the solid pixels' boxes,
 * two {@link Polygon}s with their cached bounds; circles and rectangles cost no more than a box
 * test). Measured with JMH (HybridBench), the hybrid check took 1.5 times as long as the
 * precise test alone on pixel masks, and 1.4 times on circles and rectangles. For speed, call
 * the precise test.
 */
public final class Hybrid {

    /**
     * How much bigger than the exact sum of radii two bounding circles must be apart before
     * the circle stage says "apart": a relative margin, so that a rounding error in the
     * square roots can never reject a pair that touches.
     */
    public static final double CIRCLE_SLACK = 1e-9;

    /** The stage of the hybrid check that decided. */
    public enum Stage {
        /** The bounding circles are apart. */
        CIRCLES,
        /** The bounding circles meet but the bounding boxes are apart. */
        BOXES,
        /** The precise test decided (overlap or not). */
        PRECISE
    }

    /**
     * The answer of the hybrid check and the stage that gave it.
     *
     * @param overlaps  do the shapes (or masks) overlap?
     * @param decidedBy the stage that decided; an overlap is always decided by
     *                  {@link Stage#PRECISE}
     */
    public record Result(boolean overlaps, Stage decidedBy) {

        /**
         * Makes a result, checking that it could happen.
         *
         * @param overlaps do the shapes (or masks) overlap?
         * @param decidedBy the stage that decided; an overlap is always decided by {@link Stage#PRECISE}
         *
         * @throws IllegalArgumentException if the stage is null, or an overlap is said to be
         *                                  decided before the precise stage
         */
        public Result {
            Check.notNull("decidedBy", decidedBy);
            if (overlaps && decidedBy != Stage.PRECISE) {
                throw new IllegalArgumentException("only the PRECISE stage can find an overlap, not " + decidedBy);
            }
        }
    }

    private static final Result APART_BY_CIRCLES = new Result(false, Stage.CIRCLES);
    private static final Result APART_BY_BOXES = new Result(false, Stage.BOXES);
    private static final Result APART = new Result(false, Stage.PRECISE);
    private static final Result OVERLAP = new Result(true, Stage.PRECISE);

    private Hybrid() {
    }

    // ---------------------------------------------------------------- shapes

    /**
     * Do the shapes overlap, and which stage found out? Allocates nothing.
     *
     * @param a one shape, not null
     * @param b the other shape, not null
     * @return the answer (always {@code a.overlaps(b)}) and the stage that decided, never null
     * @throws IllegalArgumentException if a shape is null
     */
    public static Result check(Shape a, Shape b) {
        Check.notNull("a", a);
        Check.notNull("b", b);
        // Each shape's bounding box in double, the same extents Shape.bounds() rounds
        // outwards, read without making a Rect.
        return stages(Extents.minX(a), Extents.minY(a), Extents.maxX(a), Extents.maxY(a),
                Extents.minX(b), Extents.minY(b), Extents.maxX(b), Extents.maxY(b), a, b);
    }

    private static Result stages(double al, double at, double ar, double ab,
                                 double bl, double bt, double br, double bb, Shape a, Shape b) {
        if (circlesApart(al, at, ar, ab, bl, bt, br, bb)) {
            return APART_BY_CIRCLES;
        }
        if (ar < bl || br < al || ab < bt || bb < at) {
            return APART_BY_BOXES;
        }
        return a.overlaps(b) ? OVERLAP : APART;
    }

    // ---------------------------------------------------------------- masks

    /**
     * Do two masks overlap, each placed with its top-left pixel at a whole-pixel position,
     * and which stage found out? Allocates nothing.
     *
     * @param a  one mask, not null
     * @param ax where a's left column is
     * @param ay where a's top row is
     * @param b  the other mask, not null
     * @param bx where b's left column is
     * @param by where b's top row is
     * @return the answer (always {@code a.overlaps(b, bx - ax, by - ay)}) and the stage that
     *         decided; masks with no solid pixel are apart at the first stage, never null
     * @throws IllegalArgumentException if a mask is null
     */
    public static Result check(PixelMask a, int ax, int ay, PixelMask b, int bx, int by) {
        Check.notNull("a", a);
        Check.notNull("b", b);
        if (a.count() == 0 || b.count() == 0) {
            return APART_BY_CIRCLES;
        }
        // The solid pixels' bounds, as unit squares, where each mask is placed.
        long al = (long) ax + a.minX, at = (long) ay + a.minY, ar = (long) ax + a.maxX + 1, ab = (long) ay + a.maxY + 1;
        long bl = (long) bx + b.minX, bt = (long) by + b.minY, br = (long) bx + b.maxX + 1, bb = (long) by + b.maxY + 1;
        if (circlesApart(al, at, ar, ab, bl, bt, br, bb)) {
            return APART_BY_CIRCLES;
        }
        if (ar <= bl || br <= al || ab <= bt || bb <= at) {
            return APART_BY_BOXES;
        }
        // The boxes overlap, so the offset is smaller than a mask and fits an int.
        return a.overlaps(b, (int) ((long) bx - ax), (int) ((long) by - ay)) ? OVERLAP : APART;
    }

    // ---------------------------------------------------------------- counting

    /**
     * A tally of hybrid checks by the stage that decided them, for a sketch to show how much
     * precise work was saved. Mutable, and meant to live in the sketch: {@link #reset()} it
     * each frame, {@link #add} every result.
     */
    public static final class Counter {
        private final int[] byStage = new int[Stage.values().length];
        private int overlapping;

        /** Makes a counter at zero. */
        public Counter() {
        }

        /**
         * Counts a result and hands it back, so a check can be counted where it is made:
         * {@code if (counter.add(Hybrid.check(a, b)).overlaps()) ...}.
         *
         * @param result the result to count, not null
         * @return the same result, never null
         * @throws IllegalArgumentException if result is null
         */
        public Result add(Result result) {
            Check.notNull("result", result);
            byStage[result.decidedBy().ordinal()]++;
            if (result.overlaps()) {
                overlapping++;
            }
            return result;
        }

        /**
         * @param stage the stage, not null
         * @return how many counted checks that stage decided
         * @throws IllegalArgumentException if stage is null
         */
        public int decidedBy(Stage stage) {
            return byStage[Check.notNull("stage", stage).ordinal()];
        }

        /** @return how many checks were counted */
        public int total() {
            int sum = 0;
            for (int n : byStage) {
                sum += n;
            }
            return sum;
        }

        /** @return how many counted checks found an overlap */
        public int overlapping() {
            return overlapping;
        }

        /** Sets every count back to zero. */
        public void reset() {
            java.util.Arrays.fill(byStage, 0);
            overlapping = 0;
        }

        /** @return the counts, for example {@code "circles 812, boxes 150, precise 38 (12 overlapping)"} */
        @Override
        public String toString() {
            return "circles " + byStage[0] + ", boxes " + byStage[1] + ", precise " + byStage[2]
                    + " (" + overlapping + " overlapping)";
        }
    }

    // ---------------------------------------------------------------- the stages

    /** 1 / (1 + CIRCLE_SLACK)^2: the squared distance is shrunk by this before comparing. */
    private static final double SHRINK = 1 / ((1 + CIRCLE_SLACK) * (1 + CIRCLE_SLACK));

    /**
     * Are the circles around the two boxes (l, t, r, b) apart, with room to spare for
     * rounding? With D the distance between the centres doubled and A, B the diagonals
     * (the radii doubled), apart means D > A + B; squared twice, so no square root is
     * taken: L = D^2 - A^2 - B^2 > 2AB, that is L > 0 and L^2 > 4 A^2 B^2. D^2 is first
     * shrunk by the slack, so a pair that touches is never called apart.
     */
    static boolean circlesApart(double al, double at, double ar, double ab,
                                double bl, double bt, double br, double bb) {
        double dx = (bl + br) - (al + ar);
        double dy = (bt + bb) - (at + ab);
        double wa = ar - al, ha = ab - at, wb = br - bl, hb = bb - bt;
        double qa = wa * wa + ha * ha, qb = wb * wb + hb * hb;
        double l = (dx * dx + dy * dy) * SHRINK - qa - qb;
        return l > 0 && l * l > 4 * qa * qb;
    }
}
