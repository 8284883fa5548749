package hitbox.bench;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import jdk.jfr.consumer.RecordedClass;
import jdk.jfr.consumer.RecordedEvent;
import jdk.jfr.consumer.RecordedFrame;
import jdk.jfr.consumer.RecordedStackTrace;
import jdk.jfr.consumer.RecordingFile;
import org.openjdk.jmh.runner.Runner;
import org.openjdk.jmh.runner.RunnerException;
import org.openjdk.jmh.runner.options.OptionsBuilder;
import org.openjdk.jmh.runner.options.TimeValue;

/**
 * Where a missed row of the narrow-phase table spends its time (or its bytes): each Hitbox
 * call that misses a goal is run once more, alone, under async-profiler (its Linux library
 * ships inside the {@code tools.profiler:async-profiler} jar), which records to JFR. It samples
 * without the safepoint bias of JMH's stack profiler, and with {@code -XX:+DebugNonSafepoints}
 * each sample's top frame names its source line even inside code inlined into the benchmark's
 * loop, which is where a few-nanosecond test lives. The table then quotes the hottest lines,
 * so a reader sees what a miss is made of rather than being told.
 *
 * <p>CPU samples come from {@code itimer} (no perf_events needed) every 0.1 ms; allocation
 * samples from the JVM's TLAB events, weighted by size. The agent starts with the JVM, so the
 * first second (warm-up, the interpreter) is in the samples too; the run is measured for five
 * more, and only samples inside {@link NarrowPhaseBench#answerEveryCase} count.
 */
final class NarrowProfiles {
    private NarrowProfiles() {
    }

    /** One line's share of a call's samples, with the source line itself where it is ours. */
    record Line(String frame, double percent, String source) {
    }

    /** A call's profile: what was sampled ("cpu" or "alloc"), how many samples, the top lines. */
    record Profile(String id, String event, long total, List<Line> top) {
    }

    /** How the profiles were taken, for the table's text. */
    static final String HOW = "itimer samples every 0.1 ms and allocation samples, 1 s warm-up and 5 s measured,"
            + " `-XX:+DebugNonSafepoints` so inlined lines are named";

    /**
     * Why each call misses, as far as its profile and the code say: written by hand from a
     * profiled run, keyed by contender id (question.key). A miss with no reason here says so
     * in the table, so a new miss cannot hide behind an old sentence.
     */
    private static final Map<String, String> WHY = new HashMap<>();

