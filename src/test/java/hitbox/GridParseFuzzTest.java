package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * Fuzzing Grid.parse, which reads text a user (or a file) hands it. In a normal test run this
 * replays the inputs kept in src/test/resources/hitbox/GridParseFuzzTestInputs/parse/; with
 * {@code JAZZER_FUZZ=1} Jazzer looks for new ones. The documented exception is the only one
 * allowed, and a map that parses comes back the same through {@link Grid#toMap()}.
 */
class GridParseFuzzTest {

    @FuzzTest(maxDuration = "5m")
    void parse(FuzzedDataProvider data) {
        float cellWidth = data.consumeBoolean() ? data.consumeFloat() : data.consumeInt(1, 64);
        float cellHeight = cellWidth;  // a map is read with square cells
        String map = data.consumeRemainingAsString();
        Grid grid;
        try {
            grid = Grid.parse(map, cellWidth);
        } catch (IllegalArgumentException expected) {
            assertTrue(expected.getMessage() != null && !expected.getMessage().isBlank());
            return;
        }
        assertTrue(grid.cols() > 0 && grid.rows() > 0);
        // Every cell is a digit terrain, so the map's text reads back to the same cells.
        Grid again = Grid.parse(grid.toMap(), cellWidth);
        assertEquals(grid.toMap(), again.toMap());
        for (int row = 0; row < grid.rows(); row++) {
            for (int col = 0; col < grid.cols(); col++) {
                int t = grid.get(col, row);
                assertTrue(t >= 0 && t <= 9, "terrain " + t);
            }
        }
        // The pixel test answers without throwing, anywhere: for every shape that can be made
        // (a huge cell size can put a shape's numbers beyond the float range, which the shape refuses).
        probe(grid, () -> new Rect(cellWidth / 3, cellHeight / 2, cellWidth, cellHeight));
        probe(grid, () -> new Circle(grid.width() / 2, grid.height() / 2, cellWidth));
        grid.overlapsSolid(grid.cellRect(grid.cols() - 1, grid.rows() - 1));
    }

    private static void probe(Grid grid, java.util.function.Supplier<Shape> make) {
        Shape shape;
        try {
            shape = make.get();
        } catch (IllegalArgumentException refusedByTheShape) {
            return;
        }
        grid.overlapsSolid(shape);
    }
}
