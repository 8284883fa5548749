package hitbox;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

/** The Contact record itself; the pairs have their own classes (CircleRectContactTest, ...). */
class ContactTest {

    @ParameterizedTest
    @CsvSource({
        "0, 1, 0, 'depth must be > 0, was 0.0'",
        "0, 1, -2, 'depth must be > 0, was -2.0'",
        "0, 1, NaN, 'depth must be a finite number, was NaN'",
        "0, 1, Infinity, 'depth must be a finite number, was Infinity'",
        "NaN, 1, 1, 'nx must be a finite number, was NaN'",
        "0, 2, 1, 'the normal (nx, ny) must have length 1, but (0.0, 2.0) has length 2.0'",
        "0, 0, 1, 'the normal (nx, ny) must have length 1, but (0.0, 0.0) has length 0.0'",
        "0.6, 0.7, 1, 'the normal (nx, ny) must have length 1, but (0.6, 0.7) has length 0.92195445'",
    })
    void constructor_badValues_throwNamingThem(float nx, float ny, float depth, String message) {
        assertEquals(message, assertThrows(IllegalArgumentException.class, () -> new Contact(nx, ny, depth)).getMessage());
    }

    @ParameterizedTest
    @CsvSource({"0.6, 0.8", "0.70710677, 0.70710677", "1.0005, 0", "-0.9995, 0"})
    void constructor_acceptsUnitNormalsWithinTolerance(float nx, float ny) {
        Contact c = new Contact(nx, ny, 1);
        assertEquals(nx, c.nx());
        assertEquals(ny, c.ny());
    }

    @Test
    void constructor_negativeZero_becomesZero() {
        assertEquals(new Contact(0, 1, 2), new Contact(-0.0f, 1, 2));
        assertEquals(new Contact(0, -1, 2), new Contact(0, 1, 2).flipped());
        assertEquals(Float.floatToIntBits(0.0f), Float.floatToIntBits(new Contact(-0.0f, 1, 2).nx()));
    }

    @ParameterizedTest
    @CsvSource({
        // nx, ny, side of b that a is against
        "0, 1, TOP",              // b below a: a landed on b
        "0, -1, BOTTOM",          // b above a: a hit its head
        "1, 0, LEFT",             // b to the right: a ran into b's left side
        "-1, 0, RIGHT",
        "0.6, 0.8, TOP",          // mostly down
        "0.8, 0.6, LEFT",         // mostly right
        "-0.8, -0.6, RIGHT",
        "-0.6, -0.8, BOTTOM",
        "0.70710677, 0.70710677, TOP",      // exactly 45 degrees: landing wins
        "-0.70710677, -0.70710677, BOTTOM",
    })
    void side_isTheSideOfB_thatAIsAgainst(float nx, float ny, Side side) {
        assertEquals(side, new Contact(nx, ny, 1).side());
        assertEquals(side == Side.TOP, new Hit(0.5f, nx, ny, new Contact(nx, ny, 1).side()).landed(), "a hit with that side landed");
    }

    @Test
    void side_platformer_playerFallingOntoAPlatform_landed() {
        Rect player = new Rect(10, 5, 10, 20);       // feet at y = 25
        Rect platform = new Rect(0, 22, 100, 10);    // top at y = 22
        Contact c = player.contact(platform);
        assertEquals(Side.TOP, c.side());
        assertEquals(Side.BOTTOM, platform.contact(player).side(), "seen from the platform, it is against the player's bottom");
        Rect wall = new Rect(18, -50, 10, 70);       // overlaps the player's right side by 2
        assertEquals(Side.LEFT, player.contact(wall).side());
        assertEquals(new Contact(1, 0, 2), player.contact(wall));
    }

    @Test
    void flipped_reversesNormal_keepsDepth() {
        assertEquals(new Contact(-0.6f, -0.8f, 3), new Contact(0.6f, 0.8f, 3).flipped());
        assertEquals(new Contact(0.6f, 0.8f, 3), new Contact(0.6f, 0.8f, 3).flipped().flipped());
    }


    @Test
    void between_nullShapes_throwNamingThem() {
        Circle c = new Circle(0, 0, 1);
        assertEquals("other must not be null", assertThrows(IllegalArgumentException.class, () -> c.contact(null)).getMessage());
    }

    @Test
    void shapeContact_isBetween_forEveryKind() {
        Shape[] shapes = {new Circle(5, 5, 4), new Rect(2, 3, 6, 5), Polygon.of(0, 0, 10, 0, 5, 8),
            Polygon.of(0, 0, 10, 0, 10, 10, 5, 4, 0, 10)};
        for (Shape a : shapes) {
            for (Shape b : shapes) {
                assertEquals(a.contact(b), a.contact(b), a + " and " + b);
            }
        }
    }
}
