package hitbox.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Pattern;

import hitbox.bench.NarrowContender.Role;
import hitbox.bench.NarrowQuestions.Question;
import org.openjdk.jmh.profile.GCProfiler;
import org.openjdk.jmh.results.Result;
import org.openjdk.jmh.results.RunResult;
import org.openjdk.jmh.results.format.ResultFormatType;
import org.openjdk.jmh.runner.Runner;
import org.openjdk.jmh.runner.options.CommandLineOptions;
import org.openjdk.jmh.runner.options.Options;
import org.openjdk.jmh.runner.options.OptionsBuilder;

/**
 * Makes the narrow-phase table: checks that every contender agrees with Hitbox on every case
 * (failing before anything is timed if one does not, except where a touching rule or a skin
 * explains it), runs {@link NarrowPhaseBench} for every contender with JMH's GC profiler, and
 * writes {@code docs/narrow-phase.md} (the README links to it, with a one-line summary written by
 * hand). Arguments are JMH's own ({@code -f 1 -wi 2 ...}); {@code -Dnarrow.only=regex}
 * picks questions by id (and then writes {@code build/narrow-phase-some.md} only),
 * {@code -Dnarrow.checkOnly=true} stops after the check, and {@code -Dnarrow.fromCsv=true} writes
 * the text again from the last run's results ({@code build/narrow-phase.csv}) without timing.
 *
 * <p>Run through {@code gradle narrowPhaseTable [-Pjmh.args="..."] [-Pnarrow.only=regex]}.
 */
public final class NarrowPhaseTable {
    /** How far two unit normals may differ, per component. */
    static final double NORMAL_TOLERANCE = 0.01;

    private NarrowPhaseTable() {
    }

    /** How one contender's answers compare with Hitbox's on one question. */
    static final class Agreement {
        int agree, touchingHit, touchingMiss, normalTies, skin, wrong;
        /** Cases it gives up on (NaN: a root finder's FAILED state). */
        int gaveUp;
        /** Contact points: the same points seen on the other shape, another count, other places. */
        int otherFace, otherCount, otherPoints;
        String firstWrong, firstOther;
        /** Answers an independent check ({@link NarrowCase#verdict}) shows wrong, by what is wrong, with the first case. */
        final Map<String, Integer> confirmed = new LinkedHashMap<>();
        final Map<String, String> firstConfirmed = new LinkedHashMap<>();

        final double tolerance;
        final NarrowCase.Kind kind;
        final boolean relative;

        Agreement(double tolerance) {
            this(tolerance, NarrowCase.Kind.OVERLAP, false);
        }

        Agreement(double tolerance, NarrowCase.Kind kind, boolean relative) {
            this.tolerance = tolerance;
            this.kind = kind;
            this.relative = relative;
        }

        String describe(String peer) {
            List<String> parts = new ArrayList<>();
            if (kind == NarrowCase.Kind.CONTAIN) {
                if (touchingHit > 0) parts.add(touchingHit + " touching or grazing cases it counts as held (Hitbox: not held)");
                if (touchingMiss > 0) parts.add(touchingMiss + " cases touching the outline from inside (or grazing) it counts as not held");
            } else if (kind == NarrowCase.Kind.APART) {
                if (touchingHit > 0) parts.add(touchingHit + " touching or grazing cases it gives a distance for (Hitbox: overlapping)");
                if (touchingMiss > 0) parts.add(touchingMiss + " touching or grazing cases it gives no distance for (it says overlapping)");
            } else {
                if (touchingHit > 0) parts.add(touchingHit + " touching or grazing cases it counts as hits");
                if (touchingMiss > 0) parts.add(touchingMiss + " touching or grazing hits it misses");
            }
            String within = relative ? String.format(Locale.ROOT, "%.0e", tolerance).replace("e-0", "e-") + " of the shapes' size" : tolerance + " px";
            if (skin > 0) parts.add(skin + " answers off by under " + within + " (its skin or tolerance)");
            if (normalTies > 0) parts.add(normalTies + " equally deep normals it picks otherwise");
            if (gaveUp > 0) parts.add(gaveUp + " it gives up on (no answer)");
            confirmed.forEach((what, n) -> parts.add(n + " " + what));
            if (otherFace > 0) parts.add(otherFace + " with the points on the other shape (the other face as reference)");
            if (otherCount > 0) parts.add(otherCount + " with another number of points");
            if (otherPoints > 0) parts.add(otherPoints + " with other points");
            if (wrong > 0) parts.add(wrong + " WRONG (first: " + firstWrong + ")");
            return peer + ": " + (parts.isEmpty() ? "agrees on all " + NarrowCase.N : String.join(", ", parts));
        }
    }

