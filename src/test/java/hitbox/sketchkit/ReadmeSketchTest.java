package hitbox.sketchkit;

import hitbox.internal.Extents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import hitbox.Body;
import hitbox.CharacterBody;
import processing.core.PApplet;

/**
 * The README's Processing code blocks are sketches that really build, through Processing's own
 * preprocessor as the IDE builds them, each exactly as the README prints it; and its platformer
 * on the world runs: the player falls onto the floor, runs along it, jumps, and walks up the
 * slope.
 */
class ReadmeSketchTest {
    private static final File README = new File("README.md");

    @TempDir
    static Path out;
    static File classes;
    static List<String> blocks;
    static final List<SketchBuild.Outcome> OUTCOMES = new ArrayList<>();

    /** Every block fenced with {@code ```processing} in the README, in order, as printed. */
    static List<String> processingBlocks(String readme) {
        List<String> found = new ArrayList<>();
        StringBuilder block = null;
        for (String line : readme.split("\n", -1)) {
            if (block == null) {
                if (line.strip().equals("```processing")) {
                    block = new StringBuilder();
                }
            } else if (line.strip().equals("```")) {
                found.add(block.toString());
                block = null;
            } else {
                block.append(line).append('\n');
            }
        }
        return found;
    }

    @BeforeAll
    static void buildEveryBlock() throws IOException {
        blocks = processingBlocks(Files.readString(README.toPath(), StandardCharsets.UTF_8));
        classes = out.resolve("classes").toFile();
        for (int i = 0; i < blocks.size(); i++) {
            String name = "ReadmeBlock" + (i + 1);
            Path folder = Files.createDirectories(out.resolve("sketches").resolve(name));
            Files.writeString(folder.resolve(name + ".pde"), blocks.get(i));
            OUTCOMES.add(SketchBuild.build(folder.toFile(), SketchBuild.PACKAGE, TestClassPath.get(), classes));
        }
    }

    @Test
    void everyProcessingBlock_buildsAsTheIdeBuildsIt() {
        assertTrue(blocks.size() >= 2, "the first sketch and the platformer: " + blocks.size() + " blocks");
        for (SketchBuild.Outcome o : OUTCOMES) {
            assertTrue(o.ok(), o.name() + ", the README's block " + o.name().substring("ReadmeBlock".length())
                    + ", does not build:\n" + o.report());
        }
    }

    /** The block that makes a world: the README's platformer. */
    private static int platformer() {
        for (int i = 0; i < blocks.size(); i++) {
            if (blocks.get(i).contains("new World(")) {
                return i;
            }
        }
        throw new AssertionError("the README has no ```processing block with new World(");
    }

    @Test
    void thePlatformer_isAboutFifteenLines() {
        long lines = blocks.get(platformer()).lines().filter(l -> !l.isBlank()).count();
        assertTrue(lines <= 25, "the README's platformer is short: " + lines + " lines");
    }

    private static PApplet newPlatformer() throws ReflectiveOperationException, IOException {
        int i = platformer();
        assertTrue(OUTCOMES.get(i).ok(), OUTCOMES.get(i).report());
        URLClassLoader loader = new URLClassLoader(new URL[] {classes.toURI().toURL()}, ReadmeSketchTest.class.getClassLoader());
        return (PApplet) Class.forName(SketchBuild.PACKAGE + ".ReadmeBlock" + (i + 1), true, loader)
                .getDeclaredConstructor().newInstance();
    }

    private static CharacterBody character(PApplet sketch) throws ReflectiveOperationException {
        java.lang.reflect.Field field = sketch.getClass().getDeclaredField("player");
        field.setAccessible(true);   // a sketch's globals are package-private fields
        return (CharacterBody) field.get(sketch);
    }

    private static Body player(PApplet sketch) throws ReflectiveOperationException {
        return character(sketch).body();
    }

    @Test
    void thePlatformer_playerLandsOnTheFloor_runsRight_jumps_andWalksUpTheSlope() throws Exception {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
        // Falls and lands, then runs right, then jumps, then runs right up the slope.
        double[] startX = new double[1];
        double[] top = {Double.MAX_VALUE};
        double[] landed = new double[1];
        double[] last = {Double.NaN, Double.NaN};
        int[] upTheSlope = {0};
        Script script = new Script().frames(310).hold(80, "RIGHT", 40).key(150, ' ').hold(200, "RIGHT", 110);
        SketchRun.of(newPlatformer()).script(script).everyFrame(s -> {
            try {
                Body p = player(s);
                double bottom = Extents.maxY(p.shape());
                if (s.frameCount == 79) {
                    landed[0] = bottom;
                    startX[0] = Extents.minX(p.shape());
                }
                if (s.frameCount == 125) {
                    assertEquals(landed[0], bottom, 1e-3, "runs along the floor, at the same height");
                    assertTrue(Extents.minX(p.shape()) > startX[0] + 40, "ran right: from " + startX[0] + " to " + Extents.minX(p.shape()));
                }
                if (s.frameCount > 150 && s.frameCount < 200) {
                    top[0] = Math.min(top[0], bottom);
                }
                // Up the slope: on the ground every frame, three pixels sideways, rising.
                if (s.frameCount > 202 && Extents.maxX(p.shape()) > 430) {
                    assertTrue(character(s).onGround(), "frame " + s.frameCount + ": on the ground up the slope");
                    assertEquals(3, Extents.minX(p.shape()) - last[0], 1e-3, "frame " + s.frameCount + ": three pixels sideways");
                    assertTrue(bottom < last[1], "frame " + s.frameCount + ": and up: " + last[1] + " to " + bottom);
                    upTheSlope[0]++;
                }
                last[0] = Extents.minX(p.shape());
                last[1] = bottom;
                if (s.frameCount == 310) {
                    assertTrue(bottom < landed[0] - 25, "walked up the slope: from " + landed[0] + " to " + bottom);
                }
            } catch (ReflectiveOperationException e) {
                throw new AssertionError(e);
            }
        }).run();
        assertTrue(landed[0] > 300 && landed[0] < 400, "stands on the floor near the bottom: " + landed[0]);
        assertTrue(top[0] < landed[0] - 40, "the jump goes up: from " + landed[0] + " to " + top[0]);
        assertTrue(upTheSlope[0] > 20, "frames walking up the slope: " + upTheSlope[0]);
    }
}
