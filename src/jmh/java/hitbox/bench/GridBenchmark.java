package hitbox.bench;

import java.util.Random;
import java.util.concurrent.TimeUnit;

import hitbox.Collide;
import hitbox.Grid;
import hitbox.PathCosts;
import hitbox.Rect;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * Grids at sizes a sketch would never draw but a game map might hold.
 *
 * <ul>
 *   <li>Line of sight: 200 lines between random points of a 2000 x 2000 grid (8 px cells),
 *       open but for a few scattered walls so most lines are walked to the end; against the
 *       baseline that tests every solid cell in each line's bounding box with
 *       {@code Collide.lineRect}.</li>
 *   <li>Routes on a 1000 x 1000 grid: the fewest steps corner to corner on an open grid and
 *       through a random maze (30% solid), and the cheapest route over random terrain, with
 *       and without diagonals.</li>
 * </ul>
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class GridBenchmark {
    static final int LINES = 200;

    Grid sight;
    float[] lines = new float[4 * LINES];
    Grid open;
    Grid maze;
    Grid terrain;
    PathCosts costs = PathCosts.byTerrain(1, Float.POSITIVE_INFINITY, 3, 8);
    int[] mazeEnds;

    @Setup
    public void setup() {
        Random random = new Random(11);
        sight = new Grid(2000, 2000, 8).fillRandom(0.0001f, 3, 0, 0);
        for (int i = 0; i < lines.length; i++) {
            lines[i] = random.nextFloat() * sight.width();
        }
        open = new Grid(1000, 1000, 8);
        maze = new Grid(1000, 1000, 8).fillRandom(0.3f, 5, 0, 0);
        maze.set(999, 999, Grid.EMPTY);
        terrain = new Grid(1000, 1000, 8).passable(2, 3);
        for (int row = 0; row < 1000; row++) {
            for (int col = 0; col < 1000; col++) {
                int r = random.nextInt(100);
                terrain.set(col, row, r < 10 ? Grid.SOLID : r < 30 ? 2 : r < 35 ? 3 : Grid.EMPTY);
            }
        }
        terrain.set(0, 0, Grid.EMPTY);
        terrain.set(999, 999, Grid.EMPTY);
        if (lineOfSight() != scanBoundingBoxes()) {
            throw new IllegalStateException("the walk and the scan disagree");
        }
        if (pathMaze() == 0 || pathTerrain() == 0) {
            throw new IllegalStateException("no route through the maze or the terrain: pick another seed");
        }
    }

    /** 200 lines, each walked cell by cell; counts the clear ones. */
    @Benchmark
    public int lineOfSight() {
        int clear = 0;
        for (int i = 0; i < lines.length; i += 4) {
            if (sight.lineOfSight(lines[i], lines[i + 1], lines[i + 2], lines[i + 3])) {
                clear++;
            }
        }
        return clear;
    }

    /** Baseline: the same 200 lines, each tested against every solid cell of its bounding box. */
    @Benchmark
    public int scanBoundingBoxes() {
        int clear = 0;
        for (int i = 0; i < lines.length; i += 4) {
            float x0 = lines[i], y0 = lines[i + 1], x1 = lines[i + 2], y1 = lines[i + 3];
            boolean blocked = false;
            for (int row = sight.rowAt(Math.min(y0, y1)); row <= sight.rowAt(Math.max(y0, y1)) && !blocked; row++) {
                for (int col = sight.colAt(Math.min(x0, x1)); col <= sight.colAt(Math.max(x0, x1)); col++) {
                    if (sight.isSolid(col, row)) {
                        Rect c = sight.cellRect(col, row);
                        if (Collide.lineRect(x0, y0, x1, y1, c.x(), c.y(), c.w(), c.h())) {
                            blocked = true;
                            break;
                        }
                    }
                }
            }
            if (!blocked) {
                clear++;
            }
        }
        return clear;
    }

    /** Fewest steps, corner to corner, on an open 1000 x 1000 grid (1999 cells). */
    @Benchmark
    public int pathOpen() {
        return open.path(0, 0, 999, 999).length;
    }

    /**
     * Baseline for {@link #pathOpen}: the same breadth-first search on plain arrays, with
     * nothing asked of the grid; what a search of a million cells costs on this machine.
     */
    @Benchmark
    public int pathOpenPlainArrays() {
        int cols = 1000, rows = 1000, n = cols * rows;
        if (plainSeen == null) {
            plainSeen = new int[n];
            plainLink = new int[n];
            plainQueue = new int[n];
        }
        int mark = ++plainMark;
        int start = 0, goal = n - 1;
        plainSeen[goal] = mark;
        plainQueue[0] = goal;
        int head = 0, tail = 1;
        while (head < tail) {
            int cell = plainQueue[head++];
            int row = cell / cols, col = cell - row * cols;
            for (int k = 0; k < 4; k++) {
                int c = col + (k == 0 ? 1 : k == 1 ? -1 : 0), r = row + (k == 2 ? 1 : k == 3 ? -1 : 0);
                if (c < 0 || c >= cols || r < 0 || r >= rows) {
                    continue;
                }
                int next = r * cols + c;
                if (plainSeen[next] != mark) {
                    plainSeen[next] = mark;
                    plainLink[next] = cell;
                    if (next == start) {
                        return tail;
                    }
                    plainQueue[tail++] = next;
                }
            }
        }
        return 0;
    }

    int[] plainSeen;
    int[] plainLink;
    int[] plainQueue;
    int plainMark;

    /** Fewest steps through a 1000 x 1000 maze, 30% solid. */
    @Benchmark
    public int pathMaze() {
        return maze.path(0, 0, 999, 999).length;
    }

    /** Cheapest route over 1000 x 1000 cells of grass, forest, water and walls, straight steps. */
    @Benchmark
    public int pathTerrain() {
        return terrain.path(0, 0, 999, 999, costs).length;
    }

    /** The same with diagonal steps. */
    @Benchmark
    public int pathTerrainDiagonal() {
        return terrain.path(0, 0, 999, 999, costs.withDiagonals()).length;
    }
}