    static {
        WHY.put("sepPoly8.raw", "Every edge of one outline against every edge of the other (64 pairs for two 8-gons), each pair's distance the least of its end-to-edge distances, with an exact crossing test where the pair's boxes meet (`Distances.chains`), after the exact overlap test that makes sure the two are apart (`Collide.polygonPolygon`) and a copy of each outline in double. The same kernel answers concave outlines and every pair of straight kinds; dyn4j's GJK walks two convex outlines in a few steps, stops within its epsilon, and gives no distance for touching pairs (the notes). A walk for two convex outlines is the next step.");
        WHY.put("sepPoly8.shape", "The exact overlap test through the shapes' own tests first (`Overlaps`), then `ConvexOutlines`: the two outlines' difference, their edges merged by direction (16 steps for two 8-gons), whose edge nearest the origin names the pair of edges that holds the closest points, measured as every kernel of straight edges measures a pair (its end-to-edge distances and an exact crossing test; 1.25 pairs a case here). By perf on 2026-11-29, with the helpers kept out of line: the merge with its comparisons of directions about half of the time, the two walks from the lowest corners a sixth, then the distances, the measured pair and the `Separation`. Until then this was every edge against every vertex of the other (`Distances.facing`) and the pairs that face each other: 1,037 ns. JBox2D's GJK runs in float on polygons whose normals it stores; dyn4j's stops within its epsilon and gives no distance for touching pairs (the notes).");
        WHY.put("sepCirclePoly8.raw", "The circle's centre against each of the polygon's edges (`Distances.chains`), after the exact overlap test (`Collide.polygonCircle`) and a copy of the outline in double; JBox2D's GJK runs in float on a polygon whose normals it stores.");
        WHY.put("sepCirclePoly8.shape", "One pass over the polygon's edges for their squared distances from the circle's centre (those it is surely behind left out), then the nearest measured with both closest points (`Distances.pointAndOutline`); the exact overlap test (`Overlaps`) is asked only where the two are not surely apart (an exact side and a gap beyond rounding: the touching cases, one in eight here). Before 2026-11-30 the overlap test came first, a third of the time, then every edge the centre lies in front of (2.26x). JBox2D's GJK runs in float on a polygon whose normals it stores.");
        WHY.put("sepCircleCircle.shape", "The raw call is a square root of two squares; the Shape route first runs the exact overlap test and makes the `Separation` with both closest points.");
        WHY.put("containRect.shape", "Each side is a sum of two floats compared exactly: the sums in float decide when they differ, and a tie (an edge on an edge, a third of these cases) is settled exactly by error-free sums (`Containment.atLeast`), after `Rect.contains(Shape)`'s switch over the kinds. libGDX compares its float sums strictly, so an edge on an edge is \"not held\" there (the notes).");
        WHY.put("manifoldPoly8.manifold", "One kernel for every pair with area, concave shapes through their convex pieces (`Manifolds`): the contact first (`Contact.between`), then the reference face and incident edge of each pair of pieces clipped in double, each candidate point's depth measured by a ray through both shapes, its pieces, edges and points in a thread's scratch (a call makes only its answer). JBox2D and dyn4j clip two convex polygons in float against normals they store, and some of their points lie outside a shape (the notes). Of the time left after issue 29's trim (a profile of 2026-11-29, before the face query's early stop), the contact's face query (`FaceQuery.convexPolygons`) took a third, making the two pieces' planes and faces (`Manifolds$Piece.set`) a sixth, the depth rays (`Manifolds.slabExit`) a thirteenth: normals kept with a polygon, as Box2D keeps them, are the next step.");
        WHY.put("manifoldBoxes.manifold", "As for two 8-gons: the same kernel, through a turned rectangle's polygon. The contact's face query (`FaceQuery.convexPolygons`) stops reading an edge's reach once it is too long to win; the pieces' face lengths are worked out once per piece.");
        WHY.put("polygonRect.collide", "Each of the polygon's edges is tested against the rectangle exactly (`Collide.lineRect`, with its own NaN check, `Check.nan`), then a corner of each shape for containment in the other (`Polygons.locate`): exact for concave polygons too, where dyn4j's GJK takes convexity on trust and decides touching within an epsilon. A `Polygon`, which keeps its convexity, goes the separating-edge way instead (`Polygons.convexRectOverlap`: its box against the rectangle, then each edge against the rectangle's four corners, exact orientations); for the raw array, finding the convexity first cost more than it saved (179 against 147 ns a call on this table).");
        WHY.put("polygonLine.collide", "Each end in the polygon first (`Polygons.contains`, exact), then the segment against the edges with exact orientations (`Polygons.segmentCrossesInto`), after a NaN check of every coordinate (`Check.nan`) and the winding the raw array does not keep. The code did not change between the runs of 2026-11-29: at 18:12 UTC it measured 157 ns against dyn4j's GJK at 182 (0.86x), at 22:54 131 against 114; the peer's swing decides the row on this busy machine.");
        WHY.put("lineCircle.shape", "The raw and the Shape profiles show the same lines (`Check.nan`, `Lines.signOfProductDifference`); what the route through `Overlaps` adds is the objects' fields and a type check on a 6 ns test, and this short run's noise (earlier runs measured 1.14x and under 1.25x).");
        WHY.put("poly8.collide", "The raw call takes two float arrays, so it must first learn whether each outline is convex, with an exact orientation at every corner (`Polygons.convexWinding` in the profile) before the exact separating-edge test; a `Polygon` knows that from its construction, and `Polygon.overlaps`, in the table below, skips it. dyn4j's GJK takes convexity on trust and decides touching within an epsilon.");
        WHY.put("star16Point.collide", "The same crossing count as libGDX's, in double: the corners are widened to double, a point within an edge's x range has its side decided by an exact orientation, and an inside answer then scans the array for NaN (`Check.nan`). libGDX crosses in float with a division, and answers a quarter of points within a relative 1e-6 of an edge wrongly (`docs/peer-exactness.md`); Hitbox none.");
        WHY.put("lineLine.collide", "Four orientation signs, each with Shewchuk's error bound (`Lines.orient`, exact when within rounding of 0), after a NaN check of the eight floats (`Check.nan`). libGDX solves in float with a division and answers 3.5% of nearly touching pairs at screen coordinates wrongly (`docs/peer-exactness.md`); Hitbox none.");
        WHY.put("rayCircle.raw", "A nanosecond or less (1.01x to 1.23x across runs): Hitbox checks that the ray and circle are finite (`Float.isFinite`), solves in double with the stable form of the root (`Discs.entry`) and turns the parameter into a distance with the direction's length; libGDX's 3D ray answers in float (the notes' one answer off by under 0.05 px).");
        WHY.put("rectRect.collide", "Hitbox adds `x + w` in double, so the sum is never rounded, and checks the four sizes' signs for the negative-size rule; libGDX adds and compares in float, and answers 1.8% of nearly touching pairs wrongly at screen coordinates and 2.2% at world coordinates (`docs/peer-exactness.md`); Hitbox none. At about 2 ns a case the widening to double is the difference.");
        WHY.put("circleCircle.collide", "A filter, as Shewchuk's predicates work: the squares in float decide outside a band of 2^-18 (wider than their rounding), and the pairs inside it, with the radii's signs and the NaN rule, go to the comparison in double with its own band (`Discs.centresCloser`, exact in BigDecimal inside that). The band test is the difference from libGDX's bare float squares, which answer 1.7% of nearly touching pairs wrongly at screen coordinates (`docs/peer-exactness.md`); Hitbox none. `FilterFormsBench` has the forms side by side ([benchmarks.md](benchmarks.md#filtered-predicates-what-exactness-costs-on-the-small-tests)).");
        WHY.put("circlePoint.collide", "`Collide.circleCircle` with a radius of 0, so the same filter: float squares outside a band, exact inside it. libGDX's float square answers 1.1% of points within a relative 1e-6 of the outline wrongly at screen coordinates (`docs/peer-exactness.md`); Hitbox none.");
        WHY.put("rectPoint.collide", "Within half a nanosecond: Hitbox adds `x + w` in double for the open rectangle; libGDX adds in float and counts the outline as inside (the notes' touching cases), and answers 1.8% of nearly touching points wrongly (`docs/peer-exactness.md`); Hitbox none.");
        WHY.put("circleRect.collide", "The closest point is clamped in double (by comparisons that pass NaN on: `Math.max` and `Math.min` cost this row 3x in mispredicted branches), after the signs of the radius and sizes are checked, and a centre on the outline is settled by the touching rule; libGDX clamps with float branches and answers 0.8% of nearly touching pairs wrongly at screen coordinates, 1.6% at world coordinates (`docs/peer-exactness.md`); Hitbox none.");
        WHY.put("lineRect.collide", "The box test, then the rectangle's four corners' orientations against the segment, each exact within rounding (`Lines.orient`), after a NaN check (`Check.nan`); libGDX tests the rectangle's edges in float and counts touching as a hit (the notes' 47 cases).");
        WHY.put("trianglePoint.collide", "Up to three exact orientation signs (`Lines.orient` with its error bound); libGDX's float cross products answer some points within a relative 1e-6 of an edge wrongly (86 of 200,000 at screen coordinates, `docs/peer-exactness.md`); Hitbox none.");
        WHY.put("ellipsePoint.shape", "`Ellipse.contains` asks whether the ellipse is turned (`TurnedEllipses.aligned`), then the side of the ellipse in double with an error bound (`Ellipses.side`: exact within rounding, by error-free products or BigDecimal); libGDX divides in float and answers 1.5% of points within a relative 1e-6 of the outline wrongly at screen coordinates (`docs/peer-exactness.md`); Hitbox none.");
        WHY.put("capsulePoint.shape", "`Capsule.contains`: the distance to the segment is compared with the radius exactly within rounding (`Lines.signOfProductDifference`) after a NaN check (`Check.nan`); dyn4j compares in double without a bound and answers 84 of 200,000 nearly touching points wrongly at screen coordinates (`docs/peer-exactness.md`); Hitbox none.");
        WHY.put("circleCircleContact.raw", "The normal is made unit length with `Math.hypot` (`FdLibm.Hypot` in the profile) where a plain square root would do (the squares of two floats' difference cannot overflow a double), and the answer is a checked `Contact` (`Check.held`, `Float.isFinite`); dyn4j's SAT divides by a square root. Changing `hypot` moves some normals by a last bit, so it waits for a change that re-checks every contact oracle.");
        WHY.put("rayPoly8.cast", "One pass of Cyrus-Beck clipping over the polygon's cached corners, with each crossing kept as an exact fraction and an orientation within rounding of 0 recomputed exactly, then a second pass for the hit edge's normal, and a checked `RayHit` (`Ray.hitAt`, `Math.hypot`); JBox2D clips in float against normals it stores with the shape.");
        WHY.put("turnTwoPoly8.turning", "Conservative advancement, as dyn4j's: each step places both movers' vertices at time t in the thread's arrays (`TurningSweep.at`) and bounds the gap from below over their edge normals and a ring of directions (`TurningSweep.vertexToEdges`); runs measured 0.55x to 1.25x of dyn4j, whose time varies as much.");
        WHY.put("rayRect.raw", "The slab test in double (`Slabs.boxTime`, `Slabs.firstTime`: entry and exit on each axis, NaN kept out) and the distance along the direction's length; libGDX's 3D ray works in float and counts a touching ray as a hit (the notes). Runs measured 0.7x to 1.3x.");
        WHY.put("lineCircle.collide", "The segment's nearest point decided exactly: the ends through `Collide.circleCircle`'s test, the inside of the segment by an exact sign of a product difference (`Lines.signOfProductDifference`), after a NaN check of the seven floats (`Check.nan`); libGDX projects in float. Runs measured 1.0x to 1.3x.");
        WHY.put("sweepRectRect.raw", "The exact entry (`Earliest`) and the search over the float positions (`SweptPairs.Search`) are the thread's own, reset per call, so a call makes only its answer; the time is 0.07x of JBox2D's.");
        WHY.put("sweepRectRect.shape", "As the raw call, through `Sweep.timeOfImpact`.");
        WHY.put("sweepCircleCircle.raw", "The exact entry, the entry of the obstacle grown by the rounding (`Earliest`, two) and the overlap test handed to the look-back over float positions are the thread's own, reset per call; the look-back, which keeps an overlap that rounding starts early or splits from being walked over, is most of the time (still under half of JBox2D's).");
        WHY.put("sweepCircleCircle.shape", "As the raw call, through `Sweep.timeOfImpact`.");
        WHY.put("sweepCircleRect.raw", "As for two circles: the exact and the grown entries and the look-back's overlap test are the thread's own, and the look-back is most of the time (about a third of JBox2D's).");
        WHY.put("sweepCircleRect.shape", "As the raw call, through `Sweep.timeOfImpact`.");
        WHY.put("containCircle.shape", "The squared distance of the centres against the squared difference of the radii, in double with an error band; touching from inside, common here, is settled by error-free products and sums (`Containment.discWithin`); libGDX squares in float. `Circle.contains(Shape)` goes through `Containment`'s switch over the kinds, which hands the disc on as the thread's own small object (`Containment.Disc`).");
        WHY.put("star16Point.shape", "`Polygon.contains` is the same crossing count as the raw call over the polygon's cached corners; the route (the polygon's bounds first, then `Polygons.contains`) and the object loads are the difference on a 40 ns test.");
        WHY.put("rectRect.shape", "`Rect.overlaps` reads both rectangles' four fields and routes through the kind check before the same `Collide.rectRect` (80% of the profile): about a nanosecond on a 3.5 ns test.");
        WHY.put("lineRect.shape", "`Segment.overlaps(Rect)` routes through `Overlaps`' switch to the same `Collide.lineRect`; the kind check and the loads are the difference, a nanosecond or two on a 10 ns test.");
        WHY.put("trianglePoint.shape", "`Polygon.contains` on a triangle is the general crossing count with the polygon's bounds first, where the raw call is three orientations: a little more work on a 7 ns test.");
        WHY.put("sweepPoly8.shape", "The entry is an exact Cyrus-Beck cast against the two polygons' Minkowski difference, then the float search for the promised t probes moved positions with the exact convex overlap test (`Polygons.edgeSeparates`). Then the look-back: rounding each vertex on its own can split the float overlap and put a piece of it before the exact entry (far from the origin, pinned in `ConvexSweepTest` and `SweepFarFromOriginTest`), so the float positions from the entry of the obstacle pushed out by the rounding up to t are certified clear in runs along the hit normal, walking only the near corners' coordinates, and tested exactly where the certificate fails (`ConvexPolygonSweep.firstOverlap`). dyn4j's conservative advancement stops within its epsilon and promises nothing of the float positions.");
        WHY.put("ellipseCapsule.shape", "Two bytes a call on average: the rare cases that need the distance from the ellipse to the capsule's segment (`Ellipses.segmentDistance`) make a two-element scratch array; the usual cases allocate nothing.");
        WHY.put("lineLine.shape", "`Segment.overlaps` inlines to the same `Lines.segmentsMeet` as the raw call (the two profiles show the same lines); the difference is the object loads and the route through `Overlaps.segmentWith`, a nanosecond or two on a 9 ns test.");
        WHY.put("circleCircle.shape", "The route (`Circle.overlaps` to `Overlaps.circleWith`, a type check, four field loads) costs about a nanosecond, which on a 2 ns test is the whole ratio; runs of this question alone measured 1.16x to 1.84x, so it sits at the noise of a short run.");
        WHY.put("circleRect.shape", "The route (`Circle.overlaps` to `Overlaps.circleWith`: a type check and the objects' fields) costs a nanosecond or two on a 4 ns test; runs of this question alone measured 1.5x to 1.8x, and the two profiles show the same lines of `Collide.circleRect`.");
    }

