package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The exact helpers in Lines: the sign of a product difference must never round the wrong way. */
class LinesTest {

    private static int exactSign(double a, double b, double c, double d) {
        return new BigDecimal(a).multiply(new BigDecimal(b)).subtract(new BigDecimal(c).multiply(new BigDecimal(d))).signum();
    }

    @ParameterizedTest(name = "{0}*{1} - {2}*{3}")
    @CsvSource({
            "3, 4, 2, 6, 0",
            "3, 4, 2, 5, 1",
            "3, 4, 2, 7, -1",
            // (2^27 + 1)^2 = 2^54 + 2^28 + 1 rounds to 2^54 + 2^28 = (2^27 + 2) * 2^27
            "134217729, 134217729, 134217730, 134217728, 1",
            "134217729, 134217729, 134217729, 134217729, 0",
            // (2^27 + 1)(2^27 - 1) = 2^54 - 1 rounds to 2^54 = 2^27 * 2^27
            "134217729, 134217727, 134217728, 134217728, -1",
            "500000000000, 500000000000, 250000000000, 1000000000000, 0",
    })
    void signOfProductDifference_table(double a, double b, double c, double d, int expected) {
        assertEquals(expected, (int) Math.signum(Lines.signOfProductDifference(a, b, c, d)));
    }

    @Property(tries = 3000)
    void signOfProductDifference_exactOnWholeNumbers(@ForAll @IntRange(min = -4_000_000, max = 4_000_000) int p,
                                                     @ForAll @IntRange(min = 0, max = 3) int near,
                                                     @ForAll @IntRange(min = 1, max = 4_000_000) int q) {
        // Squares compared with nearby products: a = b = p*q, c = p*p + near - 1, d = q*q.
        double a = (double) p * q;
        double c = (double) p * p + near - 1;
        double d = (double) q * q;
        assertEquals(exactSign(a, a, c, d), (int) Math.signum(Lines.signOfProductDifference(a, a, c, d)));
    }

    @Property(tries = 3000)
    void signOfProductDifference_exactOnFloats(@ForAll float a, @ForAll float b, @ForAll float c, @ForAll float d) {
        if (Float.isFinite(a) && Float.isFinite(b) && Float.isFinite(c) && Float.isFinite(d)) {
            assertEquals(exactSign(a, b, c, d), (int) Math.signum(Lines.signOfProductDifference(a, b, c, d)));
        }
    }

    @ParameterizedTest
    @CsvSource({"0", "1", "2", "3"})
    void signOfProductDifference_nanGivesNaN(int slot) {
        double[] v = {1, 2, 3, 4};
        v[slot] = Double.NaN;
        assertTrue(Double.isNaN(Lines.signOfProductDifference(v[0], v[1], v[2], v[3])));
    }
}
