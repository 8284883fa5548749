package hitbox;

import hitbox.internal.*;

import java.util.Arrays;

/**
 * Pixel-perfect collision: which pixels of a sprite are solid, as an immutable bit mask.
 *
 * <p>The tutorial names pixel-perfect detection as the last, most precise stage; testing two
 * images pixel by pixel is exact but slow, so a
 * mask stores each row as bits, 64 pixels to a {@code long}: two masks are compared a
 * whole word at a time (shift one row's bits into line with the other's and AND them), 64
 * pixels per step instead of one. Sprites a few hundred pixels on a side cost a few
 * thousand word operations; a bounding-box test first (see {@link Hybrid}) skips most pairs
 * entirely.
 *
 * <p>Coordinates are whole pixels: x from 0 to {@code width() - 1} to the right, y from 0 to
 * {@code height() - 1} down, pixel (x, y) covering the unit square from (x, y) to
 * (x + 1, y + 1). Two masks collide when some pixel is solid in both, so masks side by side
 * that only share an edge do not (the touching rule). The other mask is placed by an integer
 * offset: its pixel (0, 0) lies on this mask's pixel (dx, dy). Made from a Processing image:
 * <pre>{@code
 * img.loadPixels();
 * PixelMask mask = PixelMask.fromPixels(img.pixels, img.width, img.height, 0);
 * }</pre>
 */
public final class PixelMask {
    private final int width;
    private final int height;
    private final int wordsPerRow;
    private final long[] bits;
    private final int count;
    // The solid pixels' bounds, inclusive; minX > maxX when there are none.
    final int minX;
    final int minY;
    final int maxX;
    final int maxY;

    private PixelMask(int width, int height, long[] bits) {
        this.width = width;
        this.height = height;
        this.wordsPerRow = (width + 63) >>> 6;
        this.bits = bits;
        int n = 0, x0 = width, y0 = height, x1 = -1, y1 = -1;
        for (int y = 0; y < height; y++) {
            for (int k = 0; k < wordsPerRow; k++) {
                long w = bits[y * wordsPerRow + k];
                if (w != 0) {
                    n += Long.bitCount(w);
                    x0 = Math.min(x0, k * 64 + Long.numberOfTrailingZeros(w));
                    x1 = Math.max(x1, k * 64 + 63 - Long.numberOfLeadingZeros(w));
                    y0 = Math.min(y0, y);
                    y1 = y;
                }
            }
        }
        this.count = n;
        this.minX = x0;
        this.minY = y0;
        this.maxX = x1;
        this.maxY = y1;
    }

    // ---------------------------------------------------------------- making masks

