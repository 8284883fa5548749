package hitbox;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.IntStream;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.From;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.constraints.Size;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.function.Executable;

class HitsTest {

    /** Obstacles around the 10 x 10 box at the origin: which ones it hits is in the tables. */
    private static final List<Rect> WALLS = List.of(
            new Rect(10, 0, 10, 10),     // 0: touching the right edge
            new Rect(5, 5, 10, 10),      // 1: overlapping a corner
            new Rect(-10, -10, 10, 10),  // 2: touching a corner
            new Rect(2, 2, 3, 3),        // 3: inside
            new Rect(0, 10, 10, 0),      // 4: zero height on the bottom edge
            new Rect(5, -5, 0, 30),      // 5: zero width crossing the inside
            new Rect(100, 100, 5, 5));   // 6: far away

    @ParameterizedTest(name = "box at ({0}, {1}) size {2} x {3} hits {4}")
    @CsvSource({
            "0, 0, 10, 10, 1;3;5",
            "1000, 1000, 10, 10, ''",
            "0, 0, 0, 0, ''",             // a point on the corner of everything nearby
            "3, 3, 0, 0, 3",              // a point strictly inside wall 3 only
            "-1, -1, 12, 12, 0;1;2;3;4;5",
            "99, 99, 2, 2, 6",
    })
    void rawRect_table(float x, float y, float w, float h, String expected) {
        int[] want = indices(expected);
        assertArrayEquals(want, all(new Rect(x, y, w, h), WALLS));
        assertEquals(want.length == 0 ? -1 : want[0], Hits.first(new Rect(x, y, w, h), WALLS));
        assertEquals(want.length > 0, Hits.any(new Rect(x, y, w, h), WALLS));

        // The same answers through shapes, and in the other order: each hit wall hits the box.
        Rect box = new Rect(x, y, w, h);
        assertArrayEquals(want, all(box, WALLS));
        for (int i = 0; i < WALLS.size(); i++) {
            assertEquals(contains(want, i) ? 0 : -1, Hits.first(WALLS.get(i), List.of(box)), "wall " + i + " against the box");
        }
    }

    @ParameterizedTest(name = "circle ({0}, {1}) r={2} hits {3}")
    @CsvSource({
            "0, 0, 6, 0;2",
            "0, 0, 5, 0",                 // touches circle 2 (distance 8 = 5 + 3)
            "0, 0, 1, 0",
            "20, 0, 5, 1",
            "15, 0, 5, ''",               // touches circle 1
            "1000000, 0, 5, ''",
            "0, 0, 0, 0",                 // radius 0: a point inside the rect
            "0, 5, 0, ''",                // a point on circle 2's outline
    })
    void shapes_mixedList_table(float cx, float cy, float r, String expected) {
        List<Shape> others = List.of(
                new Rect(-3, -3, 6, 6),           // 0
                new Circle(25, 0, 5),             // 1
                new Circle(0, 8, 3));             // 2
        int[] want = indices(expected);
        Circle c = new Circle(cx, cy, r);
        assertArrayEquals(want, all(c, others));
        for (int i = 0; i < others.size(); i++) {
            assertEquals(contains(want, i), others.get(i).overlaps(c), "other order, shape " + i);
        }
    }

    @Test
    void shape_isNotCountedAsHittingItself() {
        Circle a = new Circle(0, 0, 10);
        Circle b = new Circle(5, 0, 10);
        Circle twinOfA = new Circle(0, 0, 10);
        List<Circle> balls = List.of(a, b);
        assertArrayEquals(new int[] {1}, all(a, balls));
        assertArrayEquals(new int[] {0}, all(b, balls));
        assertEquals(1, all(a, balls).length);
        assertArrayEquals(new int[] {0, 1}, all(twinOfA, balls), "an equal but separate shape counts");
        assertArrayEquals(new int[] {1}, all(a, List.of(a, b, a)));
    }

    @Test
    void manyHits_areAllFound() {
        List<Rect> stack = new ArrayList<>();
        for (int i = 0; i < 50; i++) {
            stack.add(new Rect(i, i, 100, 100));
        }
        assertArrayEquals(IntStream.range(0, 50).toArray(), all(new Rect(60, 60, 1, 1), stack));
        assertArrayEquals(IntStream.range(0, 50).toArray(), all(new Circle(60, 60, 1), stack));
        assertEquals(50, all(new Rect(60, 60, 1, 1), stack).length);
    }

    @Test
    void emptyLists_hitNothing() {
        Rect box = new Rect(0, 0, 10, 10);
        assertEquals(-1, Hits.first(box, List.of()));
        assertArrayEquals(new int[0], all(box, List.of()));
        assertFalse(Hits.any(new Rect(0, 0, 10, 10), List.of()));
        assertEquals(0, all(new Rect(0, 0, 10, 10), List.of()).length);
    }

