package hitbox.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * The same answers, bit for bit: the test vectors (hitbox.web.Vectors) answered on this JVM and
 * by the WebAssembly build in headless Chromium, compared record by record (floats by their
 * bits, exceptions by kind). A difference names its case. Sines and cosines too: the library
 * calls StrictMath's, and the browser build a port of fdlibm's (Fdlibm), also compared
 * directly on 200,000 angles.
 */
class BrowserVectorsTest {
    static final int SEED = 20261129;
    static final int COUNT = 40_000;
    static final int FMA = 200_000;
    static final int TRIG = 200_000;
    static final int MATH = 270_000;

    @Test
    void vectors_sameOnTheJvmAndInChromium() throws Exception {
        int[] jvm = Vectors.run(SEED, COUNT);
        Map<String, byte[]> got;
        try (Browser browser = Browser.start()) {
            got = browser.run("test/vectors.html?seed=" + SEED + "&count=" + COUNT + "&fma=" + FMA + "&trig=" + TRIG + "&math=" + MATH,
                    List.of("vectors", "fma", "trig", "math", "timing"), Duration.ofSeconds(120));
        }
        int[] web = ints(got.get("vectors"));
        System.out.println("  browser vectors: Chromium ran " + COUNT + " cases in "
                + Math.round(Double.parseDouble(new String(got.get("timing")))) + " ms");
        // First the platform's methods the library calls, then sines and cosines alone.
        int[] mathJvm = Vectors.mathCases(SEED, MATH);
        int[] mathWeb = ints(got.get("math"));
        assertEquals(mathJvm.length, mathWeb.length, "the platform methods' records");
        java.util.Map<String, Integer> methodsDiffering = new java.util.TreeMap<>();
        List<String> firstCalls = new java.util.ArrayList<>();
        for (int at = 0; at < mathJvm.length; at += 7) {
            if (!java.util.Arrays.equals(mathJvm, at, at + 7, mathWeb, at, at + 7)) {
                String op = Vectors.MATH_OPS[mathJvm[at]];
                if (methodsDiffering.merge(op, 1, Integer::sum) <= 3) {
                    firstCalls.add(op + "(" + Double.longBitsToDouble(bits(mathJvm, at + 1)) + ", " + Double.longBitsToDouble(bits(mathJvm, at + 3))
                            + "): JVM " + Double.longBitsToDouble(bits(mathJvm, at + 5)) + ", Chromium " + Double.longBitsToDouble(bits(mathWeb, at + 5)));
                }
            }
        }
        if (!methodsDiffering.isEmpty()) {
            fail("Chromium's platform methods answer otherwise than the JVM's: " + methodsDiffering + "\n  " + String.join("\n  ", firstCalls));
        }
        System.out.println("  browser vectors: " + MATH / Vectors.MATH_OPS.length + " calls of each of " + Vectors.MATH_OPS.length
                + " platform methods alike, bit for bit");
        int[] trigJvm = Vectors.trigCases(SEED, TRIG);
        int[] trigWeb = ints(got.get("trig"));
        int t = firstDifference(trigJvm, trigWeb);
        if (t >= 0) {
            int at = t / 6 * 6;
            double x = Vectors.trigAngle(SEED, t / 6);
            fail("Fdlibm in Chromium differs from StrictMath at angle " + t / 6 + ", " + x + " (" + Double.toHexString(x)
                    + "): the angle, sin, cos on the JVM " + slice(trigJvm, at, at + 6) + ", in Chromium "
                    + slice(trigWeb, at, Math.min(trigWeb.length, at + 6)));
        }
        System.out.println("  browser vectors: " + TRIG + " angles' sines and cosines alike (Fdlibm), bit for bit");
        int[] ends = Vectors.caseEnds(SEED, COUNT);
        boolean[] turned = Vectors.turnedCases(SEED, COUNT);
        List<String> differences = new java.util.ArrayList<>();
        int turnedCases = 0, differing = 0;
        int from = 0;
        for (int c = 0; c < COUNT; c++) {
            int to = ends[c];
            turnedCases += turned[c] ? 1 : 0;
            if (to > web.length || !java.util.Arrays.equals(jvm, from, to, web, from, to)) {
                differing++;
                if (differences.size() < 8) {
                    differences.add(Vectors.describe(SEED, c) + "\n    JVM:      " + slice(jvm, from, to)
                            + "\n    Chromium: " + slice(web, from, Math.min(web.length, to)));
                }
                if (to > web.length) {
                    break;
                }
            }
            from = to;
        }
        if (!differences.isEmpty()) {
            fail("Chromium answers otherwise than the JVM in " + differing + " cases (the first " + differences.size() + "):\n  "
                    + String.join("\n  ", differences));
        }
        assertEquals(jvm.length, web.length, "records");
        // Every case alike, those that reach sine and cosine (turned ellipses, sweeps, world
        // moves) too: the library calls StrictMath's (fdlibm on every JVM), and the browser build
        // a port of fdlibm's (Fdlibm).
        System.out.println("  browser vectors: all " + COUNT + " cases alike bit for bit, the " + turnedCases
                + " that reach sine and cosine among them");
        int[] fmaJvm = Vectors.fmaCases(SEED, FMA);
        int[] fmaWeb = ints(got.get("fma"));
        int f = firstDifference(fmaJvm, fmaWeb);
        if (f >= 0) {
            fail("ExactFma in Chromium differs from Math.fma at triple " + f / 2);
        }
        System.out.println("  browser vectors: " + FMA + " exact products (ExactFma) alike, bit for bit");
    }

    private static long bits(int[] a, int at) {
        return ((long) a[at] << 32) | (a[at + 1] & 0xffffffffL);
    }

    static int[] ints(byte[] bytes) {
        int[] out = new int[bytes.length / 4];
        ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN).asIntBuffer().get(out);
        return out;
    }

    static int firstDifference(int[] a, int[] b) {
        int n = Math.min(a.length, b.length);
        for (int i = 0; i < n; i++) {
            if (a[i] != b[i]) {
                return i;
            }
        }
        return a.length == b.length ? -1 : n;
    }

    private static String slice(int[] a, int from, int to) {
        StringBuilder sb = new StringBuilder("[");
        for (int i = from; i < to; i++) {
            sb.append(i > from ? ", " : "").append(Integer.toHexString(a[i]));
        }
        return sb.append(']').toString();
    }
}
