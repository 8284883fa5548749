package hitbox.processing;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class OverlayTest {

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "150    | 175     | true  | 150.0 < 175.0: colliding",
        "264    | 100     | false | 264.0 < 100.0 is false: not colliding",
        "175    | 175     | false | 175.0 < 175.0 is false: not colliding",
        "99.99  | 100     | true  | 99.99 < 100.00: colliding",
        "-0.5   | 0       | true  | -0.5 < 0.0: colliding",
    })
    void verdict_readsAsATrueStatement(float left, float right, boolean colliding, String expected) {
        assertEquals(expected, Overlay.verdict(left, "<", right, colliding));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "250     | 200 | true  | 250.0 > 200.0: true",
        "200.001 | 200 | true  | 200.001 > 200.000: true",
        "200     | 200 | false | 200.0 > 200.0: false",
    })
    void comparison_showsDecimalsUntilDifferentNumbersLookDifferent(float left, float right, boolean holds, String expected) {
        assertEquals(expected, Overlay.comparison(left, ">", right, holds));
    }
}
