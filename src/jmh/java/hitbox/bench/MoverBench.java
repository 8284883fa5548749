package hitbox.bench;

import hitbox.Body;
import hitbox.CharacterBody;
import hitbox.Polygon;
import hitbox.Rect;
import hitbox.Shape;
import hitbox.World;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
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
 * Issue 28's scene: 1,000 movers among 10,000 standing bodies, one frame a call. Half walk a
 * terrain of slopes and steps (500 lanes of floor tiles, a ramp, a plateau and a step down,
 * under gravity), half slide among turned boxes and triangles (pressed into them, turning back
 * when held). {@code walkers = "character"} moves the walkers as {@link CharacterBody}s;
 * {@code "body"} moves them with {@link World#move}, which is what the library had before the
 * character (the same scene then runs on the code before the change, for the before-and-after
 * rows of docs/world-benchmark.md). Bytes a frame with {@code -prof gc}.
 *
 * <p>{@code gradle jmh -Pjmh.include=MoverBench -Pjmh.args="-f 1 -wi 3 -i 5 -prof gc"}
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class MoverBench {

    @Param({"character", "body"})
    public String walkers;

    static final int LANES = 500;
    static final float LANE = 60;
    static final float LENGTH = 400;

    private World world;
    private Body[] walker;
    private CharacterBody[] hero;
    private float[] walkerVy;
    private Body[] slider;
    private float[] sliderV;

    @Setup(Level.Trial)
    public void setup() {
        world = new World();
        SplittableRandom rnd = new SplittableRandom(28);
        int standing = 0;
        // 500 lanes of 10 bodies: 6 floor tiles, a ramp, a plateau, a step down and a wall.
        for (int l = 0; l < LANES; l++) {
            float y = l * LANE + 50;
            for (int t = 0; t < 6; t++) {
                world.add(new Rect(t * 30, y, 30, 10));
            }
            world.add(Polygon.of(180, y, 260, y - 30, 260, y));
            world.add(new Rect(260, y - 30, 60, 40));
            world.add(new Rect(320, y - 22, 60, 32));  // a step of 8 down
            world.add(new Rect(380, y - 60, 20, 70));
            standing += 10;
        }
        // 5,000 turned obstacles in a field beside the lanes.
        float fx = 600, size = 1800;
        while (standing < 10_000) {
            float x = fx + (float) rnd.nextDouble() * size, y = (float) rnd.nextDouble() * LANES * LANE;
            Shape s = standing % 2 == 0 ? new Rect(-8, -8, 16, 16) : Polygon.of(-10, 8, 10, 8, 0, -10);
            world.add(s, x, y, (float) rnd.nextDouble() * 6);
            standing++;
        }
        walker = new Body[LANES];
        hero = new CharacterBody[LANES];
        walkerVy = new float[LANES];
        for (int l = 0; l < LANES; l++) {
            Rect r = new Rect(10, l * LANE + 50 - 20, 10, 20);
            if (walkers.equals("character")) {
                hero[l] = world.addCharacter(r).stepHeight(9).snap(4);
                walker[l] = hero[l].body();
            } else {
                walker[l] = world.add(r);
            }
        }
        slider = new Body[500];
        sliderV = new float[1000];
        for (int i = 0; i < slider.length; i++) {
            Shape s = null;
            while (s == null) {
                float x = fx + (float) rnd.nextDouble() * size, y = (float) rnd.nextDouble() * LANES * LANE;
                Shape c = i % 2 == 0 ? new hitbox.Circle(x, y, 5) : new Rect(x - 5, y - 5, 10, 10);
                if (world.queryShape(c).isEmpty()) {
                    s = c;
                }
            }
            slider[i] = world.add(s).layers(2, 1);  // sliders pass each other
            double a = rnd.nextDouble() * 2 * Math.PI;
            sliderV[2 * i] = (float) (2 * Math.cos(a));
            sliderV[2 * i + 1] = (float) (2 * Math.sin(a));
        }
        for (int f = 0; f < 200; f++) {
            frame();
        }
    }

    /** One frame: every walker and every slider moves once. */
    @Benchmark
    public int frame() {
        int met = 0;
        for (int l = 0; l < LANES; l++) {
            float vy = walkerVy[l] + 0.5f;
            Body b = walker[l];
            if (hero[l] != null) {
                met += hero[l].move(2, vy).size();
                walkerVy[l] = hero[l].onGround() ? 0 : vy;
            } else {
                java.util.List<hitbox.Collision> got = world.move(b, 2, vy);
                met += got.size();
                for (int k = 0; k < got.size(); k++) {
                    if (got.get(k).ny() > 0.5f) {
                        vy = 0;
                    }
                }
                walkerVy[l] = vy;
            }
            if (b.pivotX() > 370) {
                b.moveTo(15, l * LANE + 50 - 10);  // back to the lane's start
                walkerVy[l] = 0;
            }
        }
        for (int i = 0; i < slider.length; i++) {
            Body b = slider[i];
            float x = b.pivotX(), y = b.pivotY();
            met += world.move(b, sliderV[2 * i], sliderV[2 * i + 1]).size();
            if (Math.abs(b.pivotX() - x) + Math.abs(b.pivotY() - y) < 0.5f) {
                sliderV[2 * i] = -sliderV[2 * i];  // held: turn back
                sliderV[2 * i + 1] = -sliderV[2 * i + 1];
            }
        }
        return met;
    }
}
