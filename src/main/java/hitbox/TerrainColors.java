package hitbox;

import hitbox.internal.*;

import java.util.Arrays;

/**
 * The key of a map drawn as a picture: which colour stands for which terrain number, for
 * {@link Grid#fromPixels}. Draw your town in any paint program, one colour per kind of
 * place, and read it into a {@link Grid}:
 *
 * <pre>{@code
 * TerrainColors key = new TerrainColors()
 *     .put(0xFFFFFF, Grid.EMPTY)   // white: street
 *     .put(0x000000, Grid.SOLID)   // black: building
 *     .put(0x3070E0, 3);           // blue: water, a terrain type of your own
 * }</pre>
 *
 * <p>Colours are matched on red, green and blue; the alpha of a colour given here is ignored,
 * so {@code 0xFF0000} and Processing's {@code #FF0000} (which is {@code 0xFFFF0000}) are the
 * same red. A colour stands for one terrain; several colours may stand for the same one.
 *
 * <p>A key is built up with {@link #put} and is not safe to change from one thread while
 * another reads a map with it.
 */
public final class TerrainColors {

    private int[] colors = new int[0];
    private int[] terrains = new int[0];

    /** Makes an empty key: add colours with {@link #put}. */
    public TerrainColors() {
    }

    /**
     * Says which terrain a colour stands for.
     *
     * @param color   the colour, as {@code 0xRRGGBB} or Processing's {@code color} (the alpha is
     *                ignored)
     * @param terrain the terrain number: {@link Grid#EMPTY}, {@link Grid#SOLID} or one of your own
     * @return this key, for chaining, never null
     * @throws IllegalArgumentException if the colour already stands for another terrain
     */
    public TerrainColors put(int color, int terrain) {
        int rgb = color & 0xFFFFFF;
        int i = find(rgb);
        if (i >= 0) {
            if (terrains[i] != terrain) {
                throw new IllegalArgumentException("color " + GridImages.hex(rgb) + " already stands for terrain " + terrains[i]
                        + ", so it cannot also be terrain " + terrain + ": give each terrain its own colour");
            }
            return this;
        }
        colors = Arrays.copyOf(colors, colors.length + 1);
        terrains = Arrays.copyOf(terrains, terrains.length + 1);
        colors[colors.length - 1] = rgb;
        terrains[terrains.length - 1] = terrain;
        return this;
    }

    /**
     * The terrain a colour stands for.
     *
     * @param color the colour (the alpha is ignored)
     * @return its terrain number
     * @throws IllegalArgumentException if the colour is not in the key; the message lists the
     *                                  colours that are
     */
    public int terrainOf(int color) {
        int i = find(color & 0xFFFFFF);
        if (i < 0) {
            throw new IllegalArgumentException("colour " + GridImages.hex(color) + " is not in the key (" + this + ")");
        }
        return terrains[i];
    }

    /**
     * The colour that stands for a terrain: the first one {@link #put} for it, for drawing a
     * map back as a picture.
     *
     * @param terrain the terrain number
     * @return its colour, opaque ({@code 0xFFRRGGBB}, a Processing {@code color})
     * @throws IllegalArgumentException if no colour stands for this terrain
     */
    public int colorOf(int terrain) {
        for (int i = 0; i < terrains.length; i++) {
            if (terrains[i] == terrain) {
                return 0xFF000000 | colors[i];
            }
        }
        throw new IllegalArgumentException("no colour stands for terrain " + terrain + " in the key (" + this + ")");
    }

    /** @return how many colours the key names */
    public int size() {
        return colors.length;
    }

    /** @return the key as {@code #RRGGBB -> terrain} pairs, in the order they were put */
    @Override
    public String toString() {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < colors.length; i++) {
            s.append(i == 0 ? "" : ", ").append(GridImages.hex(colors[i])).append(" -> ").append(terrains[i]);
        }
        return colors.length == 0 ? "no colours" : s.toString();
    }

    private int find(int rgb) {
        for (int i = 0; i < colors.length; i++) {
            if (colors[i] == rgb) {
                return i;
            }
        }
        return -1;
    }

}
