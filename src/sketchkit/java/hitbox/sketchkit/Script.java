package hitbox.sketchkit;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;

import processing.core.PConstants;

/**
 * Scripted input for a sketch: what the mouse and keyboard do on which frame.
 *
 * <p>Build one in Java ({@code new Script().mouse(1, 200, 200).key(30, 'd')}) or read it from a
 * small text file, one step a line ({@code #} starts a comment):
 * <pre>
 * frames 120          how many frames to run (default 120)
 * mouse 200 150       from frame 1, the mouse is at (200, 150)
 * at 30 mouse 90 90   on frame 30 it moves to (90, 90)
 * at 40 press         on frame 40 the left button goes down where the mouse is...
 * at 41 release       ...and comes up on frame 41
 * at 50 click 120 80  a press at (120, 80) on frame 50, released the next frame
 * at 60 key d         the key 'd' is typed (pressed, released the next frame)
 * at 70 hold UP 20    the up arrow is held down for 20 frames
 * </pre>
 * Key names are a single character or one of UP, DOWN, LEFT, RIGHT, SPACE, ENTER.
 *
 * <p>Like real input, a press reaches the sketch's {@code mousePressed()} or
 * {@code keyPressed()} just after that frame's {@code draw()}; the mouse position is set
 * before {@code draw()}, so {@code mouseX} and {@code mouseY} already hold it.
 */
public final class Script {

    /** What happens on one frame. */
    enum Kind { MOUSE, PRESS, RELEASE, KEY_DOWN, KEY_UP }

    /** One step: on frame {@code frame}, do {@code kind} with these values. */
    record Step(int frame, Kind kind, int x, int y, char key, int keyCode) {
    }

    private final List<Step> steps = new ArrayList<>();
    private int frames = 120;

    /** Makes an empty script: no input, 120 frames. */
    public Script() {
    }

    /**
     * @param count how many frames to run, 1 or more
     * @return this script
     */
    public Script frames(int count) {
        if (count < 1) {
            throw new IllegalArgumentException("frames must be >= 1, was " + count);
        }
        frames = count;
        return this;
    }

    /** @return how many frames to run */
    public int frames() {
        return frames;
    }

    /**
     * Moves the mouse on a frame.
     *
     * @param frame the frame, from 1
     * @param x     the mouse's x
     * @param y     the mouse's y
     * @return this script
     */
    public Script mouse(int frame, int x, int y) {
        return add(new Step(frame, Kind.MOUSE, x, y, (char) 0, 0));
    }

    /**
     * Presses the left mouse button where the mouse is.
     *
     * @param frame the frame, from 1
     * @return this script
     */
    public Script press(int frame) {
        return add(new Step(frame, Kind.PRESS, -1, -1, (char) 0, 0));
    }

    /**
     * Releases the left mouse button.
     *
     * @param frame the frame, from 1
     * @return this script
     */
    public Script release(int frame) {
        return add(new Step(frame, Kind.RELEASE, -1, -1, (char) 0, 0));
    }

    /**
     * Moves the mouse to (x, y) and clicks there: pressed on {@code frame}, released on the next.
     *
     * @param frame the frame, from 1
     * @param x     the mouse's x
     * @param y     the mouse's y
     * @return this script
     */
    public Script click(int frame, int x, int y) {
        return mouse(frame, x, y).press(frame).release(frame + 1);
    }

    /**
     * Types a character key: down on {@code frame}, up on the next.
     *
     * @param frame the frame, from 1
     * @param key   the character, e.g. 'd'
     * @return this script
     */
    public Script key(int frame, char key) {
        return hold(frame, String.valueOf(key), 1);
    }

    /**
     * Holds a key down for some frames.
     *
     * @param frame  the frame it goes down, from 1
     * @param name   a single character, or UP, DOWN, LEFT, RIGHT, SPACE, ENTER
     * @param length how many frames it stays down, 1 or more
     * @return this script
     */
    public Script hold(int frame, String name, int length) {
        char key;
        int code;
        switch (name.toUpperCase(Locale.ROOT)) {
            case "UP" -> { key = PConstants.CODED; code = PConstants.UP; }
            case "DOWN" -> { key = PConstants.CODED; code = PConstants.DOWN; }
            case "LEFT" -> { key = PConstants.CODED; code = PConstants.LEFT; }
            case "RIGHT" -> { key = PConstants.CODED; code = PConstants.RIGHT; }
            case "SPACE" -> { key = ' '; code = 32; }
            case "ENTER" -> { key = PConstants.ENTER; code = 10; }
            default -> {
                if (name.length() != 1) {
                    throw new IllegalArgumentException("unknown key \"" + name
                            + "\": use one character or UP, DOWN, LEFT, RIGHT, SPACE, ENTER");
                }
                key = name.charAt(0);
                code = Character.toUpperCase(key);
            }
        }
        if (length < 1) {
            throw new IllegalArgumentException("a key is held for >= 1 frame, was " + length);
        }
        add(new Step(frame, Kind.KEY_DOWN, 0, 0, key, code));
        return add(new Step(frame + length, Kind.KEY_UP, 0, 0, key, code));
    }

    private Script add(Step step) {
        if (step.frame() < 1) {
            throw new IllegalArgumentException("frames count from 1, was " + step.frame());
        }
        steps.add(step);
        return this;
    }

    /** @return the steps, in the order they were added */
    List<Step> steps() {
        return Collections.unmodifiableList(steps);
    }

    /**
     * Reads a script file (format in the class comment).
     *
     * @param file the file
     * @return the script
     * @throws IllegalArgumentException naming the file, line and column of a mistake
     */
    public static Script read(File file) {
        List<String> lines;
        try {
            lines = Files.readAllLines(file.toPath(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + file, e);
        }
        Script script = new Script();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i).replaceFirst("#.*", "").trim();
            if (line.isEmpty()) {
                continue;
            }
            try {
                script.parseLine(line);
            } catch (RuntimeException e) {
                int column = lines.get(i).indexOf(line.charAt(0)) + 1;
                throw new IllegalArgumentException(file.getPath() + ":" + (i + 1) + ":" + column + ": "
                        + e.getMessage() + " in \"" + line + "\"", e);
            }
        }
        return script;
    }

    private void parseLine(String line) {
        String[] w = line.split("\\s+");
        int frame = 1;
        int at = 0;
        if (w[0].equals("at")) {
            frame = number(w, 1);
            at = 2;
        }
        String verb = word(w, at);
        switch (verb) {
            case "frames" -> frames(number(w, at + 1));
            case "mouse" -> mouse(frame, number(w, at + 1), number(w, at + 2));
            case "press" -> press(frame);
            case "release" -> release(frame);
            case "click" -> click(frame, number(w, at + 1), number(w, at + 2));
            case "key" -> hold(frame, word(w, at + 1), 1);
            case "hold" -> hold(frame, word(w, at + 1), number(w, at + 2));
            default -> throw new IllegalArgumentException("unknown step \"" + verb
                    + "\" (expected frames, mouse, press, release, click, key or hold)");
        }
    }

    private static String word(String[] w, int i) {
        if (i >= w.length) {
            throw new IllegalArgumentException("a value is missing");
        }
        return w[i];
    }

    private static int number(String[] w, int i) {
        String s = word(w, i);
        try {
            return Integer.parseInt(s);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("\"" + s + "\" is not a whole number");
        }
    }
}
