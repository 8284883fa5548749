package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Pixel masks: making them, reading them, and overlap at offsets, in both orders. */
class PixelMaskTest {

    private static final PixelMask PLUS = PixelMask.parse("""
            .#.
            ###
            .#.
            """);

    private static final PixelMask RING = PixelMask.parse("""
            #####
            #...#
            #...#
            #...#
            #####
            """);

    private static final PixelMask DOT = PixelMask.parse("#");

    @Test
    void parse_readsRowsAndRoundTrips() {
        assertEquals(3, PLUS.width());
        assertEquals(3, PLUS.height());
        assertEquals(5, PLUS.count());
        assertTrue(PLUS.contains(1, 0));
        assertFalse(PLUS.contains(0, 0));
        assertFalse(PLUS.contains(-1, 1), "outside the mask");
        assertFalse(PLUS.contains(3, 1), "outside the mask");
        assertEquals(".#.\n###\n.#.\n", PLUS.toPicture());
        assertEquals(PLUS, PixelMask.parse(PLUS.toPicture()));
        assertEquals("PixelMask[3 x 3, 5 solid]", PLUS.toString());
    }

    @Test
    void fromGrid_sameAsParse() {
        boolean[][] grid = {{false, true, false}, {true, true, true}, {false, true, false}};
        assertEquals(PLUS, PixelMask.fromGrid(grid));
        assertEquals(PLUS.hashCode(), PixelMask.fromGrid(grid).hashCode());
    }

    @Test
    void fromPixels_countsAlphaAboveTheThreshold() {
        int[] argb = {
            0x00ffffff, 0x01000000, 0x80ff0000,
            0x7f00ff00, 0xff0000ff, 0xffffffff,
        };
        assertEquals(PixelMask.parse("""
                .##
                ###
                """), PixelMask.fromPixels(argb, 3, 2, 0));
        assertEquals(PixelMask.parse("""
                ..#
                .##
                """), PixelMask.fromPixels(argb, 3, 2, 127));
        assertEquals(0, PixelMask.fromPixels(argb, 3, 2, 255).count(), "nothing is above 255");
        assertEquals(6, PixelMask.fromPixels(argb, 2, 3, 0).width() * 3, "any shape with the right count");
    }

    @Test
    void wideMask_crossesWordBoundaries() {
        boolean[][] grid = new boolean[2][130];
        grid[0][63] = grid[0][64] = grid[1][129] = grid[1][0] = true;
        PixelMask wide = PixelMask.fromGrid(grid);
        assertTrue(wide.contains(63, 0));
        assertTrue(wide.contains(64, 0));
        assertTrue(wide.contains(129, 1));
        assertFalse(wide.contains(65, 0));
        assertEquals(new Rect(0, 0, 130, 2), wide.bounds());
        assertEquals(new PixelMask.Pixel(63, 0), wide.firstOverlap(DOT, 63, 0));
        assertEquals(new PixelMask.Pixel(64, 0), wide.firstOverlap(DOT, 64, 0));
        assertNull(wide.firstOverlap(DOT, 65, 0));
        assertEquals(new PixelMask.Pixel(129, 1), wide.firstOverlap(DOT, 129, 1));
        assertTrue(DOT.overlaps(wide, -129, -1));
        assertEquals(new PixelMask.Pixel(0, 0), DOT.firstOverlap(wide, -64, 0));
    }

    @Test
    void bounds_ofTheSolidPixelsOnly() {
        PixelMask sprite = PixelMask.parse("""
                ......
                ..##..
                ...#..
                ......
                """);
        assertEquals(new Rect(2, 1, 2, 2), sprite.bounds());
        assertNull(PixelMask.parse("...").bounds());
    }

