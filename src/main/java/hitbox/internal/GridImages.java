package hitbox.internal;

import hitbox.*;

/**
 * Maps from pictures, behind {@link Grid#fromPixels}: every block of
 * {@code pixelsPerCell x pixelsPerCell} pixels is one cell, and its colour says its terrain
 * through a {@link TerrainColors} key. Anything that would make a wrong map silently (a
 * colour not in the key, a pixel that is not opaque, a block of two terrains, a picture that
 * is not a whole number of cells) is an error that says what and where.
 */
public final class GridImages {

    private GridImages() {
    }

    /** See {@link Grid#fromPixels}. */
    public static Grid read(int[] pixels, int width, int height, int pixelsPerCell, TerrainColors colors,
                     float cellWidth, float cellHeight) {
        Check.notNull("pixels", pixels);
        Check.notNull("colors", colors);
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("the picture must be at least 1 x 1 pixels, was width x height = " + width + " x " + height);
        }
        if (pixels.length != (long) width * height) {
            throw new IllegalArgumentException("pixels has " + pixels.length + " values, but a width x height = " + width + " x "
                    + height + " picture has " + (long) width * height);
        }
        if (pixelsPerCell <= 0) {
            throw new IllegalArgumentException("pixelsPerCell must be > 0, was " + pixelsPerCell);
        }
        checkWhole("wide", width, pixelsPerCell);
        checkWhole("high", height, pixelsPerCell);
        if (colors.size() == 0) {
            throw new IllegalArgumentException("colors has no colours: put(color, terrain) each colour of the map");
        }
        int cols = width / pixelsPerCell;
        int rows = height / pixelsPerCell;
        Grid grid = new Grid(cols, rows, cellWidth, cellHeight);
        for (int row = 0; row < rows; row++) {
            for (int col = 0; col < cols; col++) {
                int x0 = col * pixelsPerCell;
                int y0 = row * pixelsPerCell;
                int first = pixels[y0 * width + x0];
                int terrain = terrainAt(colors, first, x0, y0);
                for (int y = y0; y < y0 + pixelsPerCell; y++) {
                    for (int x = x0; x < x0 + pixelsPerCell; x++) {
                        int p = pixels[y * width + x];
                        if (p != first && terrainAt(colors, p, x, y) != terrain) {
                            throw new IllegalArgumentException("cell (col " + col + ", row " + row + ") is not one terrain: pixel ("
                                    + x0 + ", " + y0 + ") is " + hex(first) + " (terrain " + terrain + ") but pixel ("
                                    + x + ", " + y + ") is " + hex(p) + " (terrain " + colors.terrainOf(p)
                                    + "); with " + pixelsPerCell + " pixels per cell, each " + pixelsPerCell + " x "
                                    + pixelsPerCell + " block, counted from the top-left corner, is one cell");
                        }
                    }
                }
                grid.set(col, row, terrain);
            }
        }
        return grid;
    }

    private static void checkWhole(String wideOrHigh, int size, int pixelsPerCell) {
        if (size % pixelsPerCell != 0) {
            int less = size / pixelsPerCell * pixelsPerCell;
            throw new IllegalArgumentException("the picture is " + size + " pixels " + wideOrHigh + ", not a whole number of "
                    + "pixelsPerCell = " + pixelsPerCell + "-pixel cells (" + (less > 0 ? less + " or " : "") + (less + pixelsPerCell)
                    + " would be)");
        }
    }

    /** The terrain of one pixel's colour, or an error naming the pixel. */
    private static int terrainAt(TerrainColors colors, int argb, int x, int y) {
        int alpha = argb >>> 24;
        if (alpha != 0xFF) {
            throw new IllegalArgumentException("pixel (" + x + ", " + y + ") is not opaque (alpha " + alpha
                    + " of 255): paint every pixel of the map in one of the key's colours, fully opaque");
        }
        try {
            return colors.terrainOf(argb);
        } catch (IllegalArgumentException notInTheKey) {
            throw new IllegalArgumentException("pixel (" + x + ", " + y + ") is " + hex(argb)
                    + ", a colour the key does not have (" + colors + "); paint programs blur edges with"
                    + " in-between colours: turn off anti-aliasing, or add the colour to the key", notInTheKey);
        }
    }

    /** A colour as {@code #RRGGBB}, the way paint programs and Processing write it. */
    public static String hex(int color) {
        return String.format("#%06X", color & 0xFFFFFF);
    }
}
