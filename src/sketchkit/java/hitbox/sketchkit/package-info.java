/**
 * The tools around the sketches, not part of the library: finding the sketch folders
 * ({@link hitbox.sketchkit.Catalog}), opening one or the gallery ({@link hitbox.sketchkit.Launcher},
 * {@link hitbox.sketchkit.Gallery}), and running a sketch for a fixed number of frames with
 * scripted mouse and key input ({@link hitbox.sketchkit.SketchRun}, {@link hitbox.sketchkit.Script}),
 * which both the display tests and {@code gradle screenshots} use.
 *
 * <p>Sketches live in {@code sketches/<Name>/<Name>.pde}; the build compiles each into the
 * class {@code sketches.<Name>}, a {@code PApplet} subclass.
 */
package hitbox.sketchkit;
