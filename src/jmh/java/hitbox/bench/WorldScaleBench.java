package hitbox.bench;

import hitbox.Body;
import hitbox.BodyEvent;
import hitbox.BodyHit;
import hitbox.Circle;
import hitbox.Collisions;
import hitbox.Grid;
import hitbox.Ray;
import hitbox.Rect;
import hitbox.World;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * Every query, move and step of a {@link World} at 1,000, 10,000 and 100,000 bodies, so that
 * each one's growth with the world's size can be read off (issue 29): a world of circles in a
 * square lattice, each overlapping its four neighbours (about 2 contacts a body, all at rest),
 * with a grid's body beside it.
 *
 * <ul>
 * <li>{@code idleStep}: {@link World#step(List)} with nothing moved: constant, 0 bytes.</li>
 * <li>{@code stepAfterTeleports}: 100 bodies nudged and back, then a step: grows with the bodies
 *     moved (100), not with the world.</li>
 * <li>{@code legacyStep}: {@link World#step()} with nothing moved: a STAY per contact, linear.</li>
 * <li>{@code queryBoxWhole}: {@link World#queryShape} with the whole world's box (a {@link Rect}
 *     made once), into a reused list: k log k in the bodies found.</li>
 * <li>{@code queryBoxSmall} (a small box, made once), {@code queryPoint}, {@code overlapping}: a
 *     few bodies found: near constant.</li>
 * <li>{@code raycastAcross}: a ray across the lattice's top row: linear in the row's length (sqrt n).</li>
 * <li>{@code gridRay} beside {@code gridLineOfSight}: a ray along a grid of sqrt(n) by sqrt(n)
 *     cells and {@link Grid#lineOfSight} on the same segment.</li>
 * <li>{@code moves}: 100 circles moved by {@link World#move} through the standing lattice, then a
 *     step.</li>
 * </ul>
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class WorldScaleBench {

    @Param({"1000", "10000", "100000"})
    public int n;

    private World world;
    private Body[] lattice;
    private Body[] movers;
    private int side;
    private Grid grid;
    private World gridWorld;
    private float spread;
    private final List<BodyEvent> changes = new ArrayList<>();
    private final List<Body> found = new ArrayList<>();
    private final List<BodyHit> hits = new ArrayList<>();
    private final Predicate<Body> all = b -> true;
    /** The boxes of the box queries, made once as a sketch querying every frame would. */
    private Rect wholeBox;
    private Rect smallBox;
    private int frame;

    @Setup(Level.Trial)
    public void setup() {
        side = (int) Math.ceil(Math.sqrt(n));
        world = new World();
        lattice = new Body[n];
        for (int i = 0; i < n; i++) {
            lattice[i] = world.add(new Circle(0, 0, 5), (i % side) * 9.5f, (i / side) * 9.5f, 0);
        }
        spread = side * 9.5f;
        wholeBox = new Rect(-10, -10, spread + 20, spread + 20);
        smallBox = new Rect(spread / 2, spread / 2, 20, 20);
        movers = new Body[100];
        for (int i = 0; i < movers.length; i++) {
            movers[i] = world.add(new Rect(-2, -2, 4, 4), 4.75f + (i * 37 % side) * 9.5f, 4.75f + (i * 53 % side) * 9.5f, 0)
                    .layers(2, 2);  // they move through the lattice without meeting it: the sweep's cost, no slides
        }
        world.step(changes);
        grid = new Grid(side, side, 10);
        grid.fillRandom(0.05f, 7, 0, 0);
        for (int col = 0; col < side; col++) {
            grid.set(col, 0, Grid.EMPTY);  // the ray below runs along row 0
        }
        grid.set(side - 1, 0, Grid.SOLID);  // the far end of row 0: the ray meets it last
        gridWorld = new World();
        gridWorld.add(grid);
    }

    @Benchmark
    public int idleStep() {
        world.step(changes);
        return changes.size();
    }

    @Benchmark
    public int stepAfterTeleports() {
        frame++;
        float d = (frame & 1) == 0 ? 0.25f : -0.25f;
        for (int i = 0; i < 100; i++) {
            Body b = lattice[(i * 7919) % n];
            b.moveTo(b.pivotX() + d, b.pivotY());
        }
        world.step(changes);
        return changes.size();
    }

    @Benchmark
    public int legacyStep() {
        return world.step().size();
    }

    @Benchmark
    public int queryBoxWhole() {
        found.clear();
        world.queryShape(wholeBox, all, found);
        return found.size();
    }

    @Benchmark
    public int queryBoxSmall() {
        found.clear();
        world.queryShape(smallBox, all, found);
        return found.size();
    }

    @Benchmark
    public int queryPoint() {
        found.clear();
        world.queryPoint(spread / 2 + 1, spread / 2 + 1, all, found);
        return found.size();
    }

    @Benchmark
    public int overlapping() {
        found.clear();
        world.overlapping(lattice[n / 2], all, found);
        return found.size();
    }

    @Benchmark
    public int raycastAcross() {
        hits.clear();
        world.raycast(new Ray(-20, 0.5f, 1, 0, spread + 40), all, hits);
        return hits.size();
    }

    @Benchmark
    public Object gridRay() {
        return gridWorld.raycastFirst(new Ray(1, 5, 1, 0.001f, side * 10), all);
    }

    @Benchmark
    public boolean gridLineOfSight() {
        return grid.lineOfSight(1, 5, side * 10, 5 + side * 10 * 0.001f);
    }

    @Benchmark
    public int moves() {
        frame++;
        float d = (frame & 1) == 0 ? 3 : -3;
        int met = 0;
        for (Body m : movers) {
            Collisions c = world.move(m, d, d);
            met += c.size();
        }
        world.step(changes);
        return met + changes.size();
    }
}