    /** The written reason for a missed call, or a note that there is none yet. */
    static String why(String id) {
        return WHY.getOrDefault(id, "No reason written yet for this miss: read the profile below.");
    }

    private static final int TOP = 5;
    private static final double MIN_PERCENT = 3;

    /** Profiles every id (cpu for all, allocations too for those in {@code alloc}); written to {@code out}. */
    static Map<String, List<Profile>> run(Collection<String> cpu, Collection<String> alloc, Path out)
            throws IOException, RunnerException {
        Path lib = library();
        Map<String, List<Profile>> profiles = new LinkedHashMap<>();
        if (lib == null) {
            System.out.println("narrow-phase profiles: no async-profiler library for this platform; skipped");
            return profiles;
        }
        Path dir = Path.of("build/narrow-phase-profiles");
        Files.createDirectories(dir);
        for (String id : cpu) profileOne(id, "cpu", lib, dir, profiles);
        for (String id : alloc) profileOne(id, "alloc", lib, dir, profiles);
        write(profiles, out);
        return profiles;
    }

    /** Runs one call alone under the profiler, for one event, and adds its profile. */
    private static void profileOne(String id, String event, Path lib, Path dir, Map<String, List<Profile>> profiles)
            throws IOException, RunnerException {
        Path file = dir.resolve(id + "." + event + ".jfr").toAbsolutePath();
        Files.deleteIfExists(file);
        String agent = "-agentpath:" + lib + "=start,event=" + (event.equals("cpu") ? "itimer,interval=100us" : "alloc")
                + ",jfr,file=" + file;
        Runner runner = new Runner(new OptionsBuilder()
                .include(NarrowPhaseBench.class.getName() + ".answerEveryCase")
                .param("contender", id)
                .forks(1)
                .warmupIterations(1).warmupTime(TimeValue.seconds(1))
                .measurementIterations(1).measurementTime(TimeValue.seconds(5))
                .jvmArgsAppend("-XX:+UnlockDiagnosticVMOptions", "-XX:+DebugNonSafepoints", agent)
                .build());
        for (int attempt = 1; ; attempt++) {
            try {
                runner.run();
                break;
            } catch (RunnerException e) {
                // most often another JMH run holding JMH's lock between two of ours: wait for it
                if (attempt == 20) throw e;
                System.out.println("narrow-phase profile of " + id + ": " + e.getMessage() + "; trying again in 30 s");
                try {
                    Thread.sleep(30_000);
                } catch (InterruptedException stop) {
                    Thread.currentThread().interrupt();
                    throw e;
                }
            }
        }
        if (Files.exists(file)) {
            profiles.computeIfAbsent(id, k -> new ArrayList<>()).add(read(id, event, file));
        }
    }

