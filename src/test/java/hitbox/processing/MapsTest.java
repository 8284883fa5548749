package hitbox.processing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

import hitbox.Grid;
import hitbox.TerrainColors;
import processing.core.PConstants;
import processing.core.PImage;

/** Maps.fromImage and toImage: a map drawn as a PImage and read back. */
class MapsTest {

    private static final String MAP = """
            ######
            #..2.#
            #.##.#
            ######
            """;

    private static TerrainColors key() {
        return new TerrainColors().put(0xFFFFFF, Grid.EMPTY).put(0x000000, Grid.SOLID).put(0x3070E0, 2);
    }

    @Test
    void toImageThenFromImage_isTheSameMap() {
        Grid map = Grid.parse(MAP, 16);
        PImage image = Maps.toImage(map, 3, key());
        assertEquals(18, image.width);
        assertEquals(12, image.height);
        assertEquals(0xFF3070E0, image.get(3 * 3 + 1, 3 + 2), "cell (3, 1) is water, drawn blue");
        Grid back = Maps.fromImage(image, 3, key(), 16);
        assertEquals(map.toMap(), back.toMap());
        assertEquals(16, back.cellWidth());
    }

    @Test
    void fromImage_rgbImage_countsAsOpaque() {
        // An RGB image's top byte means nothing to Processing: a black pixel may be stored as 0.
        PImage image = twoPixels(PConstants.RGB, 0x00000000, 0x00FFFFFF);
        assertEquals("#.", Maps.fromImage(image, 1, key(), 1).toMap());
    }

    @Test
    void fromImage_argbImage_withATransparentPixel_isRefused() {
        PImage image = twoPixels(PConstants.ARGB, 0xFF000000, 0x00FFFFFF);
        assertEquals("pixel (1, 0) is not opaque (alpha 0 of 255): paint every pixel of the map in one of the key's colours,"
                + " fully opaque", assertThrows(IllegalArgumentException.class, () -> Maps.fromImage(image, 1, key(), 1)).getMessage());
    }

    private static PImage twoPixels(int format, int left, int right) {
        PImage image = new PImage(2, 1, format);
        image.loadPixels();
        image.pixels[0] = left;
        image.pixels[1] = right;
        image.updatePixels();
        return image;
    }

    @Test
    void fromImage_noImage_saysWhy() {
        assertEquals("image is null: loadImage returns null when it cannot find or read the file; put the picture in the"
                + " sketch's data folder and check its name",
                assertThrows(IllegalArgumentException.class, () -> Maps.fromImage(null, 1, key(), 1)).getMessage());
        PImage failed = new PImage();
        failed.width = -1;
        failed.height = -1;
        assertEquals("image is -1 x -1 pixels: it could not be read",
                assertThrows(IllegalArgumentException.class, () -> Maps.fromImage(failed, 1, key(), 1)).getMessage());
    }

    @Test
    void toImage_badInput_isNamed() {
        Grid map = Grid.parse(MAP, 16);
        assertEquals("no colour stands for terrain 2 in the key (#FFFFFF -> 0, #000000 -> 1)",
                assertThrows(IllegalArgumentException.class,
                        () -> Maps.toImage(map, 1, new TerrainColors().put(0xFFFFFF, 0).put(0, 1))).getMessage());
        assertEquals("pixelsPerCell must be > 0, was 0",
                assertThrows(IllegalArgumentException.class, () -> Maps.toImage(map, 0, key())).getMessage());
        assertEquals("grid must not be null",
                assertThrows(IllegalArgumentException.class, () -> Maps.toImage(null, 1, key())).getMessage());
    }
}
