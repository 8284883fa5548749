package hitbox.web;

import org.teavm.jso.JSExport;

/** The browser module's entry: what JavaScript may call. */
public final class HitboxJs {
    private HitboxJs() {
    }

    /**
     * The test vectors' records (Vectors.run).
     *
     * @param seed  the seed
     * @param count how many cases
     * @return the records
     */
    @JSExport
    public static int[] vectors(int seed, int count) {
        return Vectors.run(seed, count);
    }

    /**
     * The exact products' records (Vectors.fmaCases).
     *
     * @param seed  the seed
     * @param count how many triples
     * @return the records
     */
    @JSExport
    public static int[] fmaVectors(int seed, int count) {
        return Vectors.fmaCases(seed, count);
    }
}
