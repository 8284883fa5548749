package hitbox.bench;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * detect-collisions' row of the world scene's table: the scene through its own {@code System} in
 * Node ({@code src/jmh/node/world-scene.mjs}, which says what it does each frame), its answers
 * compared with Hitbox's as the Java contenders' are ({@link WorldSceneBench#compare}).
 *
 * <p>Java writes the scene as it starts ({@link #write}); the script moves it with
 * {@link WorldScene#step()}'s float arithmetic, and hands back the poses after the checked frames,
 * which must equal Java's bit for bit: then both have asked about the very same shapes.
 */
final class WorldSceneNode {
    /** What the script measured and found, or why it could not run ({@link #failure} non-null). */
    static final class Result {
        /** Why there is no row ("not run: ..." or "failed: ..."), or null. */
        String failure;
        /** detect-collisions' version and check2d's, space-separated. */
        String versions;
        /** Median ms of the main thread's CPU a frame, or -1 without a per-thread clock. */
        double threadMs;
        /** Median ms of the whole process's CPU a frame. */
        double processMs;
        /** Median bytes of JavaScript heap allocated a frame, or -1 where Node cannot tell. */
        double bytes;
    }

    private WorldSceneNode() {
    }

    /**
     * How many points detect-collisions gives an ellipse made as its stress demo makes them (step
     * 2): {@code max(8, ceil(2 pi hypot(rx, ry) / max(1, step)))}, its {@code createEllipse}.
     */
    static int ellipseCorners(float rx, float ry) {
        return (int) Math.max(8, Math.ceil(Math.PI * Math.hypot(rx, ry) * 2 / 2));
    }

    /**
     * Runs the script on a fresh scene of n bodies (seed 42, as the Java contenders') and checks
     * its answers; the returned result says why when Node, the package or the check failed.
     *
     * @param script the script's path
     * @param checkFrames the frames between the two checked ones
     * @param rounds the timed rounds (two more warm up)
     * @param budgetMs CPU time a round, in ms
     */
    static Result run(Path script, int n, int checkFrames, int rounds, long budgetMs) {
        Result result = new Result();
        Path sceneFile = null, answerFile = null, errFile = null;
        try {
            WorldScene scene = new WorldScene(n, 42);
            sceneFile = Files.createTempFile("world-scene", ".bin");
            answerFile = Files.createTempFile("world-scene", ".txt");
            errFile = Files.createTempFile("world-scene", ".err");
            write(scene, sceneFile);
            Process node;
            try {
                node = new ProcessBuilder(System.getProperty("node", "node"), script.toString(), sceneFile.toString(), answerFile.toString(),
                        Integer.toString(checkFrames), Integer.toString(rounds), Long.toString(budgetMs))
                        .redirectOutput(ProcessBuilder.Redirect.INHERIT).redirectError(errFile.toFile()).start();
            } catch (IOException e) {
                result.failure = "not run: no Node (" + e.getMessage() + ")";
                return result;
            }
            if (!node.waitFor(2, TimeUnit.HOURS)) {
                node.destroyForcibly();
                result.failure = "not run: node took over 2 hours";
                return result;
            }
            if (node.exitValue() != 0) {
                List<String> err = Files.readAllLines(errFile, StandardCharsets.UTF_8);
                String why = err.stream().filter(l -> l.matches("\\s*\\w*Error\\b.*")).findFirst().orElse(err.isEmpty() ? "" : err.get(err.size() - 1));
                result.failure = "not run: node exited with " + node.exitValue() + ": " + why.trim()
                        + (why.contains("detect-collisions") ? " (`npm ci` in src/jmh/node)" : "");
                return result;
            }
            Map<String, String> answer = new HashMap<>();
            for (String line : Files.readAllLines(answerFile, StandardCharsets.UTF_8)) {
                int space = line.indexOf(' ');
                answer.put(space < 0 ? line : line.substring(0, space), space < 0 ? "" : line.substring(space + 1));
            }
            result.versions = answer.get("versions");
            String name = "detectCollisions " + result.versions.replace(' ', '/');
            WorldSceneBench.compare(scene, pairs(answer.get("pairs0")), name);
            for (int f = 0; f < checkFrames; f++) {
                scene.step();
            }
            samePoses(scene, answer.get("poses"));
            WorldSceneBench.compare(scene, pairs(answer.get("pairsF")), name);
            result.threadMs = median(answer.get("threadMs"));
            result.processMs = median(answer.get("processMs"));
            result.bytes = median(answer.get("bytes"));
            return result;
        } catch (IOException | IllegalStateException e) {
            result.failure = "failed: " + e.getMessage();
            return result;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            result.failure = "interrupted";
            return result;
        } finally {
            for (Path p : new Path[] {sceneFile, answerFile, errFile}) {
                if (p != null) {
                    try {
                        Files.deleteIfExists(p);
                    } catch (IOException ignored) {
                        // a temporary file left behind
                    }
                }
            }
        }
    }

    /**
     * The scene as it starts, little-endian: n, the size unit, then each array whole: kind,
     * p, q, the polygons' corners (8 a body, 0 for the others), x, y, angle, vx, vy, spin, standing (1 or 0).
     */
    static void write(WorldScene s, Path file) throws IOException {
        int n = s.n;
        ByteBuffer b = ByteBuffer.allocate(8 + 4 * n * 18).order(ByteOrder.LITTLE_ENDIAN);
        b.putInt(n).putFloat(s.size);
        for (int i = 0; i < n; i++) {
            b.putInt(s.kind[i]);
        }
        for (float[] column : new float[][] {s.p, s.q}) {
            for (int i = 0; i < n; i++) {
                b.putFloat(column[i]);
            }
        }
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < 8; k++) {
                b.putFloat(s.corners[i] == null ? 0 : s.corners[i][k]);
            }
        }
        for (float[] column : new float[][] {s.x, s.y, s.angle, s.vx, s.vy, s.spin}) {
            for (int i = 0; i < n; i++) {
                b.putFloat(column[i]);
            }
        }
        for (int i = 0; i < n; i++) {
            b.putInt(s.standing[i] ? 1 : 0);
        }
        Files.write(file, b.array());
    }

    /** The script's pairs, "a b a b ...", as sorted keys. */
    private static long[] pairs(String list) {
        String[] v = list.isBlank() ? new String[0] : list.trim().split(" ");
        long[] keys = new long[v.length / 2];
        for (int k = 0; k < keys.length; k++) {
            keys[k] = WorldSceneContenders.Contender.key(Integer.parseInt(v[2 * k]), Integer.parseInt(v[2 * k + 1]));
        }
        Arrays.sort(keys);
        return keys;
    }

    /** The script's poses (x, y, angle a body, as float bits) must be the scene's, bit for bit. */
    private static void samePoses(WorldScene s, String list) {
        String[] v = list.trim().split(" ");
        if (v.length != 3 * s.n) {
            throw new IllegalStateException("node gave " + v.length / 3 + " poses for " + s.n + " bodies");
        }
        for (int i = 0; i < s.n; i++) {
            float[] mine = {s.x[i], s.y[i], s.angle[i]};
            for (int k = 0; k < 3; k++) {
                if (Float.floatToRawIntBits(mine[k]) != Integer.parseInt(v[3 * i + k])) {
                    throw new IllegalStateException("node's pose of body " + i + " differs from Java's: "
                            + Float.intBitsToFloat(Integer.parseInt(v[3 * i + k])) + " against " + mine[k]);
                }
            }
        }
    }

    private static double median(String list) {
        double[] v = Arrays.stream(list.trim().split(" ")).mapToDouble(Double::parseDouble).sorted().toArray();
        return v[v.length / 2];
    }
}