    /** Copies the profiler's library out of its jar into build/, where the forked JVMs can load it. */
    private static Path library() throws IOException {
        String os = System.getProperty("os.name").toLowerCase(Locale.ROOT);
        String arch = System.getProperty("os.arch");
        if (!os.contains("linux")) return null;
        String name = (arch.equals("aarch64") ? "linux-arm64" : "linux-x64") + "/libasyncProfiler.so";
        try (InputStream in = NarrowProfiles.class.getClassLoader().getResourceAsStream(name)) {
            if (in == null) return null;
            Path lib = Path.of("build/async-profiler/libasyncProfiler.so").toAbsolutePath();
            Files.createDirectories(lib.getParent());
            Files.copy(in, lib, StandardCopyOption.REPLACE_EXISTING);
            return lib;
        }
    }

    /**
     * The top lines of a recording, counting only samples in the benchmark's loop. For cpu the
     * top frame is the line running; for allocations it is the line allocating, and the class
     * it makes is named beside it, weighted by the sample's size.
     */
    static Profile read(String id, String event, Path jfr) throws IOException {
        Map<String, Long> byLine = new HashMap<>();
        long total = 0;
        for (RecordedEvent e : RecordingFile.readAllEvents(jfr)) {
            String type = e.getEventType().getName();
            boolean cpu = type.equals("jdk.ExecutionSample");
            boolean alloc = type.startsWith("jdk.ObjectAllocation");
            RecordedStackTrace stack = e.getStackTrace();
            if (!(cpu || alloc) || stack == null || stack.getFrames().isEmpty() || !inLoop(stack)) continue;
            RecordedFrame top = stack.getFrames().get(0);
            String line = frame(top);
            long weight = 1;
            if (alloc) {
                RecordedClass made = e.getValue("objectClass");
                line += " makes " + (made == null ? "?" : clean(made.getName()));
                weight = e.hasField("tlabSize") && e.getLong("tlabSize") > 0 ? e.getLong("tlabSize")
                        : e.hasField("allocationSize") ? e.getLong("allocationSize") : 1;
            }
            byLine.merge(line, weight, Long::sum);
            total += weight;
        }
        List<Map.Entry<String, Long>> sorted = new ArrayList<>(byLine.entrySet());
        sorted.sort((a, b) -> Long.compare(b.getValue(), a.getValue()));
        List<Line> top = new ArrayList<>();
        for (Map.Entry<String, Long> e : sorted) {
            double percent = 100.0 * e.getValue() / total;
            if (top.size() == TOP || percent < MIN_PERCENT) break;
            top.add(new Line(e.getKey(), percent, source(e.getKey())));
        }
        return new Profile(id, event, total, top);
    }

