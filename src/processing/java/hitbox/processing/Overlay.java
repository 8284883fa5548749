package hitbox.processing;

import java.util.Locale;

import processing.core.PConstants;
import processing.core.PGraphics;

/**
 * The "show the maths" overlay: the numbers a collision test compares, drawn where they live,
 * with the comparison written out ("150.0 &lt; 175.0: colliding").
 *
 * <p>Every sketch shows it on the {@code d} key; this class keeps its look the same in all of
 * them. Numbers are written with one decimal.
 */
public final class Overlay {
    /** Text colour of the overlay. */
    public static final int TEXT = 0xFFFFFFFF;
    /**
     * Colour for a test that says "colliding": {@link Palette#HIT}'s red made lighter, since
     * it is drawn as thin text and lines on the dark label box, where the fill red is hard to
     * read; same hue, so red still means colliding.
     */
    public static final int HIT = 0xFFFF6B6B;
    /** Colour for a test that says "not colliding": {@link Palette#MISS}'s green, lighter for text. */
    public static final int MISS = 0xFF7CE38B;
    /** Colour of the guide lines the overlay draws. */
    public static final int GUIDE = 0xFFFFD23F;
    /** The label box behind overlay text. */
    private static final int BOX = 0xC8141820;

    private Overlay() {
    }

    /**
     * Writes a number as the overlay does: one decimal, a dot whatever the locale.
     *
     * <p>A NaN is written {@code "NaN"}, an infinity {@code "Infinity"}.
     *
     * @param v the number
     * @return e.g. "150.0", never null
     */
    public static String number(float v) {
        return String.format(Locale.ROOT, "%.1f", v);
    }

    /**
     * Writes out a comparison and whether it holds, e.g. {@code "150.0 < 175.0: true"}.
     *
     * <p>Two different numbers that one decimal would show as equal ("100.0 &lt; 100.0") get
     * more decimals, so the text never looks like it contradicts the answer.
     *
     * <p>A NaN value is written {@code "NaN"}.
     *
     * @param left   the left side's value
     * @param op     the operator, e.g. "&lt;"
     * @param right  the right side's value
     * @param result whether the comparison is true
     * @return the sentence, never null
     */
    public static String comparison(float left, String op, float right, boolean result) {
        return sides(left, op, right) + ": " + (result ? "true" : "false");
    }

    /**
     * Writes out a test that decides a collision: {@code "150.0 < 175.0: colliding"} when it
     * holds, {@code "264.0 < 100.0 is false: not colliding"} when it does not, so the line
     * always reads as a true statement.
     *
     * <p>A NaN value is written {@code "NaN"}.
     *
     * @param left      the left side's value
     * @param op        the operator
     * @param right     the right side's value
     * @param colliding the test's answer
     * @return the sentence, never null
     */
    public static String verdict(float left, String op, float right, boolean colliding) {
        return sides(left, op, right) + (colliding ? ": colliding" : " is false: not colliding");
    }

    /** "left op right", with enough decimals that different numbers look different. */
    private static String sides(float left, String op, float right) {
        String l = number(left);
        String r = number(right);
        for (int decimals = 2; l.equals(r) && left != right && decimals <= 6; decimals++) {
            String format = "%." + decimals + "f";
            l = String.format(Locale.ROOT, format, left);
            r = String.format(Locale.ROOT, format, right);
        }
        return l + " " + op + " " + r;
    }

    /**
     * Draws text on a dark box with its top-left at (x, y), kept inside the window.
     *
     * <p>Nothing is checked: a NaN coordinate is handed to Processing as it is.
     *
     * @param g      where to draw
     * @param x      the box's left
     * @param y      the box's top
     * @param text   the text; several lines are fine
     * @param colour the text colour, e.g. {@link #TEXT}, {@link #HIT} or {@link #MISS}
     */
    public static void label(PGraphics g, float x, float y, String text, int colour) {
        g.pushStyle();
        g.textSize(12);
        g.textAlign(PConstants.LEFT, PConstants.TOP);
        String[] lines = text.split("\n");
        float w = 0;
        for (String line : lines) {
            w = Math.max(w, g.textWidth(line));
        }
        float lineH = 15;
        float boxW = w + 8;
        float boxH = lines.length * lineH + 4;
        float bx = Math.max(2, Math.min(x, g.width - boxW - 2));
        float by = Math.max(2, Math.min(y, g.height - boxH - 2));
        g.noStroke();
        g.fill(BOX);
        g.rect(bx, by, boxW, boxH, 3);
        g.fill(colour);
        for (int i = 0; i < lines.length; i++) {
            g.text(lines[i], bx + 4, by + 2 + i * lineH);
        }
        g.popStyle();
    }

    /**
     * Draws text on a dark box centred on (x, y), kept inside the window: for a label that
     * belongs beside an edge or over a line, whatever its length.
     *
     * <p>Nothing is checked: a NaN coordinate is handed to Processing as it is.
     *
     * @param g      where to draw
     * @param x      the box's centre x
     * @param y      the box's centre y
     * @param text   the text; several lines are fine
     * @param colour the text colour
     */
    public static void labelCentered(PGraphics g, float x, float y, String text, int colour) {
        labelBeside(g, x, y, 0, 0, text, colour);
    }