    @ParameterizedTest(name = "[{index}] {3}")
    @CsvSource({
            // dx, dy, expected overlap count, scenario
            "0, 0, 5, exactly on top",
            "1, 0, 2, shifted right by one: the middle row shares two",
            "1, 1, 2, shifted by one down and right",
            "3, 0, 0, side by side: edges touch, no pixel shared",
            "2, 2, 0, diagonal: only corners touch",
            "2, 0, 1, one pixel shared",
            "-2, 0, 1, one pixel shared on the left",
            "2, 1, 0, arms pass each other",
            "-3, 0, 0, side by side on the left",
            "0, -3, 0, above, touching",
            "100, 100, 0, far away",
            "2147483647, 0, 0, as far as an int goes",
            "-2147483648, -2147483648, 0, as far the other way",
    })
    void overlaps_plusOnPlus(int dx, int dy, int count, String scenario) {
        assertEquals(count > 0, PLUS.overlaps(PLUS, dx, dy));
        assertEquals(count > 0, PLUS.overlaps(PLUS, -dx, -dy), "other order");
        assertEquals(count, PLUS.overlapCount(PLUS, dx, dy));
        assertEquals(count == 0, PLUS.firstOverlap(PLUS, dx, dy) == null);
    }

    @Test
    void overlaps_dotInsideRingHole_isNoOverlap() {
        assertFalse(RING.overlaps(DOT, 2, 2), "the hole is empty");
        assertFalse(DOT.overlaps(RING, -2, -2));
        assertTrue(RING.overlaps(DOT, 1, 0));
        assertFalse(RING.overlaps(PLUS, 1, 1), "the plus fits in the hole");
        assertTrue(RING.overlaps(PLUS, 0, 1), "the plus reaches the ring's left side");
        assertEquals(new PixelMask.Pixel(0, 2), RING.firstOverlap(PLUS, 0, 1));
        assertEquals(new PixelMask.Pixel(0, 1), PLUS.firstOverlap(RING, 0, -1), "in the plus's coordinates");
    }

    @Test
    void firstOverlap_isInReadingOrder() {
        PixelMask solid = PixelMask.parse("""
                ####
                ####
                """);
        assertEquals(new PixelMask.Pixel(0, 0), solid.firstOverlap(PLUS, 0, -1), "left arm before the middle");
        assertEquals(new PixelMask.Pixel(1, 0), solid.firstOverlap(PLUS, 1, -1));
        assertEquals(new PixelMask.Pixel(1, 0), solid.firstOverlap(PLUS, 0, -2), "only the bottom arm");
        assertEquals(new PixelMask.Pixel(3, 0), solid.firstOverlap(PLUS, 2, 0), "(3, 0) comes before (2, 1): rows first");
    }

    @Test
    void emptyMask_overlapsNothing() {
        PixelMask empty = PixelMask.parse("""
                ...
                ...
                """);
        assertEquals(0, empty.count());
        assertFalse(empty.overlaps(PLUS, 0, 0));
        assertFalse(PLUS.overlaps(empty, 0, 0));
        assertEquals(0, PLUS.overlapCount(empty, 0, 0));
    }

    @Test
    void badInput_throwsWithALearnersMessage() {
        assertEquals("width must be > 0, was 0",
                assertThrows(IllegalArgumentException.class, () -> PixelMask.fromPixels(new int[0], 0, 5, 0)).getMessage());
        assertEquals("height must be > 0, was -1",
                assertThrows(IllegalArgumentException.class, () -> PixelMask.fromPixels(new int[0], 5, -1, 0)).getMessage());
        assertEquals("pixels has 99 values but width * height is 100 (10 x 10)",
                assertThrows(IllegalArgumentException.class, () -> PixelMask.fromPixels(new int[99], 10, 10, 0)).getMessage());
        assertEquals("alphaThreshold must be between 0 and 255, was 300",
                assertThrows(IllegalArgumentException.class, () -> PixelMask.fromPixels(new int[4], 2, 2, 300)).getMessage());
        assertEquals("alphaThreshold must be between 0 and 255, was -1",
                assertThrows(IllegalArgumentException.class, () -> PixelMask.fromPixels(new int[4], 2, 2, -1)).getMessage());
        assertEquals("pixels must not be null",
                assertThrows(IllegalArgumentException.class, () -> PixelMask.fromPixels(null, 2, 2, 0)).getMessage());
        assertEquals("row 1 has 2 pixels but row 0 has 3: every row must be as long as the first",
                assertThrows(IllegalArgumentException.class, () -> PixelMask.fromGrid(new boolean[][] {{true, false, true}, {true, true}})).getMessage());
        assertEquals("solid must have at least one row",
                assertThrows(IllegalArgumentException.class, () -> PixelMask.fromGrid(new boolean[0][])).getMessage());
        assertEquals("width must be > 0, was 0",
                assertThrows(IllegalArgumentException.class, () -> PixelMask.fromGrid(new boolean[2][0])).getMessage());
        assertEquals("unexpected 'x' at row 1, column 0: use '#' for a solid pixel and '.' for an empty one",
                assertThrows(IllegalArgumentException.class, () -> PixelMask.parse("#.\nx.")).getMessage());
        assertThrows(IllegalArgumentException.class, () -> PixelMask.parse("##\n\n##"));
        assertThrows(IllegalArgumentException.class, () -> PixelMask.parse("   "));
        assertEquals("other must not be null",
                assertThrows(IllegalArgumentException.class, () -> PLUS.overlaps(null, 0, 0)).getMessage());
    }