    private static boolean inLoop(RecordedStackTrace stack) {
        for (RecordedFrame f : stack.getFrames()) {
            if (f.getMethod() != null && f.getMethod().getName().equals("answerEveryCase")
                    && f.getMethod().getType().getName().endsWith("NarrowPhaseBench")) return true;
        }
        return false;
    }

    private static String frame(RecordedFrame f) {
        if (f.getMethod() == null) return "?";
        return clean(f.getMethod().getType().getName()) + "." + f.getMethod().getName() + ":" + f.getLineNumber();
    }

    /** A name as the reader knows it: no package for ours, no lambda's generated suffix. */
    private static String clean(String name) {
        return name.replace('/', '.').replace("hitbox.bench.", "").replace("hitbox.", "").replaceAll("\\$\\$Lambda\\$.*", "\\$\\$Lambda");
    }

    /** The source line a frame "Class.method:line" names, trimmed, if it is one of ours. */
    static String source(String frame) {
        String f = frame.contains(" makes ") ? frame.substring(0, frame.indexOf(" makes ")) : frame;
        int colon = f.lastIndexOf(':');
        if (colon < 0) return "";
        String method = f.substring(0, colon);
        int dot = method.lastIndexOf('.');
        if (dot < 0) return "";
        String cls = method.substring(0, dot);
        if (cls.contains("$")) cls = cls.substring(0, cls.indexOf('$'));
        if (cls.contains(".")) return ""; // not ours (our package prefixes were taken off)
        int number;
        try {
            number = Integer.parseInt(f.substring(colon + 1));
        } catch (NumberFormatException e) {
            return "";
        }
        for (Path p : new Path[] {Path.of("src/main/java/hitbox", cls + ".java"), Path.of("src/jmh/java/hitbox/bench", cls + ".java")}) {
            try {
                List<String> lines = Files.readAllLines(p, StandardCharsets.UTF_8);
                if (number >= 1 && number <= lines.size()) {
                    String text = lines.get(number - 1).trim();
                    return text.length() > 90 ? text.substring(0, 87) + "..." : text;
                }
            } catch (IOException e) {
                // not this source set
            }
        }
        return "";
    }