    /**
     * A mask from ARGB pixels, Processing's {@code PImage.pixels} layout: row after row,
     * {@code pixels[y * width + x]}. A pixel is solid when its alpha is above the threshold.
     *
     * <p>An image with no alpha channel (Processing's {@code RGB} format) has alpha 255
     * everywhere, so all of it is solid: use a PNG with transparency, or a threshold on colour
     * made by hand with {@link #fromGrid}.
     *
     * @param pixels         the colours, {@code width * height} of them, alpha in the top byte
     * @param width          the image's width, 1 or more
     * @param height         the image's height, 1 or more
     * @param alphaThreshold from 0 to 255: a pixel counts when its alpha is greater (0: any
     *                       pixel that is not fully transparent)
     * @return the mask, never null
     * @throws IllegalArgumentException if pixels is null, a size is not positive, the array
     *                                  does not hold {@code width * height} pixels, or the
     *                                  threshold is outside 0 to 255
     */
    public static PixelMask fromPixels(int[] pixels, int width, int height, int alphaThreshold) {
        Check.notNull("pixels", pixels);
        checkSize(width, height);
        if ((long) width * height != pixels.length) {
            throw new IllegalArgumentException("pixels has " + pixels.length + " values but width * height is "
                    + (long) width * height + " (" + width + " x " + height + ")");
        }
        if (alphaThreshold < 0 || alphaThreshold > 255) {
            throw new IllegalArgumentException("alphaThreshold must be between 0 and 255, was " + alphaThreshold);
        }
        int wpr = (width + 63) >>> 6;
        long[] bits = new long[wpr * height];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                if (pixels[y * width + x] >>> 24 > alphaThreshold) {
                    bits[y * wpr + (x >>> 6)] |= 1L << x;
                }
            }
        }
        return new PixelMask(width, height, bits);
    }

    /**
     * A mask from a grid of booleans, {@code solid[y][x]}: rows top to bottom.
     *
     * @param solid the rows, all of the same length, at least one row of at least one pixel
     * @return the mask, never null
     * @throws IllegalArgumentException if the grid or a row is null or empty, or the rows
     *                                  differ in length
     */
    public static PixelMask fromGrid(boolean[][] solid) {
        Check.notNull("solid", solid);
        if (solid.length == 0) {
            throw new IllegalArgumentException("solid must have at least one row");
        }
        for (int y = 0; y < solid.length; y++) {
            Check.notNull("row " + y, solid[y]);
            if (solid[y].length != solid[0].length) {
                throw new IllegalArgumentException("row " + y + " has " + solid[y].length + " pixels but row 0 has "
                        + solid[0].length + ": every row must be as long as the first");
            }
        }
        int width = solid[0].length, height = solid.length;
        checkSize(width, height);
        int wpr = (width + 63) >>> 6;
        long[] bits = new long[wpr * height];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                if (solid[y][x]) {
                    bits[y * wpr + (x >>> 6)] |= 1L << x;
                }
            }
        }
        return new PixelMask(width, height, bits);
    }

    /**
     * A mask drawn as text, one line per row: {@code '#'} is a solid pixel, {@code '.'} an
     * empty one. Spaces around each line are ignored, so a text block can be indented:
     * <pre>{@code
     * PixelMask ship = PixelMask.parse("""
     *     ..#..
     *     .###.
     *     ##.##
     *     """);
     * }</pre>
     *
     * @param picture the rows, separated by line breaks
     * @return the mask, never null
     * @throws IllegalArgumentException if the picture is null or empty, a row is empty or of
     *                                  a different length, or it has another character
     */
    public static PixelMask parse(String picture) {
        Check.notNull("picture", picture);
        String[] lines = picture.strip().split("\\R");
        boolean[][] solid = new boolean[lines.length][];
        for (int y = 0; y < lines.length; y++) {
            String line = lines[y].strip();
            if (line.isEmpty()) {
                throw new IllegalArgumentException("row " + y + " of the picture is empty: draw every row with '#' and '.'");
            }
            solid[y] = new boolean[line.length()];
            for (int x = 0; x < line.length(); x++) {
                char c = line.charAt(x);
                if (c != '#' && c != '.') {
                    throw new IllegalArgumentException("unexpected '" + c + "' at row " + y + ", column " + x
                            + ": use '#' for a solid pixel and '.' for an empty one");
                }
                solid[y][x] = c == '#';
            }
        }
        return fromGrid(solid);
    }

    private static void checkSize(int width, int height) {
        if (width <= 0) {
            throw new IllegalArgumentException("width must be > 0, was " + width);
        }
        if (height <= 0) {
            throw new IllegalArgumentException("height must be > 0, was " + height);
        }
    }

    // ---------------------------------------------------------------- reading

    /** @return the mask's width in pixels */
    public int width() {
        return width;
    }

    /** @return the mask's height in pixels */
    public int height() {
        return height;
    }

    /**
     * Is this pixel solid?
     *
     * @param x the pixel's column
     * @param y the pixel's row
     * @return true if the pixel is solid; false for a pixel outside the mask
     */
    public boolean contains(int x, int y) {
        if (x < 0 || y < 0 || x >= width || y >= height) {
            return false;
        }
        return (bits[y * wordsPerRow + (x >>> 6)] & (1L << x)) != 0;
    }

    /** @return how many pixels are solid */
    public int count() {
        return count;
    }

    /**
     * The smallest rectangle holding every solid pixel, in this mask's coordinates: a tighter
     * hit box than the image's own size when the sprite has transparent margins.
     *
     * @return the bounds, each pixel counted as a unit square; null if no pixel is solid
     */
    public Rect bounds() {
        return count == 0 ? null : new Rect(minX, minY, maxX - minX + 1, maxY - minY + 1);
    }

    // ---------------------------------------------------------------- collision

    /**
     * Does the other mask, with its top-left pixel placed on this mask's pixel (dx, dy),
     * have a solid pixel where this one does?
     *
     * @param other the other mask, not null
     * @param dx    where the other mask's left column lies in this mask's columns
     * @param dy    where the other mask's top row lies in this mask's rows
     * @return true if some pixel is solid in both
     * @throws IllegalArgumentException if other is null
     */
    public boolean overlaps(PixelMask other, int dx, int dy) {
        return scan(other, dx, dy, STOP_AT_FIRST) != NONE;
    }

    /**
     * The first pixel, in reading order (row by row, left to right), that is solid in both
     * masks: where a bullet first touched the sprite.
     *
     * @param other the other mask, not null
     * @param dx    where the other mask's left column lies in this mask's columns
     * @param dy    where the other mask's top row lies in this mask's rows
     * @return the pixel in this mask's coordinates, or null if the masks do not overlap
     * @throws IllegalArgumentException if other is null
     */
    public Pixel firstOverlap(PixelMask other, int dx, int dy) {
        long found = scan(other, dx, dy, STOP_AT_FIRST);
        return found == NONE ? null : new Pixel((int) (found & 0xffffffffL), (int) (found >>> 32));
    }

    /**
     * How many pixels are solid in both masks: how deep the overlap is.
     *
     * @param other the other mask, not null
     * @param dx    where the other mask's left column lies in this mask's columns
     * @param dy    where the other mask's top row lies in this mask's rows
     * @return the number of pixels solid in both, 0 if they do not overlap
     * @throws IllegalArgumentException if other is null
     */
    public int overlapCount(PixelMask other, int dx, int dy) {
        return (int) scan(other, dx, dy, COUNT);
    }

    private static final long NONE = -1;
    private static final boolean STOP_AT_FIRST = true;
    private static final boolean COUNT = false;

    /**
     * Walks the rows both masks' solid pixels share, word by word. Stopping at the first
     * pixel it returns {@code y << 32 | x} or {@link #NONE}; counting it returns the count.
     */
    private long scan(PixelMask other, int dx, int dy, boolean stopAtFirst) {
        Check.notNull("other", other);
        long none = stopAtFirst ? NONE : 0;
        if (count == 0 || other.count == 0) {
            return none;
        }
        // Only where both masks' solid bounds meet, in this mask's coordinates (long: no overflow).
        long x0 = Math.max(minX, (long) dx + other.minX), x1 = Math.min(maxX, (long) dx + other.maxX);
        long y0 = Math.max(minY, (long) dy + other.minY), y1 = Math.min(maxY, (long) dy + other.maxY);
        if (x0 > x1 || y0 > y1) {
            return none;
        }
        int k0 = (int) (x0 >>> 6), k1 = (int) (x1 >>> 6);
        long firstMask = -1L << (x0 & 63), lastMask = -1L >>> (63 - (x1 & 63));
        long total = 0;
        for (int y = (int) y0; y <= y1; y++) {
            int row = y * wordsPerRow;
            int otherRow = (y - dy) * other.wordsPerRow;
            for (int k = k0; k <= k1; k++) {
                long mine = bits[row + k];
                if (k == k0) {
                    mine &= firstMask;
                }
                if (k == k1) {
                    mine &= lastMask;
                }
                if (mine == 0) {
                    continue;
                }
                long both = mine & other.word(otherRow, (long) k * 64 - dx);
                if (both != 0) {
                    if (stopAtFirst) {
                        return (long) y << 32 | (k * 64L + Long.numberOfTrailingZeros(both));
                    }
                    total += Long.bitCount(both);
                }
            }
        }
        return stopAtFirst ? NONE : total;
    }

    /** The 64 pixels of a row starting at column {@code from} (which may be negative), as one word. */
    private long word(int rowStart, long from) {
        long k = Math.floorDiv(from, 64);
        int shift = Math.floorMod(from, 64);
        long low = wordAt(rowStart, k) >>> shift;
        return shift == 0 ? low : low | wordAt(rowStart, k + 1) << (64 - shift);
    }

    private long wordAt(int rowStart, long k) {
        return k < 0 || k >= wordsPerRow ? 0 : bits[rowStart + (int) k];
    }

    // ---------------------------------------------------------------- values

    /**
     * The mask drawn as text, the format {@link #parse} reads: {@code '#'} for solid pixels,
     * {@code '.'} for empty ones, one line per row.
     *
     * @return the picture, never null
     */
    public String toPicture() {
        StringBuilder sb = new StringBuilder((width + 1) * height);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                sb.append(contains(x, y) ? '#' : '.');
            }
            sb.append('\n');
        }
        return sb.toString();
    }

    /** Two masks are equal when they have the same size and the same solid pixels. */
    @Override
    public boolean equals(Object o) {
        return o instanceof PixelMask m && m.width == width && m.height == height && Arrays.equals(m.bits, bits);
    }

    @Override
    public int hashCode() {
        return 31 * (31 * width + height) + Arrays.hashCode(bits);
    }

    @Override
    public String toString() {
        return "PixelMask[" + width + " x " + height + ", " + count + " solid]";
    }

    /**
     * A pixel of a mask, by column and row.
     *
     * @param x the column
     * @param y the row
     */
    public record Pixel(int x, int y) {
    }
}
