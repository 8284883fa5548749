package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * Fuzzing Grid.fromPixels, which reads a map drawn as a picture. In a normal test run this
 * replays the inputs kept in src/test/resources/hitbox/GridFromPixelsFuzzTestInputs/read/;
 * with {@code JAZZER_FUZZ=1} Jazzer looks for new ones. Only the documented exception is
 * allowed; a map that is read has one cell per block of pixels, each the terrain of its
 * block's colour.
 */
class GridFromPixelsFuzzTest {

    private static final int[] PALETTE = {0xFFFFFFFF, 0xFF000000, 0xFF3070E0, 0x80FFFFFF, 0xFF123456};

    @FuzzTest(maxDuration = "5m")
    void read(FuzzedDataProvider data) {
        int width = data.consumeInt(-1, 40);
        int height = data.consumeInt(-1, 40);
        int ppc = data.consumeInt(-1, 5);
        float cellSize = data.consumeBoolean() ? data.consumeFloat() : data.consumeInt(1, 16);
        int n = data.consumeInt(0, 1700);
        int[] pixels = new int[n];
        for (int i = 0; i < n; i++) {
            pixels[i] = data.consumeBoolean() ? PALETTE[data.consumeInt(0, PALETTE.length - 1)] : data.consumeInt();
        }
        TerrainColors key = new TerrainColors().put(0xFFFFFF, Grid.EMPTY).put(0x000000, Grid.SOLID).put(0x3070E0, 3);
        Grid grid;
        try {
            grid = Grid.fromPixels(pixels, width, height, ppc, key, cellSize);
        } catch (IllegalArgumentException expected) {
            assertTrue(expected.getMessage() != null && !expected.getMessage().isBlank());
            return;
        }
        assertEquals(width, grid.cols() * ppc);
        assertEquals(height, grid.rows() * ppc);
        for (int row = 0; row < grid.rows(); row++) {
            for (int col = 0; col < grid.cols(); col++) {
                int pixel = pixels[row * ppc * width + col * ppc];
                assertEquals(key.terrainOf(pixel), grid.get(col, row), "cell " + col + ", " + row);
            }
        }
    }
}