    // ---------------------------------------------------------------- saved beside the CSV

    static void write(Map<String, List<Profile>> profiles, Path out) throws IOException {
        StringBuilder s = new StringBuilder();
        for (List<Profile> list : profiles.values()) {
            for (Profile p : list) {
                for (Line l : p.top()) {
                    s.append(p.id()).append('\t').append(p.event()).append('\t').append(p.total()).append('\t')
                            .append(l.frame()).append('\t').append(String.format(Locale.ROOT, "%.1f", l.percent())).append('\t')
                            .append(l.source()).append('\n');
                }
            }
        }
        Files.writeString(out, s.toString(), StandardCharsets.UTF_8);
    }

    /** The profiles saved by the last run, to write the text again without profiling. */
    static Map<String, List<Profile>> read(Path saved) throws IOException {
        Map<String, List<Profile>> profiles = new LinkedHashMap<>();
        if (!Files.exists(saved)) return profiles;
        Map<String, Profile> byKey = new LinkedHashMap<>();
        for (String line : Files.readAllLines(saved, StandardCharsets.UTF_8)) {
            String[] f = line.split("\t", -1);
            if (f.length < 6) continue;
            Profile p = byKey.computeIfAbsent(f[0] + " " + f[1], k -> {
                Profile made = new Profile(f[0], f[1], Long.parseLong(f[2]), new ArrayList<>());
                profiles.computeIfAbsent(f[0], id -> new ArrayList<>()).add(made);
                return made;
            });
            p.top().add(new Line(f[3], Double.parseDouble(f[4]), f[5]));
        }
        return profiles;
    }

    /** The profile of one call as a sentence for the table: the hottest lines and their shares. */
    static String describe(List<Profile> list) {
        if (list == null || list.isEmpty()) return "";
        List<String> parts = new ArrayList<>();
        for (Profile p : list) {
            List<String> lines = new ArrayList<>();
            for (Line l : p.top()) {
                lines.add(String.format(Locale.ROOT, "%.0f%% `%s`", l.percent(), l.frame())
                        + (l.source().isEmpty() ? "" : " (`" + l.source().replace("|", "\\|").replace("`", "'") + "`)"));
            }
            parts.add((p.event().equals("cpu") ? "time: " : "bytes: ") + String.join(", ", lines));
        }
        return String.join("; ", parts);
    }
}