    @Test
    void nulls_areNamed() {
        Rect box = new Rect(0, 0, 10, 10);
        assertMessage("shape must not be null", () -> Hits.first(null, WALLS));
        assertMessage("others must not be null", () -> Hits.any(box, (List<Shape>) null));
        assertMessage("others must not be null", () -> Hits.first(new Rect(0, 0, 1, 1), (List<Rect>) null));
        List<Rect> withHole = Arrays.asList(new Rect(500, 500, 1, 1), null);
        assertStartsWith("others[1] is null", () -> Hits.first(box, withHole));
        assertStartsWith("others[1] is null", () -> Hits.any(new Rect(0, 0, 1, 1), withHole));
        assertStartsWith("others[0] is null", () -> Hits.first(new Rect(0, 0, 1, 1), Arrays.asList((Rect) null)));
        assertStartsWith("others[2] is null", () -> Hits.first(box, Arrays.asList(box, new Rect(50, 50, 1, 1), null)));
    }

    @Test
    void first_stopsAtTheFirstHitBeforeAHole() {
        // A hit before a null element is found without reaching the null.
        List<Rect> withHole = Arrays.asList(new Rect(0, 0, 5, 5), null);
        assertEquals(0, Hits.first(new Rect(1, 1, 1, 1), withHole));
        assertTrue(Hits.any(new Rect(1, 1, 1, 1), withHole));
    }

    // ---- properties -------------------------------------------------------------------

    @Provide
    Arbitrary<Rect> rects() {
        Arbitrary<Integer> pos = Arbitraries.integers().between(-50, 50);
        Arbitrary<Integer> size = Arbitraries.integers().between(0, 30);
        return Combinators.combine(pos, pos, size, size).as((x, y, w, h) -> new Rect(x, y, w, h));
    }

    @Provide
    Arbitrary<Shape> shapes() {
        Arbitrary<Integer> pos = Arbitraries.integers().between(-50, 50);
        Arbitrary<Integer> size = Arbitraries.integers().between(0, 30);
        Arbitrary<Shape> circles = Combinators.combine(pos, pos, size).as((x, y, r) -> new Circle(x, y, r));
        return Arbitraries.oneOf(rects().map(r -> r), circles);
    }

    @Property
    void shapeQueries_agreeWithAPlainLoop(@ForAll("shapes") Shape shape,
                                          @ForAll @Size(max = 12) List<@From("shapes") Shape> others) {
        List<Integer> reference = new ArrayList<>();
        for (int i = 0; i < others.size(); i++) {
            if (shape.overlaps(others.get(i))) {
                reference.add(i);
            }
        }
        int[] want = reference.stream().mapToInt(Integer::intValue).toArray();
        assertArrayEquals(want, all(shape, others));
        assertEquals(want.length == 0 ? -1 : want[0], Hits.first(shape, others));
        assertEquals(want.length > 0, Hits.any(shape, others));
        // Both orders: each hit, tested against the shape alone, hits it back.
        for (int i : want) {
            assertEquals(0, Hits.first(others.get(i), List.of(shape)));
        }
    }

    @Property
    void rawRect_agreesWithTheRectShape_andIsTranslationInvariant(
            @ForAll("rects") Rect box, @ForAll @Size(max = 12) List<@From("rects") Rect> rects,
            @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
            @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        int[] want = all(box, rects);
        assertArrayEquals(want, all(new Rect(box.x(), box.y(), box.w(), box.h()), rects));
        List<Rect> moved = rects.stream().map(r -> r.translated(dx, dy)).toList();
        Rect movedBox = box.translated(dx, dy);
        assertArrayEquals(want, all(new Rect(movedBox.x(), movedBox.y(), movedBox.w(), movedBox.h()), moved));
    }

    // ---- helpers ----------------------------------------------------------------------

    private static int[] indices(String list) {
        return list.isEmpty() ? new int[0] : Arrays.stream(list.split(";")).mapToInt(Integer::parseInt).toArray();
    }

    private static boolean contains(int[] a, int v) {
        return Arrays.stream(a).anyMatch(k -> k == v);
    }

    /**
     * Every index of the others the shape hits, in order, found with the one call that lists
     * them: {@link Hits#first}, asked again after each hit of the rest of the list.
     */
    private static int[] all(Shape shape, List<? extends Shape> others) {
        List<Integer> found = new ArrayList<>();
        for (int from = 0; from < others.size(); ) {
            int i = Hits.first(shape, others.subList(from, others.size()));
            if (i < 0) {
                break;
            }
            found.add(from + i);
            from += i + 1;
        }
        return found.stream().mapToInt(Integer::intValue).toArray();
    }

    private static void assertMessage(String message, Executable call) {
        assertEquals(message, assertThrows(IllegalArgumentException.class, call).getMessage());
    }

    private static void assertStartsWith(String start, Executable call) {
        String message = assertThrows(IllegalArgumentException.class, call).getMessage();
        assertTrue(message.startsWith(start), message);
    }
}
