package hitbox.processing;

import hitbox.Grid;
import hitbox.TerrainColors;
import processing.core.PConstants;
import processing.core.PImage;

/**
 * Maps drawn as pictures: read a {@link Grid} from a {@code PImage}, or draw one into a
 * {@code PImage}, through a {@link TerrainColors} key. Draw the map of your town in any paint
 * program, one colour per kind of place, save it as a PNG in the sketch's {@code data/}
 * folder, and read it with
 * {@code Maps.fromImage(loadImage("town.png"), 1, key, 16)}.
 */
public final class Maps {
    private Maps() {
    }

    /**
     * Reads a map from a picture: every {@code pixelsPerCell x pixelsPerCell} block of
     * pixels is one cell, and its colour says the cell's terrain; see
     * {@link Grid#fromPixels}, which this calls with the image's pixels. An image without
     * alpha (format {@code RGB}) counts as opaque, as Processing draws it.
     *
     * <p>A NaN or infinite {@code cellSize} throws, naming it, as {@link Grid#fromPixels} does.
     *
     * @param image         the picture, as {@code loadImage} returns it
     * @param pixelsPerCell how many pixels across (and down) one cell is drawn, 1 or more
     * @param colors        which colour is which terrain
     * @param cellSize      a cell's width and height in the grid, in pixels, more than 0
     * @return a new grid, one cell per block of pixels, never null
     * @throws IllegalArgumentException if the image is null (loadImage did not find or could
     *                                  not read the file) or not loaded, or the picture is not
     *                                  a map the key can read; the message says what and where
     */
    public static Grid fromImage(PImage image, int pixelsPerCell, TerrainColors colors, float cellSize) {
        if (image == null) {
            throw new IllegalArgumentException("image is null: loadImage returns null when it cannot find or read the"
                    + " file; put the picture in the sketch's data folder and check its name");
        }
        if (image.width <= 0 || image.height <= 0) {
            throw new IllegalArgumentException("image is " + image.width + " x " + image.height + " pixels: "
                    + (image.width == 0 ? "it is still loading (requestImage)" : "it could not be read"));
        }
        image.loadPixels();
        int[] pixels = image.pixels;
        if (image.format == PConstants.RGB) {
            // An RGB image has no alpha: Processing ignores the top byte, so must the map.
            pixels = pixels.clone();
            for (int i = 0; i < pixels.length; i++) {
                pixels[i] |= 0xFF000000;
            }
        }
        return Grid.fromPixels(pixels, image.pixelWidth, image.pixelHeight, pixelsPerCell, colors, cellSize);
    }

    /**
     * Draws a map as a picture, each cell a {@code pixelsPerCell x pixelsPerCell} block in the
     * colour the key gives its terrain: the picture {@link #fromImage} reads back as the same
     * map. Save it ({@code image.save("town.png")}) to start a map in a paint program from one
     * written as text.
     *
     * @param grid          the map
     * @param pixelsPerCell how many pixels across (and down) to draw each cell, 1 or more
     * @param colors        which colour is which terrain; every terrain of the map needs one
     * @return a new image, never null
     * @throws IllegalArgumentException if an argument is null, {@code pixelsPerCell} is less
     *                                  than 1 or the picture would be too big, or the key has
     *                                  no colour for a terrain of the map
     */
    public static PImage toImage(Grid grid, int pixelsPerCell, TerrainColors colors) {
        if (grid == null || colors == null) {
            throw new IllegalArgumentException((grid == null ? "grid" : "colors") + " must not be null");
        }
        if (pixelsPerCell <= 0) {
            throw new IllegalArgumentException("pixelsPerCell must be > 0, was " + pixelsPerCell);
        }
        long w = (long) grid.cols() * pixelsPerCell;
        long h = (long) grid.rows() * pixelsPerCell;
        if (w * h > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("a picture of " + w + " x " + h + " pixels is too big");
        }
        PImage image = new PImage((int) w, (int) h, PConstants.RGB);
        image.loadPixels();
        for (int row = 0; row < grid.rows(); row++) {
            for (int col = 0; col < grid.cols(); col++) {
                int color = colors.colorOf(grid.get(col, row));
                for (int y = row * pixelsPerCell; y < (row + 1) * pixelsPerCell; y++) {
                    for (int x = col * pixelsPerCell; x < (col + 1) * pixelsPerCell; x++) {
                        image.pixels[y * (int) w + x] = color;
                    }
                }
            }
        }
        image.updatePixels();
        return image;
    }
}
