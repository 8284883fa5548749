/**
 * Drawing for sketches: shapes, labels and the "show the maths" overlay, kept apart from the
 * collision maths in {@link hitbox}, which never depends on Processing.
 *
 * <p>Every method takes the {@code PGraphics} to draw on explicitly; inside a sketch that is
 * the sketch's own {@code g}: {@code Draw.shape(g, circle)}. Each method saves and restores the
 * drawing style, so it leaves the sketch's fill, stroke and text settings as they were.
 */
package hitbox.processing;
