package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.junit.jupiter.api.Test;

/** Grid.fromPixels and TerrainColors: maps drawn as pictures, and clear errors for pictures that are not maps. */
class GridImagesTest {

    private static final int WHITE = 0xFFFFFFFF;
    private static final int BLACK = 0xFF000000;
    private static final int BLUE = 0xFF3070E0;

    private static TerrainColors key() {
        return new TerrainColors().put(0xFFFFFF, Grid.EMPTY).put(0x000000, Grid.SOLID).put(BLUE, 3);
    }

    /** The picture of a map, each cell a block of ppc x ppc pixels. */
    private static int[] picture(String map, int ppc, TerrainColors key) {
        Grid g = Grid.parse(map);
        int w = g.cols() * ppc;
        int[] pixels = new int[w * g.rows() * ppc];
        for (int y = 0; y < g.rows() * ppc; y++) {
            for (int x = 0; x < w; x++) {
                pixels[y * w + x] = key.colorOf(g.get(x / ppc, y / ppc));
            }
        }
        return pixels;
    }

    @Test
    void fromPixels_onePixelPerCell() {
        int[] pixels = {
            WHITE, BLACK, BLUE,
            BLUE, WHITE, BLACK,
        };
        Grid g = Grid.fromPixels(pixels, 3, 2, 1, key(), 16);
        assertEquals(3, g.cols());
        assertEquals(2, g.rows());
        assertEquals(16, g.cellWidth());
        assertEquals(".#3\n3.#", g.toMap());
    }

    @Test
    void fromPixels_blocksOfPixels_readAsTheTextMap() {
        String map = """
                #####
                #..3#
                #.#3#
                #####
                """;
        Grid g = Grid.fromPixels(picture(map, 4, key()), 20, 16, 4, key(), 10);
        assertEquals(Grid.parse(map, 10).toMap(), g.toMap());
    }

    @Property(tries = 300)
    void fromPixels_readsBackAnyMapDrawnAsAPicture(@ForAll long seed) {
        Random random = new Random(seed);
        Grid want = GridSightTest.randomGrid(random);
        int ppc = 1 + random.nextInt(5);
        TerrainColors key = new TerrainColors().put(0xFFFFFF, Grid.EMPTY).put(0x202020, Grid.SOLID).put(0x20A040, 2);
        int[] pixels = picture(want.toMap(), ppc, key);
        Grid got = Grid.fromPixels(pixels, want.cols() * ppc, want.rows() * ppc, ppc, key, 5);
        assertEquals(want.toMap(), got.toMap());
    }

    @Test
    void fromPixels_twoColoursForOneTerrain_mayShareABlock() {
        TerrainColors key = key().put(0x404040, Grid.SOLID);
        int[] pixels = {BLACK, 0xFF404040, 0xFF404040, BLACK};
        assertEquals("#", Grid.fromPixels(pixels, 2, 2, 2, key, 1).toMap());
    }