    public static void main(String[] args) throws Exception {
        Pattern only = Pattern.compile(System.getProperty("narrow.only", ".*"));
        List<Question> questions = new ArrayList<>();
        for (Question q : NarrowQuestions.all()) {
            if (only.matcher(q.id()).matches()) questions.add(q);
        }
        Map<String, Agreement> agreements = check(questions);
        if (Boolean.getBoolean("narrow.checkOnly")) {
            return;
        }
        // a run of some questions only is written beside the full run's files, never over them
        boolean some = System.getProperty("narrow.only") != null;
        String name = some ? "build/narrow-phase-some" : "build/narrow-phase";
        Path run = Path.of(name + "-run.txt"), csv = Path.of(name + ".csv");
        Map<String, double[]> measured;
        if (Boolean.getBoolean("narrow.fromCsv")) {
            measured = readCsv(csv);
        } else {
            String load = loadAverage();
            measured = measure(questions, args, csv);
            Files.writeString(run, String.join(" ", args) + "\n" + ZonedDateTime.now(ZoneOffset.UTC).format(DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm 'UTC'"))
                    + "\n" + load + ", after the run " + loadAverage() + "\n", StandardCharsets.UTF_8);
        }
        List<String> how = Files.readAllLines(run, StandardCharsets.UTF_8);
        // First the table alone, to learn which calls miss a goal; then those calls profiled, and the table again.
        Misses misses = new Misses();
        table(questions, agreements, measured, how.get(0), how.get(1), how.get(2), Map.of(), misses);
        Path saved = Path.of(name + "-profiles.tsv");
        Map<String, List<NarrowProfiles.Profile>> profiles = Boolean.getBoolean("narrow.fromCsv")
                || !Boolean.parseBoolean(System.getProperty("narrow.profile", "true"))
                ? NarrowProfiles.read(saved) : NarrowProfiles.run(misses.cpu, misses.alloc, saved);
        String text = table(questions, agreements, measured, how.get(0), how.get(1), how.get(2), profiles, new Misses());
        if (some) {
            Files.writeString(Path.of(name + ".md"), text, StandardCharsets.UTF_8);
            System.out.println("wrote " + name + ".md (some questions only: docs/narrow-phase.md left as it is)");
            return;
        }
        Files.writeString(Path.of("docs/narrow-phase.md"), "# Hitbox's narrow phase against the peers\n\n"
                + "Made by `gradle narrowPhaseTable` (src/jmh/java/hitbox/bench/NarrowPhaseTable.java); edit the generator,\n"
                + "not the output. The README's one-line summary of it is written by hand: check it after a new run.\n\n"
                + text.substring(text.indexOf('\n') + 2),
                StandardCharsets.UTF_8);
        System.out.println("wrote docs/narrow-phase.md (check the README's one-line summary of it)");
    }

    // ---------------------------------------------------------------- result objects

    /** Hits per question (cases whose Hitbox answer is a result), from the agreement check. */
    static final Map<String, Integer> HITS = new HashMap<>();

    static final String RESULT_RULE = "a `Contact`, `Hit`, `RayHit`, `Separation` or `Manifold` (with its `Contact`) per hit is the answer itself: hits / 1,024 times its size,"
            + " a 12-byte header and 4 bytes a field rounded up to 8, is not counted against the goal";

    /**
     * The bytes per case that the answers themselves take: for a call that returns a result
     * object ({@code Contact}, {@code Hit}, {@code RayHit}; the table knows them by the call's
     * name), one object per hit, sized as HotSpot lays it out with compressed class pointers;
     * 0 for yes-or-no, distance and float-time calls.
     */
    static double resultBytes(NarrowContender c, Question q) {
        // a Manifold holds its Contact: two objects per hit
        Class<?>[] types = c.call.startsWith("Contact.manifold") ? new Class<?>[] {hitbox.Manifold.class, hitbox.Contact.class}
                : c.call.startsWith("Separation.between") ? new Class<?>[] {hitbox.Separation.class}
                : c.call.startsWith("Contact.") || c.call.contains(".contact") ? new Class<?>[] {hitbox.Contact.class}
                : c.call.startsWith("Ray.cast") ? new Class<?>[] {hitbox.RayHit.class}
                : c.call.contains("Hit") || c.call.contains("timeOfImpact") || c.call.contains("TimeOfImpact") ? new Class<?>[] {hitbox.Hit.class}
                : new Class<?>[0];
        int size = 0;
        for (Class<?> type : types) {
            int fields = 0;
            for (java.lang.reflect.Field f : type.getDeclaredFields()) {
                if (!java.lang.reflect.Modifier.isStatic(f.getModifiers())) fields++;
            }
            size += (12 + 4 * fields + 7) / 8 * 8; // floats, ints and compressed references are 4 bytes
        }
        return (double) HITS.getOrDefault(q.id(), 0) / NarrowCase.N * size;
    }

    // ---------------------------------------------------------------- agreement

    /** Every contender against Hitbox's own call, case by case; exits with an error if any is wrong. */
    static Map<String, Agreement> check(List<Question> questions) {
        Map<String, Agreement> out = new LinkedHashMap<>();
        List<String> failures = new ArrayList<>();
        float[] scratch = new float[3];
        for (Question q : questions) {
            NarrowCase cases = q.cases().get();
            NarrowContender hitbox = q.contenders().get(0);
            hitbox.prepare(cases);
            double[][] truth = new double[NarrowCase.N][];
            int hits = 0;
            for (int i = 0; i < NarrowCase.N; i++) {
                truth[i] = hitbox.answer(i, scratch);
                if (truth[i] != null) hits++;
            }
            System.out.printf(Locale.ROOT, "%-22s %4d hits of %d%n", q.id(), hits, NarrowCase.N);
            HITS.put(q.id(), hits);
            for (NarrowContender c : q.contenders().subList(1, q.contenders().size())) {
                c.prepare(cases);
                Agreement a = new Agreement(q.tolerance(), cases.kind, q.relative());
                for (int i = 0; i < NarrowCase.N; i++) {
                    compare(cases, q, i, truth[i], c.answer(i, scratch), c.role == Role.SHAPE, a);
                }
                out.put(c.id(), a);
                String line = a.describe(c.call);
                System.out.println("    " + line);
                if (a.firstOther != null) System.out.println("      first other points: " + a.firstOther);
                a.firstConfirmed.forEach((what, first) -> System.out.println("      first " + what + ": " + first));
                if (a.wrong > 0) failures.add(q.id() + ": " + line);
            }
        }
        if (!failures.isEmpty()) {
            throw new IllegalStateException("contenders disagree with Hitbox:\n" + String.join("\n", failures));
        }
        return out;
    }

    private static void compare(NarrowCase cases, Question q, int i, double[] want, double[] got, boolean exact, Agreement a) {
        if (want == null && got == null) {
            a.agree++;
            return;
        }
        if (got != null && Double.isNaN(got[0])) {
            a.gaveUp++;
            return;
        }
        boolean edge = !exact && cases.borderline(i, q.step());
        if (want == null || got == null) {
            if (!edge) {
                disagree(cases, q, i, want, got, exact, a);
            } else if (got != null) {
                a.touchingHit++;
            } else {
                a.touchingMiss++;
            }
            return;
        }
        // both hit: a distance, a time or a depth, in pixels
        double tolerance = exact ? 1e-4 : q.relative() ? q.tolerance() * cases.size(i) : q.tolerance();
        double off = Math.abs(want[0] - got[0]) * cases.scale(i);
        if (off > tolerance && !edge) {
            disagree(cases, q, i, want, got, exact, a);
        } else if (off > 1e-4) {
            a.skin++;
        } else if (want.length >= 3 && (Math.abs(want[1] - got[1]) > NORMAL_TOLERANCE || Math.abs(want[2] - got[2]) > NORMAL_TOLERANCE)) {
            if (exact) wrong(a, cases, i, want, got); else a.normalTies++;
        } else if (want.length == NarrowContender.POINTS) {
            comparePoints(cases, i, want, got, tolerance, exact, a);
        } else {
            a.agree++;
        }
    }

    /**
     * Contact points, once the depth and normal agree: the points deeper than the tolerance
     * (a peer's skin keeps points just in front of the face) are matched, in either order, each
     * to within the tolerance in place and depth. Points that differ only along the normal, by
     * at most the depth, are the same contact seen on the other shape (the other face taken as
     * reference, which the manifold's convention, not the geometry, decides); another count or
     * other places are reported, not failed: they are conventions of the clipping too.
     */
    private static void comparePoints(NarrowCase cases, int i, double[] want, double[] got, double tolerance, boolean exact,
                                      Agreement a) {
        List<double[]> w = deepPoints(want, tolerance), g = deepPoints(got, tolerance);
        boolean shallow = w.size() != (int) want[3] || g.size() != (int) got[3];
        String category;
        if (w.size() != g.size()) {
            category = "count";
        } else if (matches(w, g, tolerance, 0, want)) {
            category = shallow ? "skin" : "agree";
        } else if (matches(w, g, tolerance, want[0], want)) {
            category = "face";
        } else {
            category = "points";
        }
        if (exact && !category.equals("agree")) {
            wrong(a, cases, i, want, got);
            return;
        }
        switch (category) {
            case "agree" -> a.agree++;
            case "skin" -> a.skin++;
            case "face" -> a.otherFace++;
            default -> {
                if (cases.pointOutside(i, got, tolerance) && !cases.pointOutside(i, want, tolerance)) {
                    // Box2D and dyn4j clip the incident edge to the reference face's side lines only
                    String what = (category.equals("count") ? "with another number of points" : "with other points")
                            + ", one outside a shape (clipped to the reference face's side lines only; Hitbox's lie in both shapes)";
                    a.confirmed.merge(what, 1, Integer::sum);
                    a.firstConfirmed.putIfAbsent(what, "case " + i + " " + cases.a[i] + " " + cases.b[i] + " Hitbox "
                            + java.util.Arrays.toString(want) + ", it " + java.util.Arrays.toString(got));
                    return;
                }
                if (category.equals("count")) a.otherCount++; else a.otherPoints++;
                if (a.firstOther == null) {
                    a.firstOther = "case " + i + " " + cases.a[i] + " " + cases.b[i] + " Hitbox " + java.util.Arrays.toString(want)
                            + ", it " + java.util.Arrays.toString(got);
                }
            }
        }
    }

    /** The answer's points (x, y, depth) deeper than the tolerance. */
    private static List<double[]> deepPoints(double[] m, double tolerance) {
        List<double[]> out = new ArrayList<>();
        for (int k = 0; k < (int) m[3]; k++) {
            if (m[6 + 3 * k] > tolerance) out.add(new double[] {m[4 + 3 * k], m[5 + 3 * k], m[6 + 3 * k]});
        }
        return out;
    }

    /**
     * Do the points pair up, in some order, each within the tolerance across the normal and
     * in depth, and within the tolerance plus {@code along} along the normal?
     */
    private static boolean matches(List<double[]> w, List<double[]> g, double tolerance, double along, double[] want) {
        double nx = want[1], ny = want[2];
        for (int shift = 0; shift < Math.max(1, w.size()); shift++) {
            boolean all = true;
            for (int k = 0; k < w.size() && all; k++) {
                double[] p = w.get(k), r = g.get((k + shift) % g.size());
                double dx = p[0] - r[0], dy = p[1] - r[1];
                double normal = Math.abs(dx * nx + dy * ny), across = Math.abs(dx * ny - dy * nx);
                all = across <= tolerance && normal <= along + tolerance && (along > 0 || Math.abs(p[2] - r[2]) <= tolerance);
            }
            if (all) return true;
        }
        return false;
    }

    /**
     * A difference no touching rule, skin or tolerance explains: the peer's answer is counted
     * apart, with what is wrong, only where an independent check of the case
     * ({@link NarrowCase#verdict}) shows Hitbox right and the peer wrong; otherwise it is wrong
     * and fails the run.
     */
    private static void disagree(NarrowCase cases, Question q, int i, double[] want, double[] got, boolean exact, Agreement a) {
        String what = exact ? null : cases.verdict(i, want, got, q.tolerance());
        if (what == null) {
            wrong(a, cases, i, want, got);
            return;
        }
        if (what.equals(NarrowCase.WITHIN_TOLERANCE)) {
            a.skin++;
            return;
        }
        a.confirmed.merge(what, 1, Integer::sum);
        a.firstConfirmed.putIfAbsent(what, "case " + i + " " + cases.a[i] + " " + cases.b[i]
                + (cases.v[i] == null ? "" : " v=" + java.util.Arrays.toString(cases.v[i]))
                + " Hitbox " + java.util.Arrays.toString(want) + ", it " + java.util.Arrays.toString(got));
    }

    private static void wrong(Agreement a, NarrowCase cases, int i, double[] want, double[] got) {
        if (a.wrong++ == 0) {
            a.firstWrong = "case " + i + " " + cases.a[i] + " " + cases.b[i]
                    + (cases.v[i] == null ? "" : " v=" + java.util.Arrays.toString(cases.v[i]))
                    + " Hitbox " + java.util.Arrays.toString(want) + ", it " + java.util.Arrays.toString(got);
        }
    }

    // ---------------------------------------------------------------- timing

    /** ns per case and bytes per case for every contender, by id. */
    static Map<String, double[]> measure(List<Question> questions, String[] args, Path csv) throws Exception {
        List<String> ids = new ArrayList<>();
        for (Question q : questions) {
            for (NarrowContender c : q.contenders()) ids.add(c.id());
        }
        Options options = new OptionsBuilder()
                .parent(new CommandLineOptions(args))
                .include(NarrowPhaseBench.class.getName() + ".answerEveryCase")
                .param("contender", ids.toArray(new String[0]))
                .addProfiler(GCProfiler.class)
                .resultFormat(ResultFormatType.CSV)
                .result(csv.toString())
                .build();
        Collection<RunResult> results = new Runner(options).run();
        Map<String, double[]> out = new HashMap<>();
        for (RunResult r : results) {
            String id = r.getParams().getParam("contender");
            @SuppressWarnings("rawtypes")
            Result alloc = r.getSecondaryResults().get("gc.alloc.rate.norm");
            // both per case: JMH counts OperationsPerInvocation operations for the time and the allocation alike
            out.put(id, new double[] {r.getPrimaryResult().getScore(), alloc == null ? Double.NaN : alloc.getScore()});
        }
        return out;
    }

    /** The table from a run's CSV, to rewrite the text without timing again. */
    static Map<String, double[]> readCsv(Path csv) throws IOException {
        Map<String, double[]> out = new HashMap<>();
        for (String line : Files.readAllLines(csv, StandardCharsets.UTF_8)) {
            String[] f = line.split(",");
            if (f.length < 8 || f[0].startsWith("\"Benchmark")) continue;
            double[] m = out.computeIfAbsent(f[7].trim(), k -> new double[] {Double.NaN, Double.NaN});
            if (f[0].endsWith("answerEveryCase\"")) m[0] = Double.parseDouble(f[4]);
            if (f[0].endsWith(":gc.alloc.rate.norm\"")) m[1] = Double.parseDouble(f[4]);
        }
        return out;
    }

    private static String loadAverage() {
        try {
            String[] f = Files.readString(Path.of("/proc/loadavg")).trim().split("\\s+");
            return "load average " + f[0] + ", " + f[1] + ", " + f[2];
        } catch (IOException | RuntimeException e) {
            return "load average unknown";
        }
    }

    // ---------------------------------------------------------------- the table

    /** The Hitbox calls that miss a goal: to profile for time, and for bytes. */
    static final class Misses {
        final java.util.Set<String> cpu = new java.util.LinkedHashSet<>(), alloc = new java.util.LinkedHashSet<>();
        /** Each missed call's line in the "where the time goes" list, in table order. */
        final Map<String, String> rows = new LinkedHashMap<>();
    }

    static String table(List<Question> questions, Map<String, Agreement> agreements, Map<String, double[]> measured,
                        String jmhArgs, String when, String load, Map<String, List<NarrowProfiles.Profile>> profiles,
                        Misses misses) {
        StringBuilder s = new StringBuilder();
        s.append("### One shape against another: the narrow phase against the peers\n\n");
        s.append("Each question is 1,024 random cases (whole and half-pixel coordinates, so some pairs touch exactly; the two\n");
        s.append("boxes of a pair overlap or touch, as after a broad phase, except that where a miss needs apart boxes (two\n");
        s.append("rectangles, a point in a rectangle) at most 64 pairs touch and the other misses lie anywhere; half the cases\n");
        s.append("hit). Every contender gets the same cases in its own types, made before timing, and answers all of them\n");
        s.append("in one loop; its answers are checked against Hitbox's, case by case, before anything is timed. The peers are\n");
        s.append("dyn4j 6.0.0, libGDX 1.14.2, JTS 1.20 and JBox2D 2.2.1.1 (benchmark-only dependencies); for each question the\n");
        s.append("table shows the fastest of those measured. Made by `gradle narrowPhaseTable` (JMH `").append(jmhArgs.trim())
                .append("`, with `-prof gc`)\n");
        s.append("on ").append(when)
                .append(", on ").append(Runtime.getRuntime().availableProcessors())
                .append(" cores shared with other builds (").append(load).append("): a short run on a busy machine, so read\n");
        s.append("the ratios, measured in the same run, rather than the nanoseconds. B/call is JMH's `gc.alloc.rate.norm`, bytes per case.\n\n");

        List<String> slower = new ArrayList<>(), shapeSlow = new ArrayList<>(), allocating = new ArrayList<>();
        int peerRows = 0, shapeRows = 0, allocRows = 0;
        s.append("| question | Hitbox call | Hitbox ns/case | B/call | fastest peer (call) | peer ns/case | Hitbox/peer | notes (agreement) |\n");
        s.append("| --- | --- | ---: | ---: | --- | ---: | ---: | --- |\n");
        for (Question q : questions) {
            NarrowContender hitbox = q.contenders().get(0);
            double[] h = measured.getOrDefault(hitbox.id(), new double[] {Double.NaN, Double.NaN});
            NarrowContender best = null;
            List<String> notes = new ArrayList<>();
            for (NarrowContender c : q.contenders()) {
                if (c.role != Role.PEER) continue;
                Agreement a = agreements.get(c.id());
                if (a != null) notes.add(a.describe(c.call));
                double[] m = measured.get(c.id());
                if (m != null && (best == null || m[0] < measured.get(best.id())[0])) best = c;
            }
            String peerNs = "", ratio = "", peerCall = "no peer";
            if (best != null) {
                double p = measured.get(best.id())[0];
                peerCall = best.call;
                peerNs = ns(p);
                ratio = String.format(Locale.ROOT, "%.2fx", h[0] / p);
                peerRows++;
                if (!(h[0] <= p)) {
                    slower.add(q.title() + " (" + ratio + ")");
                    misses.cpu.add(hitbox.id());
                    misses.rows.merge(hitbox.id(), q.title() + ", `" + hitbox.call + "`: " + ratio + " the fastest peer's time",
                            (x, y) -> x + "; " + y);
                }
            }
            for (NarrowContender c : q.contenders()) {
                if (c.role == Role.PEER) continue;
                double[] m = measured.get(c.id());
                allocRows++;
                // The rule: an object per result is fine where a result exists, nothing else.
                double beyond = m == null ? Double.NaN : m[1] - resultBytes(c, q);
                if (!(beyond < 0.5)) {
                    allocating.add("`" + c.call + "` (" + (m == null ? "?" : bytes(m[1]) + " B, " + bytes(beyond) + " beyond its results") + ")");
                    misses.alloc.add(c.id());
                    misses.rows.merge(c.id(), q.title() + ", `" + c.call + "`: " + bytes(beyond) + " B a call beyond its results",
                            (x, y) -> x + "; " + y);
                }
            }
            s.append("| ").append(q.title()).append(" | `").append(hitbox.call).append("` | ").append(ns(h[0])).append(" | ")
                    .append(bytes(h[1])).append(" | ").append(best == null ? peerCall : "`" + peerCall + "`").append(" | ")
                    .append(peerNs).append(" | ").append(ratio).append(" | ").append(String.join("; ", notes)).append(" |\n");
        }

        s.append("\n**Through `Shape` against the raw call**, same cases, same run (the goal below is for the yes-or-no rows;\n");
        s.append("`Ray.cast`, `Sweep.timeOfImpact` and `Shape.contact` are shown beside their raw calls):\n\n");
        s.append("| question | raw call | raw ns/case | shape call | shape ns/case | B/call | shape/raw |\n");
        s.append("| --- | --- | ---: | --- | ---: | ---: | ---: |\n");
        for (Question q : questions) {
            NarrowContender raw = q.contenders().get(0);
            for (NarrowContender c : q.contenders()) {
                if (c.role != Role.SHAPE) continue;
                double[] r = measured.getOrDefault(raw.id(), new double[] {Double.NaN, Double.NaN});
                double[] m = measured.getOrDefault(c.id(), new double[] {Double.NaN, Double.NaN});
                String ratio = String.format(Locale.ROOT, "%.2fx", m[0] / r[0]);
                // the goal is Shape.overlaps and contains against Collide; rays, sweeps and contacts are shown beside it
                if (c instanceof NarrowContender.Bool) {
                    shapeRows++;
                    if (!(m[0] <= 1.25 * r[0])) {
                        shapeSlow.add(q.title() + " `" + c.call + "` (" + ratio + ")");
                        misses.cpu.add(c.id());
                        misses.cpu.add(raw.id()); // the raw call's profile beside it shows what the Shape route adds
                        misses.rows.merge(c.id(), q.title() + ", `" + c.call + "`: " + ratio + " the raw call's time",
                                (x, y) -> x + "; " + y);
                    }
                }
                s.append("| ").append(q.title()).append(" | `").append(raw.call).append("` | ").append(ns(r[0])).append(" | `")
                        .append(c.call).append("` | ").append(ns(m[0])).append(" | ").append(bytes(m[1])).append(" | ")
                        .append(ratio).append(" |\n");
            }
        }

        s.append("\n**Goals, in this run:**\n\n");
        s.append(goal("every Hitbox call at or below the fastest peer", peerRows, slower));
        s.append(goal("`Shape.overlaps` (and `contains`) within 1.25x of the raw `Collide` call", shapeRows, shapeSlow));
        s.append(goal("0 bytes per call for every Hitbox answer (yes/no, distance, time of impact, Contact), beyond one result object\n"
                + "  where a result exists (" + RESULT_RULE + ")", allocRows, allocating));

        s.append("\nReading the rows: the swept 8-gon row is `Sweep.timeOfImpact`'s straight sweep by convex pieces (the turning\n");
        s.append("sweep is measured against dyn4j in `ShapesBench`). libGDX's rays are 3D (z = 0). JBox2D stops a time of impact within\n");
        s.append("its skin (polygons carry a 0.01 radius) and a float root finder's tolerance, dyn4j within its distance epsilon,\n");
        s.append("so their times are compared to 0.25 px of motion and their hit or miss exactly. \"Touching or grazing\" means\n");
        s.append("Hitbox's answer changes when the second shape moves 0.02 px (0.05 px for sweeps): the peer's touching rule\n");
        s.append("(closed shapes, a contact of depth 0) or its skin, not a wrong answer; any other difference fails the run.\n");
        s.append("The separation rows' cases are all apart or touching (every case has an answer; in a quarter of those placed by\n");
        s.append("hand the shapes touch exactly, distance 0): a distance agrees to 1e-4 of the case's size (its largest coordinate;\n");
        s.append("JBox2D works in float), and JTS, which has no circle, measures to the centre and the radius is taken off.\n");
        s.append("The containment rows hold a shape touching the outline from inside (Hitbox's rule, and JTS's `covers`);\n");
        s.append("libGDX's `Rectangle.contains(Rectangle)` and dyn4j's `Sat.contains` (strictly inside every projection) do not,\n");
        s.append("and dyn4j's circle in circle compares the circles' extents along x only (its wrong answers are checked exactly).\n");
        s.append("The manifold rows compare the depth and normal as the contact rows do, then the points deeper than 0.05 px,\n");
        s.append("in either order, to 0.05 px in place and depth: JBox2D keeps the first polygon's face unless the other's is 2%\n");
        s.append("less deep, and its search for the face can stop at a local best (both checked against the least depth by\n");
        s.append("separating axes in double); JBox2D and dyn4j clip the incident edge to the reference face's side lines only,\n");
        s.append("where Hitbox keeps each point in both shapes (checked by JTS distance). Such differences, another count of\n");
        s.append("points, and the same points seen on the other shape are counted in the notes, not failed. The two-movers row\n");
        s.append("turns both 8-gons about their centroids; a time is compared to 0.25 px of the fastest any point of one gains\n");
        s.append("on the other, and where a peer stops earlier than that the gap it leaves is measured instead; where a peer\n");
        s.append("misses a hit, the motion is sampled 4,000 times, each body placed in double and JTS asked whether they overlap.\n");
        s.append("\"WRONG (checked ...)\" marks a peer's answer that such a check shows wrong and Hitbox's right; it is reported,\n");
        s.append("not failed. A `Manifold` per hit holds its `Contact`: two result objects.\n");
        s.append("The pixel masks and `Hybrid` have no peer. Every contender answers case i through a lambda over its own\n");
        s.append("arrays, in a JVM of its own (one JMH fork each), so the call is inlined as a direct call would be.\n");
        s.append(whereTheTimeGoes(misses, profiles));
        s.append("\n<details><summary>Every contender measured</summary>\n\n");
        s.append("| question | contender | ns/case | B/call |\n| --- | --- | ---: | ---: |\n");
        for (Question q : questions) {
            for (NarrowContender c : q.contenders()) {
                double[] m = measured.getOrDefault(c.id(), new double[] {Double.NaN, Double.NaN});
                s.append("| ").append(q.title()).append(" | `").append(c.call).append("` | ").append(ns(m[0])).append(" | ")
                        .append(bytes(m[1])).append(" |\n");
            }
        }
        s.append("\n</details>\n");
        return s.toString();
    }

    /** Every missed call with its reason and the profile that shows where its time or bytes go. */
    private static String whereTheTimeGoes(Misses misses, Map<String, List<NarrowProfiles.Profile>> profiles) {
        if (misses.rows.isEmpty()) return "";
        StringBuilder s = new StringBuilder();
        s.append("\n**Where the missed rows' time goes.** Each call that misses a goal was run again alone under async-profiler\n");
        s.append("(").append(NarrowProfiles.HOW).append("). For each: why it misses, then the hottest source lines of its own samples\n");
        s.append("(the `NarrowContender` lines are the benchmark's loop, reading the case, common to every contender).\n");
        s.append("Where a peer is faster on a small test it mostly computes in float: `gradle peerExactness` counts how often\n");
        s.append("such a peer answers nearly touching shapes wrongly, against exact arithmetic, and checks Hitbox answers none\n");
        s.append("wrongly (`docs/peer-exactness.md`). That exactness, and the checks behind the NaN and negative-size rules,\n");
        s.append("are what the small rows pay for. What a floating-point filter saves of it is measured apart, every form on the\n");
        s.append("same arrays (`FilterFormsBench`, [benchmarks.md](benchmarks.md#filtered-predicates-what-exactness-costs-on-the-small-tests)).\n\n");
        for (Map.Entry<String, String> row : misses.rows.entrySet()) {
            String id = row.getKey();
            s.append("- ").append(row.getValue()).append(". ").append(NarrowProfiles.why(id)).append('\n');
            String profile = NarrowProfiles.describe(profiles.get(id));
            if (!profile.isEmpty()) s.append("  - ").append(profile).append('\n');
            String raw = id.replaceAll("\\.[^.]*$", ".collide");
            if (!raw.equals(id) && misses.cpu.contains(raw) && profiles.containsKey(raw) && id.endsWith(".shape")) {
                s.append("  - the raw call, for comparison: ").append(NarrowProfiles.describe(profiles.get(raw))).append('\n');
            }
        }
        return s.toString();
    }

    private static String goal(String what, int rows, List<String> missed) {
        if (missed.isEmpty()) {
            return "- " + what + ": **met** (" + rows + " of " + rows + ").\n";
        }
        return "- " + what + ": **missed** in " + missed.size() + " of " + rows + ": " + String.join(", ", missed) + ".\n";
    }

    private static String ns(double v) {
        return Double.isNaN(v) ? "-" : v >= 100 ? String.format(Locale.ROOT, "%.0f", v) : String.format(Locale.ROOT, "%.1f", v);
    }

    private static String bytes(double v) {
        return Double.isNaN(v) ? "-" : String.format(Locale.ROOT, "%.0f", Math.max(0, v));
    }
}
