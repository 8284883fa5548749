package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.FloatRange;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Issue 19's one vocabulary: one side type (the deprecated aliases of {@link Edges} and
 * {@link Motion} answer as {@link Side} does), one exception per kind of mistake, the
 * additions that close the overload holes ({@link Collide#rectCircle}, {@link Sweep#circleRect},
 * {@link Hits#firstShape}), and the named tolerances' one padding formula.
 */
// Exercises the deprecated aliases and overloads too: they are kept, and must keep answering, for one release.
@SuppressWarnings("deprecation")
class VocabularyTest {

    // ---- one side type ------------------------------------------------------------------

    @Test
    @SuppressWarnings("deprecation")
    void deprecatedSideConstants_areSidesBits() {
        assertEquals(Side.LEFT.bit(), Edges.LEFT);
        assertEquals(Side.RIGHT.bit(), Edges.RIGHT);
        assertEquals(Side.TOP.bit(), Edges.TOP);
        assertEquals(Side.BOTTOM.bit(), Edges.BOTTOM);
        assertEquals(Side.NONE.bit(), Edges.NONE);
        assertEquals(Side.NONE.bit(), Motion.NONE);
        assertEquals(Side.LEFT_RIGHT, Motion.X);
        assertEquals(Side.TOP_BOTTOM, Motion.Y);
        assertEquals(Side.ALL_BITS, Motion.BOTH);
        assertEquals(Side.bits(Side.LEFT, Side.RIGHT), Side.LEFT_RIGHT);
        assertEquals(Side.bits(Side.TOP, Side.BOTTOM), Side.TOP_BOTTOM);
    }

    @Property
    @SuppressWarnings("deprecation")
    void deprecatedHas_answersAsSideHasAny(@ForAll @IntRange(min = -1, max = 40) int sides,
                                           @ForAll @IntRange(min = 0, max = 15) int bits) {
        assertEquals(Side.hasAny(sides, bits), Edges.has(sides, bits));
        assertEquals(Side.hasAny(sides, bits), Motion.has(sides, bits));
    }

    @Property
    @SuppressWarnings("deprecation")
    void edgesDescribe_isSideDescribe(@ForAll @IntRange(min = -1, max = 40) int sides) {
        assertEquals(Side.describe(sides), Edges.describe(sides));
    }

    @ParameterizedTest(name = "Motion.describe({0}) = {1}, Side.describe({0}) = {2}")
    @CsvSource({
            "0, NONE, NONE",
            "3, X, LEFT|RIGHT",
            "12, Y, TOP|BOTTOM",
            "15, BOTH, LEFT|RIGHT|TOP|BOTTOM",
            "1, X, LEFT",
            "8, Y, BOTTOM",
    })
    @SuppressWarnings("deprecation")
    void motionDescribe_keepsItsWords_sideDescribeNamesTheSides(int blocked, String motion, String side) {
        assertEquals(motion, Motion.describe(blocked), "the deprecated alias answers as before");
        assertEquals(side, Side.describe(blocked), "the one printer names the sides");
    }

    @ParameterizedTest(name = "hasAny({0}, {1}) = {2}")
    @CsvSource({
            "0, 15, false",
            "15, 0, false",
            "3, 3, true",
            "1, 3, true",
            "2, 12, false",
            "12, 4, true",
            "16, 16, false",  // a bit outside the scheme names no side
            "-1, 8, true",
    })
    void hasAny_sharesASide(int sides, int bits, boolean expected) {
        assertEquals(expected, Side.hasAny(sides, bits));
    }

    @Test
    void motionAnswers_areReadWithSide() {
        // A wall straight ahead across: the move across is blocked, the move down is not.
        int blocked = Motion.rectBlocked(0, 0, 10, 10, 5, 0, 12, 0, 10, 10);
        assertEquals(Side.LEFT_RIGHT, blocked);
        assertTrue(Side.hasAny(blocked, Side.LEFT_RIGHT));
        assertFalse(Side.hasAny(blocked, Side.TOP_BOTTOM));
        assertEquals(-5, Motion.reverseX(blocked, 5));
        assertEquals("LEFT|RIGHT", Side.describe(blocked));
    }

    @Test
    @SuppressWarnings("deprecation")
    void motionOneRectOverloads_answerAsTheRawAndListForms() {
        Rect wall = new Rect(12, 0, 10, 10);
        int raw = Motion.rectBlocked(0, 0, 10, 10, 5, 3, 12, 0, 10, 10);
        assertEquals(raw, Motion.rectBlocked(0, 0, 10, 10, 5, 3, wall));
        assertEquals(raw, Motion.rectBlocked(0, 0, 10, 10, 5, 3, List.of(wall)));
        assertEquals(raw, Motion.blocked(new Rect(0, 0, 10, 10), 5, 3, wall));
        int ball = Motion.circleBlocked(5, 5, 5, 5, 3, 12, 0, 10, 10);
        assertEquals(ball, Motion.circleBlocked(5, 5, 5, 5, 3, wall));
        assertEquals(ball, Motion.circleBlocked(5, 5, 5, 5, 3, List.of(wall)));
        assertEquals(ball, Motion.blocked(new Circle(5, 5, 5), 5, 3, wall));
    }

    // ---- one exception per kind of mistake ----------------------------------------------

    @ParameterizedTest(name = "cell ({0}, {1}) outside a 4 x 3 grid")
    @CsvSource({"-1, 0", "4, 0", "0, -1", "0, 3", "2147483647, 2147483647"})
    void gridCellOutside_isIndexOutOfBounds_forGetSetAndPath(int col, int row) {
        Grid g = new Grid(4, 3, 10);
        assertThrows(IndexOutOfBoundsException.class, () -> g.get(col, row));
        assertThrows(IndexOutOfBoundsException.class, () -> g.set(col, row, Grid.SOLID));
        assertThrows(IndexOutOfBoundsException.class, () -> g.path(col, row, 0, 0));
        assertThrows(IndexOutOfBoundsException.class, () -> g.path(0, 0, col, row));
        assertThrows(IndexOutOfBoundsException.class, () -> g.path(col, row, 0, 0, PathCosts.steps()));
        assertThrows(IndexOutOfBoundsException.class, () -> g.fillRandom(0.5f, 1, col, row));
    }

    @Test
    void gridBadValues_stayIllegalArgument() {
        Grid g = new Grid(4, 3, 10);
        assertThrows(IllegalArgumentException.class, () -> g.path(0, 0, 1, 1, null));
        assertThrows(IllegalArgumentException.class, () -> g.fillRandom(2, 1, 0, 0));
    }

    @Test
    void noResultArrays_areEmptyNotNull() {
        Grid walled = Grid.parse(".#.", 10);
        assertEquals(0, walled.path(0, 0, 2, 0).length);
        assertEquals(0, Hits.all(new Rect(0, 0, 1, 1), List.of(new Rect(5, 5, 1, 1))).length);
        assertEquals(0, Hits.all(Float.NaN, 0, 1, 1, List.of(new Rect(0, 0, 1, 1))).length);
    }

    // ---- Collide.rectCircle, both orders --------------------------------------------------

    @ParameterizedTest(name = "rect (0, 0, 10, 10) and circle ({0}, {1}, {2}): {3}")
    @CsvSource({
            "5, 5, 1, true",       // inside
            "15, 5, 5, false",     // touching the right edge
            "15, 5, 5.001, true",
            "13, 13, 4.2426405, false", // just short of the corner (3 * sqrt 2 = 4.24264068...)
            "13, 13, 4.25, true",
            "5, 5, 0, true",       // a point strictly inside
            "10, 5, 0, false",     // a point on the edge
            "5, 5, -1, false",     // a negative radius
            "NaN, 5, 1, false",
    })
    void rectCircle_answersAsCircleRect_inBothOrders(float cx, float cy, float r, boolean expected) {
        assertEquals(expected, Collide.rectCircle(0, 0, 10, 10, cx, cy, r));
        assertEquals(expected, Collide.circleRect(cx, cy, r, 0, 0, 10, 10));
        if (r >= 0 && !Float.isNaN(cx)) {
            assertEquals(expected, new Rect(0, 0, 10, 10).overlaps(new Circle(cx, cy, r)));
            assertEquals(expected, new Circle(cx, cy, r).overlaps(new Rect(0, 0, 10, 10)));
        }
    }

    @Property
    void rectCircle_isCircleRectSwapped(@ForAll @FloatRange(min = -50, max = 50) float x,
                                        @ForAll @FloatRange(min = -50, max = 50) float y,
                                        @ForAll @FloatRange(min = 0, max = 40) float w,
                                        @ForAll @FloatRange(min = 0, max = 40) float h,
                                        @ForAll @FloatRange(min = -50, max = 50) float cx,
                                        @ForAll @FloatRange(min = -50, max = 50) float cy,
                                        @ForAll @FloatRange(min = 0, max = 30) float r) {
        assertEquals(Collide.circleRect(cx, cy, r, x, y, w, h), Collide.rectCircle(x, y, w, h, cx, cy, r));
    }

    // ---- Sweep.circleRect ----------------------------------------------------------------

    @Test
    void sweepCircleRect_fastBallHitsThinWall() {
        // A ball of radius 5 at x = 0 moving 1000 right; the wall's left face at x = 500.
        float t = Raw.sweepCircleRect(0, 50, 5, 1000, 0, 500, 0, 1, 100);
        assertEquals(0.495f, t, 1e-6f);
        assertFalse(Collide.circleRect(0 + t * 1000, 50, 5, 500, 0, 1, 100), "never left inside");
    }

    @Test
    void sweepCircleRect_missOverlapAndNaN() {
        assertEquals(Float.POSITIVE_INFINITY, Raw.sweepCircleRect(0, 50, 5, 100, 0, 500, 0, 1, 100), "too short a move");
        assertEquals(Float.POSITIVE_INFINITY, Raw.sweepCircleRect(0, 50, 5, 0, -100, 500, 0, 1, 100), "moving away");
        assertEquals(0f, Raw.sweepCircleRect(500, 50, 5, 10, 0, 500, 0, 1, 100), "already overlapping");
        assertEquals(Float.POSITIVE_INFINITY, Raw.sweepCircleRect(Float.NaN, 50, 5, 1000, 0, 500, 0, 1, 100));
        assertEquals(Float.POSITIVE_INFINITY, Raw.sweepCircleRect(0, 50, -5, 1000, 0, 500, 0, 1, 100));
    }

    @Test
    void sweepsOnFloats_negativeSize_isNoHit() {
        // Documented as "no hit for negative input"; the search used to report t = 1.
        assertNull(Raw.sweepCircleRectHit(0, 50, -5, 1000, 0, 500, 0, 1, 100));
        assertNull(Raw.sweepCircleRectHit(0, 50, 5, 1000, 0, 500, 0, -1, 100));
        assertNull(Raw.sweepCircleCircleHit(0, 0, -5, 100, 0, 50, 0, 10));
        assertNull(Raw.sweepCircleCircleHit(0, 0, 5, 100, 0, 50, 0, -10));
        assertNull(Raw.sweepRectRectHit(0, 0, -5, 5, 100, 0, 50, 0, 10, 10));
        assertNull(Raw.sweepRectRectHit(0, 0, 5, 5, 100, 0, 50, 0, 10, -10));
        assertEquals(Float.POSITIVE_INFINITY, Sweep.rectRect(0, 0, -5, 5, 100, 0, 50, 0, 10, 10));
        assertEquals(Float.POSITIVE_INFINITY, Raw.sweepCircleCircle(0, 0, -5, 100, 0, 50, 0, 10));
        // The same moves with real sizes do hit.
        assertEquals(0.45f, Sweep.rectRect(0, 0, 5, 5, 100, 0, 50, 0, 10, 10), 1e-6f);
        assertEquals(0.4f, Raw.sweepCircleCircle(0, 0, 5, 100, 0, 50, 0, 5), 1e-6f);
    }

    @Property
    void sweepCircleRect_isCircleRectHitsTime(@ForAll @FloatRange(min = -100, max = 100) float cx,
                                              @ForAll @FloatRange(min = -100, max = 100) float cy,
                                              @ForAll @FloatRange(min = 0, max = 20) float r,
                                              @ForAll @FloatRange(min = -200, max = 200) float vx,
                                              @ForAll @FloatRange(min = -200, max = 200) float vy) {
        Hit hit = Raw.sweepCircleRectHit(cx, cy, r, vx, vy, -10, -20, 30, 15);
        float t = Raw.sweepCircleRect(cx, cy, r, vx, vy, -10, -20, 30, 15);
        assertEquals(hit == null ? Float.POSITIVE_INFINITY : hit.t(), t);
        Hit shapes = Sweep.timeOfImpact(new Circle(cx, cy, r), vx, vy, new Rect(-10, -20, 30, 15));
        assertEquals(hit, shapes, "the raw tiers and the shape tier agree");
    }

    // ---- Hits.first is an index; firstShape the shape -------------------------------------

    @Test
    void firstShape_isTheElementFirstPointsAt() {
        Rect player = new Rect(0, 0, 10, 10);
        List<Rect> walls = List.of(new Rect(20, 0, 5, 5), new Rect(5, 5, 10, 10), new Rect(-5, -5, 8, 8));
        int i = Hits.first(player, walls);
        assertEquals(1, i);
        assertSame(walls.get(1), Hits.firstShape(player, walls));
        assertSame(walls.get(1), Hits.firstShape(player, walls.toArray(new Rect[0])));
        Rect found = Hits.firstShape(player, walls);  // typed as the list's kind: no cast
        assertEquals(new Rect(5, 5, 10, 10), found);
    }

    @Test
    void firstShape_noneIsNull_selfIsSkipped_nullThrows() {
        Rect player = new Rect(0, 0, 10, 10);
        assertNull(Hits.firstShape(player, List.of(new Rect(10, 0, 5, 5))), "touching is not hitting");
        assertNull(Hits.firstShape(player, List.of(player)), "a shape never hits itself");
        assertThrows(IllegalArgumentException.class, () -> Hits.firstShape(null, List.of(player)));
        assertThrows(IllegalArgumentException.class, () -> Hits.firstShape(player, (List<Rect>) null));
        assertThrows(IllegalArgumentException.class, () -> Hits.firstShape(player, (Rect[]) null));
        assertThrows(IllegalArgumentException.class, () -> Hits.firstShape(player, new Rect[] {null}));
    }

    @Test
    @SuppressWarnings("deprecation")
    void hitsRawArrayOverloads_answerAsTheListForms() {
        Rect[] walls = {new Rect(20, 0, 5, 5), new Rect(5, 5, 10, 10), new Rect(8, 8, 1, 1)};
        List<Rect> list = List.of(walls);
        assertEquals(Hits.any(0, 0, 10, 10, list), Hits.any(0, 0, 10, 10, walls));
        assertEquals(Hits.first(0, 0, 10, 10, list), Hits.first(0, 0, 10, 10, walls));
        assertEquals(Hits.count(0, 0, 10, 10, list), Hits.count(0, 0, 10, 10, walls));
        assertEquals(List.of(1, 2), java.util.Arrays.stream(Hits.all(0, 0, 10, 10, walls)).boxed().toList());
    }

    // ---- the one padding formula ---------------------------------------------------------

    @Property
    void tolerancePad_isTheFormulaItReplaced(@ForAll double lo, @ForAll double hi) {
        double written = 1e-9 * (Math.abs(lo) + Math.abs(hi)) + 1e-30;
        assertEquals(Double.doubleToRawLongBits(written), Double.doubleToRawLongBits(Tolerance.pad(lo, hi)));
    }
}
