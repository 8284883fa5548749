package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.FloatRange;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Issues 19 and 30's one vocabulary: one side type (several sides are a set of {@link Side},
 * one NONE), one exception per kind of mistake, the pairs either way round on the shapes, and
 * the named tolerances' one padding formula.
 */
class VocabularyTest {

    // ---- one side type ------------------------------------------------------------------

    @Test
    void oneNone_isSides() throws ReflectiveOperationException {
        // One representation of a side: Edges and Motion have no NONE (or LEFT, X, ...) of
        // their own, and no public int constant anywhere in the API stands for a side.
        for (Class<?> c : List.of(Edges.class, Motion.class, Side.class, Sweep.class, Sweep.Move.class)) {
            for (java.lang.reflect.Field f : c.getFields()) {
                assertFalse(f.getType() == int.class && List.of("NONE", "LEFT", "RIGHT", "TOP", "BOTTOM", "X", "Y", "BOTH",
                        "LEFT_RIGHT", "TOP_BOTTOM", "ALL_BITS").contains(f.getName()), c.getSimpleName() + "." + f.getName());
            }
        }
        assertEquals(Side.class, Side.class.getField("NONE").getType());
    }

    @Test
    void severalSides_areUnmodifiableSetsOfSide_withoutNone() {
        Set<Side> crossed = Edges.crossed(new Circle(-5, -5, 10), 100, 100);
        assertEquals(EnumSet.of(Side.LEFT, Side.TOP), crossed);
        assertEquals(Set.of(), Edges.crossed(new Circle(50, 50, 10), 100, 100));
        assertThrows(UnsupportedOperationException.class, () -> crossed.add(Side.RIGHT));
        Set<Side> blocked = Motion.blocked(new Rect(0, 0, 10, 10), 5, 0, List.of(new Rect(12, 0, 10, 10)));
        assertThrows(UnsupportedOperationException.class, () -> blocked.clear());
        Sweep.Move m = Sweep.move(new Rect(0, 0, 10, 10), 0, 20, List.of(new Rect(-50, 15, 100, 10)));
        assertEquals(Set.of(Side.TOP), m.sides());
        assertThrows(UnsupportedOperationException.class, () -> m.sides().remove(Side.TOP));
        Sweep.Move made = new Sweep.Move(0, 0, 0, 0, EnumSet.of(Side.NONE, Side.LEFT));
        assertEquals(Set.of(Side.LEFT), made.sides(), "NONE names no side, so no set holds it");
    }

    @Test
    void motionAnswers_areReadWithSide() {
        // A wall straight ahead across: the move across is blocked, the move down is not.
        Set<Side> blocked = Motion.blocked(new Rect(0, 0, 10, 10), 5, 0, List.of(new Rect(12, 0, 10, 10)));
        assertEquals(EnumSet.of(Side.LEFT, Side.RIGHT), blocked);
        assertTrue(blocked.contains(Side.LEFT) && blocked.contains(Side.RIGHT));
        assertFalse(blocked.contains(Side.TOP) || blocked.contains(Side.BOTTOM));
        assertEquals(-5, Motion.reverseX(blocked, 5));
        assertEquals(3, Motion.reverseY(blocked, 3));
        assertEquals("[LEFT, RIGHT]", blocked.toString());
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
    }

    // ---- a rect and a circle, both orders (Collide.rectCircle went: the shapes answer either way)

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
        assertEquals(Collide.circleRect(cx, cy, r, x, y, w, h), new Rect(x, y, w, h).overlaps(new Circle(cx, cy, r)));
        assertEquals(Collide.circleRect(cx, cy, r, x, y, w, h), new Circle(cx, cy, r).overlaps(new Rect(x, y, w, h)));
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
        // NaN or a negative size: no shape to sweep (the float forms' "no hit" went with them).
        assertThrows(IllegalArgumentException.class, () -> Raw.sweepCircleRect(Float.NaN, 50, 5, 1000, 0, 500, 0, 1, 100));
        assertThrows(IllegalArgumentException.class, () -> Raw.sweepCircleRect(0, 50, -5, 1000, 0, 500, 0, 1, 100));
        assertThrows(IllegalArgumentException.class, () -> Sweep.timeOfImpact(new Circle(0, 50, 5), Float.NaN, 0, new Rect(500, 0, 1, 100)));
    }

    @Test
    void sweepsOnFloats_negativeSize_isNoHit() {
        // The one form left on floats is documented as "no hit for negative input" (the search
        // used to report t = 1); on shapes a negative size is refused before any sweep.
        assertEquals(Float.POSITIVE_INFINITY, Sweep.rectRect(0, 0, -5, 5, 100, 0, 50, 0, 10, 10));
        assertEquals(Float.POSITIVE_INFINITY, Sweep.rectRect(0, 0, 5, 5, 100, 0, 50, 0, 10, -10));
        assertThrows(IllegalArgumentException.class, () -> Raw.sweepCircleRectHit(0, 50, -5, 1000, 0, 500, 0, 1, 100));
        assertThrows(IllegalArgumentException.class, () -> Raw.sweepRectRectHit(0, 0, 5, 5, 100, 0, 50, 0, 10, -10));
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

    // ---- Hits.first is an index; the shape is the list's element there -------------------

    @Test
    void first_isAnIndex_noneIsMinusOne_selfIsSkipped_nullThrows() {
        Rect player = new Rect(0, 0, 10, 10);
        List<Rect> walls = List.of(new Rect(20, 0, 5, 5), new Rect(5, 5, 10, 10), new Rect(-5, -5, 8, 8));
        assertEquals(1, Hits.first(player, walls));
        assertEquals(new Rect(5, 5, 10, 10), walls.get(Hits.first(player, walls)));
        assertEquals(-1, Hits.first(player, List.of(new Rect(10, 0, 5, 5))), "touching is not hitting");
        assertEquals(-1, Hits.first(player, List.of(player)), "a shape never hits itself");
        assertThrows(IllegalArgumentException.class, () -> Hits.first(null, List.of(player)));
        assertThrows(IllegalArgumentException.class, () -> Hits.first(player, (List<Rect>) null));
        assertThrows(IllegalArgumentException.class, () -> Hits.first(player, java.util.Arrays.asList((Rect) null)));
    }

    // ---- the one padding formula ---------------------------------------------------------

    @Property
    void tolerancePad_isTheFormulaItReplaced(@ForAll double lo, @ForAll double hi) {
        double written = 1e-9 * (Math.abs(lo) + Math.abs(hi)) + 1e-30;
        assertEquals(Double.doubleToRawLongBits(written), Double.doubleToRawLongBits(Tolerance.pad(lo, hi)));
    }
}
