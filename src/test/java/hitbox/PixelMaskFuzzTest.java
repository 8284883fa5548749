package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * Fuzzing PixelMask.fromPixels and PixelMask.parse, which read pixels and pictures a user
 * hands them. In a normal test run this replays the inputs kept in
 * src/test/resources/hitbox/PixelMaskFuzzTestInputs/&lt;method&gt;/; with {@code JAZZER_FUZZ=1}
 * Jazzer looks for new ones. Only the documented exception is allowed; a mask counts exactly
 * the pixels above the threshold, reads back from its picture, and overlaps itself exactly
 * when it has a solid pixel.
 */
class PixelMaskFuzzTest {

    @FuzzTest(maxDuration = "5m")
    void fromPixels(FuzzedDataProvider data) {
        int width = data.consumeInt(-2, 130);
        int height = data.consumeInt(-2, 20);
        int threshold = data.consumeInt(-2, 257);
        int[] pixels = data.consumeInts(data.consumeInt(0, 2600));
        PixelMask mask;
        try {
            mask = PixelMask.fromPixels(pixels, width, height, threshold);
        } catch (IllegalArgumentException expected) {
            assertTrue(expected.getMessage() != null && !expected.getMessage().isBlank());
            return;
        }
        int solid = 0;
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                boolean on = pixels[y * width + x] >>> 24 > threshold;
                assertEquals(on, mask.contains(x, y), "pixel " + x + ", " + y);
                solid += on ? 1 : 0;
            }
        }
        assertEquals(solid, mask.count());
        assertEquals(mask, PixelMask.parse(mask.toPicture()));
        assertEquals(solid > 0, mask.overlaps(mask, 0, 0));
        assertEquals(solid, mask.overlapCount(mask, 0, 0));
        int dx = data.consumeInt(-140, 140), dy = data.consumeInt(-30, 30);
        assertEquals(mask.overlaps(mask, dx, dy), Hybrid.check(mask, 0, 0, mask, dx, dy).overlaps());
    }

    @FuzzTest(maxDuration = "5m")
    void parse(FuzzedDataProvider data) {
        String picture = data.consumeRemainingAsString();
        PixelMask mask;
        try {
            mask = PixelMask.parse(picture);
        } catch (IllegalArgumentException expected) {
            assertTrue(expected.getMessage() != null && !expected.getMessage().isBlank());
            return;
        }
        assertEquals(mask, PixelMask.parse(mask.toPicture()));
    }
}