    // ------------------------------------------------------------------ against the per-pixel loop

    /** Random masks up to 200 wide (several words a row): the word-wise answers equal the naive per-pixel ones. */
    @Property(tries = 1000)
    void overlap_agreesWithPerPixelLoop(@ForAll @IntRange(min = 1, max = 200) int w1, @ForAll @IntRange(min = 1, max = 12) int h1,
                                        @ForAll @IntRange(min = 1, max = 200) int w2, @ForAll @IntRange(min = 1, max = 12) int h2,
                                        @ForAll @IntRange(min = -210, max = 210) int dx, @ForAll @IntRange(min = -14, max = 14) int dy,
                                        @ForAll @IntRange(min = 1, max = 99) int fill, @ForAll long seed) {
        Random random = new Random(seed);
        PixelMask a = randomMask(random, w1, h1, fill), b = randomMask(random, w2, h2, fill);
        int count = 0;
        PixelMask.Pixel first = null;
        for (int y = 0; y < h1; y++) {
            for (int x = 0; x < w1; x++) {
                if (a.contains(x, y) && b.contains(x - dx, y - dy)) {
                    count++;
                    if (first == null) {
                        first = new PixelMask.Pixel(x, y);
                    }
                }
            }
        }
        assertEquals(count, a.overlapCount(b, dx, dy));
        assertEquals(count, b.overlapCount(a, -dx, -dy), "other order");
        assertEquals(count > 0, a.overlaps(b, dx, dy));
        assertEquals(count > 0, b.overlaps(a, -dx, -dy), "other order");
        assertEquals(first, a.firstOverlap(b, dx, dy));
    }

    @Property(tries = 300)
    void fromPixels_agreesWithContains(@ForAll @IntRange(min = 1, max = 150) int w, @ForAll @IntRange(min = 1, max = 10) int h,
                                       @ForAll @IntRange(min = 0, max = 255) int threshold, @ForAll long seed) {
        Random random = new Random(seed);
        int[] pixels = new int[w * h];
        for (int i = 0; i < pixels.length; i++) {
            pixels[i] = random.nextInt();
        }
        PixelMask mask = PixelMask.fromPixels(pixels, w, h, threshold);
        int count = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                boolean solid = (pixels[y * w + x] >>> 24) > threshold;
                assertEquals(solid, mask.contains(x, y));
                count += solid ? 1 : 0;
            }
        }
        assertEquals(count, mask.count());
        assertEquals(mask, PixelMask.parse(mask.toPicture()));
    }

    static PixelMask randomMask(Random random, int w, int h, int fillPercent) {
        boolean[][] grid = new boolean[h][w];
        for (boolean[] row : grid) {
            for (int x = 0; x < w; x++) {
                row[x] = random.nextInt(100) < fillPercent;
            }
        }
        return PixelMask.fromGrid(grid);
    }
}