    @Test
    void fromPixels_unknownColour_namesThePixel() {
        int[] pixels = {WHITE, WHITE, WHITE, 0xFF808080, WHITE, WHITE};
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Grid.fromPixels(pixels, 3, 2, 1, key(), 1));
        assertEquals("pixel (0, 1) is #808080, a colour the key does not have (#FFFFFF -> 0, #000000 -> 1, #3070E0 -> 3);"
                + " paint programs blur edges with in-between colours: turn off anti-aliasing, or add the colour to the key",
                e.getMessage());
    }

    @Test
    void fromPixels_notOpaque_namesThePixel() {
        int[] pixels = {WHITE, 0x80FFFFFF};
        assertEquals("pixel (1, 0) is not opaque (alpha 128 of 255): paint every pixel of the map in one of the key's"
                + " colours, fully opaque",
                assertThrows(IllegalArgumentException.class, () -> Grid.fromPixels(pixels, 2, 1, 1, key(), 1)).getMessage());
    }

    @Test
    void fromPixels_blockOfTwoTerrains_namesTheCellAndBothPixels() {
        int[] pixels = new int[4 * 2];
        java.util.Arrays.fill(pixels, WHITE);
        pixels[1 * 4 + 3] = BLACK;  // pixel (3, 1), in cell (1, 0)
        assertEquals("cell (col 1, row 0) is not one terrain: pixel (2, 0) is #FFFFFF (terrain 0) but pixel (3, 1) is"
                + " #000000 (terrain 1); with 2 pixels per cell, each 2 x 2 block, counted from the top-left corner, is one cell",
                assertThrows(IllegalArgumentException.class, () -> Grid.fromPixels(pixels, 4, 2, 2, key(), 1)).getMessage());
    }

    @Test
    void fromPixels_sizesThatDoNotFit_areNamed() {
        int[] six = new int[6];
        java.util.Arrays.fill(six, WHITE);
        assertEquals("pixels has 6 values, but a width x height = 4 x 2 picture has 8",
                assertThrows(IllegalArgumentException.class, () -> Grid.fromPixels(six, 4, 2, 1, key(), 1)).getMessage());
        assertEquals("the picture is 3 pixels wide, not a whole number of pixelsPerCell = 2-pixel cells (2 or 4 would be)",
                assertThrows(IllegalArgumentException.class, () -> Grid.fromPixels(six, 3, 2, 2, key(), 1)).getMessage());
        assertEquals("the picture is 3 pixels high, not a whole number of pixelsPerCell = 2-pixel cells (2 or 4 would be)",
                assertThrows(IllegalArgumentException.class, () -> Grid.fromPixels(six, 2, 3, 2, key(), 1)).getMessage());
        assertEquals("the picture is 3 pixels wide, not a whole number of pixelsPerCell = 4-pixel cells (4 would be)",
                assertThrows(IllegalArgumentException.class, () -> Grid.fromPixels(new int[12], 3, 4, 4, key(), 1)).getMessage());
        assertEquals("the picture must be at least 1 x 1 pixels, was width x height = 0 x 2",
                assertThrows(IllegalArgumentException.class, () -> Grid.fromPixels(new int[0], 0, 2, 1, key(), 1)).getMessage());
        assertEquals("pixelsPerCell must be > 0, was 0",
                assertThrows(IllegalArgumentException.class, () -> Grid.fromPixels(six, 3, 2, 0, key(), 1)).getMessage());
        assertEquals("cellSize must be > 0, was -1.0",
                assertThrows(IllegalArgumentException.class, () -> Grid.fromPixels(six, 3, 2, 1, key(), -1)).getMessage());
        assertEquals("pixels must not be null",
                assertThrows(IllegalArgumentException.class, () -> Grid.fromPixels(null, 3, 2, 1, key(), 1)).getMessage());
        assertEquals("colors must not be null",
                assertThrows(IllegalArgumentException.class, () -> Grid.fromPixels(six, 3, 2, 1, null, 1)).getMessage());
        assertEquals("colors has no colours: put(color, terrain) each colour of the map",
                assertThrows(IllegalArgumentException.class,
                        () -> Grid.fromPixels(six, 3, 2, 1, new TerrainColors(), 1)).getMessage());
    }

    @Test
    void terrainColors_matchOnRedGreenBlue_andRefuseAColourForTwoTerrains() {
        TerrainColors key = key();
        assertEquals(3, key.terrainOf(BLUE));
        assertEquals(3, key.terrainOf(0x003070E0), "the alpha is ignored");
        assertThrows(IllegalArgumentException.class, () -> key.terrainOf(0xFF3070E1), "not in the key");
        assertEquals(3, key.terrainOf(0x3070E0));
        assertEquals(BLUE, key.colorOf(3));
        assertEquals(3, key.size());
        assertEquals(key, key.put(BLUE, 3), "the same pair again changes nothing");
        assertEquals(3, key.size());
        assertEquals("color #3070E0 already stands for terrain 3, so it cannot also be terrain 4: give each terrain its"
                + " own colour", assertThrows(IllegalArgumentException.class, () -> key.put(0x3070E0, 4)).getMessage());
        assertEquals("colour #123456 is not in the key (#FFFFFF -> 0, #000000 -> 1, #3070E0 -> 3)",
                assertThrows(IllegalArgumentException.class, () -> key.terrainOf(0x123456)).getMessage());
        assertEquals("no colour stands for terrain 9 in the key (#FFFFFF -> 0, #000000 -> 1, #3070E0 -> 3)",
                assertThrows(IllegalArgumentException.class, () -> key.colorOf(9)).getMessage());
        assertEquals("no colours", new TerrainColors().toString());
    }
}