    /**
     * Draws text on a dark box just beside the point (x, y), on the side the direction
     * (dx, dy) points to, whatever the text's length: for a label beside a line (give the
     * line's sideways direction) or outside an edge (give the edge's outward direction).
     * A zero direction centres the box on the point. The box is kept inside the window.
     *
     * <p>Nothing is checked: a NaN coordinate is handed to Processing as it is.
     *
     * @param g      where to draw
     * @param x      the point's x
     * @param y      the point's y
     * @param dx     the direction's x, any length
     * @param dy     the direction's y, any length
     * @param text   the text; several lines are fine
     * @param colour the text colour
     */
    public static void labelBeside(PGraphics g, float x, float y, float dx, float dy, String text, int colour) {
        g.pushStyle();
        g.textSize(12);
        String[] lines = text.split("\n");
        float w = 0;
        for (String line : lines) {
            w = Math.max(w, g.textWidth(line));
        }
        g.popStyle();
        // The same box as label(): text width + 8 across, 15 a line + 4 down.
        float halfW = (w + 8) / 2;
        float halfH = (lines.length * 15 + 4) / 2f;
        float len = (float) Math.hypot(dx, dy);
        float cx = x;
        float cy = y;
        if (len > 0) {
            float ux = dx / len;
            float uy = dy / len;
            // How far the box's centre must be from the point for the box to just clear it
            // in that direction, plus a small gap.
            float reach = halfW * Math.abs(ux) + halfH * Math.abs(uy) + 4;
            cx += ux * reach;
            cy += uy * reach;
        }
        label(g, cx - halfW, cy - halfH, text, colour);
    }

    /**
     * Draws a label in the overlay's plain text colour.
     *
     * <p>Nothing is checked: a NaN coordinate is handed to Processing as it is.
     *
     * @param g    where to draw
     * @param x    the box's left
     * @param y    the box's top
     * @param text the text
     */
    public static void label(PGraphics g, float x, float y, String text) {
        label(g, x, y, text, TEXT);
    }

    /**
     * Draws a guide line (dashed) between two points with its length written at its middle:
     * the distance a circle test compares.
     *
     * <p>Nothing is checked: a NaN coordinate is handed to Processing as it is.
     *
     * @param g  where to draw
     * @param x1 one end's x
     * @param y1 one end's y
     * @param x2 the other end's x
     * @param y2 the other end's y
     * @param name what the length is called, e.g. "distance"
     */
    public static void measure(PGraphics g, float x1, float y1, float x2, float y2, String name) {
        guide(g, x1, y1, x2, y2);
        float len = (float) Math.hypot(x2 - x1, y2 - y1);
        label(g, (x1 + x2) / 2 + 6, (y1 + y2) / 2 + 6, name + " = " + number(len), GUIDE);
    }

    /**
     * Draws a circle's radius as a dimension bar: a solid line as long as the radius, from the
     * centre along a direction, with a tick at each end, labelled {@code "r = 100.0"} by the
     * centre. The bar is set 12 pixels to the side {@code (-dy, dx)} of the direction, so it
     * does not hide a distance line drawn from the same centre; two circles that draw their
     * radii towards each other get them on opposite sides.
     *
     * <p>Nothing is checked: a NaN coordinate is handed to Processing as it is.
     *
     * @param g    where to draw
     * @param cx   the circle's centre x
     * @param cy   the circle's centre y
     * @param dx   the direction's x, any length (a zero direction draws it to the right)
     * @param dy   the direction's y, any length
     * @param r    the radius
     * @param name what the radius is called, e.g. "r1"
     */
    public static void radius(PGraphics g, float cx, float cy, float dx, float dy, float r, String name) {
        float len = (float) Math.hypot(dx, dy);
        float ux = len > 0 ? dx / len : 1;
        float uy = len > 0 ? dy / len : 0;
        float sx = -uy;
        float sy = ux;
        float x1 = cx + sx * 12;
        float y1 = cy + sy * 12;
        float x2 = x1 + ux * r;
        float y2 = y1 + uy * r;
        g.pushStyle();
        g.stroke(TEXT);
        g.strokeWeight(2);
        g.line(x1, y1, x2, y2);
        g.strokeWeight(1.5f);
        g.line(x1 - sx * 5, y1 - sy * 5, x1 + sx * 5, y1 + sy * 5);
        g.line(x2 - sx * 5, y2 - sy * 5, x2 + sx * 5, y2 + sy * 5);
        g.popStyle();
        // By the centre, behind it and to the bar's side: clear of the bar and of whatever
        // the bar points at.
        labelBeside(g, x1, y1, sx - ux, sy - uy, name + " = " + number(r), TEXT);
    }

    /**
     * Draws a dashed guide line.
     *
     * <p>Nothing is checked: a NaN coordinate is handed to Processing as it is.
     *
     * @param g  where to draw
     * @param x1 one end's x
     * @param y1 one end's y
     * @param x2 the other end's x
     * @param y2 the other end's y
     */
    public static void guide(PGraphics g, float x1, float y1, float x2, float y2) {
        g.pushStyle();
        g.stroke(GUIDE);
        g.strokeWeight(1.5f);
        float len = (float) Math.hypot(x2 - x1, y2 - y1);
        int dashes = Math.max(1, (int) (len / 6));
        for (int i = 0; i < dashes; i += 2) {
            float a = (float) i / dashes;
            float b = Math.min(1, (float) (i + 1) / dashes);
            g.line(x1 + (x2 - x1) * a, y1 + (y2 - y1) * a, x1 + (x2 - x1) * b, y1 + (y2 - y1) * b);
        }
        g.popStyle();
    }

    /**
     * Draws the key hint along the bottom of the window, e.g. "d: show the maths".
     *
     * @param g    where to draw
     * @param text the hint
     */
    public static void hint(PGraphics g, String text) {
        g.pushStyle();
        g.textSize(11);
        g.textAlign(PConstants.LEFT, PConstants.BOTTOM);
        g.fill(0x99000000);
        g.noStroke();
        g.rect(0, g.height - 18, g.width, 18);
        g.fill(0xFFDDDDDD);
        g.text(text, 6, g.height - 3);
        g.popStyle();
    }
}
