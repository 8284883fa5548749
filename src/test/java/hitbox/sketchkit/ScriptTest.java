package hitbox.sketchkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import processing.core.PConstants;

class ScriptTest {
    @TempDir
    Path dir;

    private File write(String text) throws IOException {
        Path file = dir.resolve("screenshot.txt");
        Files.writeString(file, text);
        return file.toFile();
    }

    @Test
    void read_everyStep() throws IOException {
        Script s = Script.read(write("""
                # a comment
                frames 90
                mouse 200 150
                at 30 click 10 20   # press here, release next frame
                at 40 key d
                at 50 hold UP 3
                """));
        assertEquals(90, s.frames());
        List<Script.Step> steps = s.steps();
        assertEquals(new Script.Step(1, Script.Kind.MOUSE, 200, 150, (char) 0, 0), steps.get(0));
        assertEquals(new Script.Step(30, Script.Kind.MOUSE, 10, 20, (char) 0, 0), steps.get(1));
        assertEquals(Script.Kind.PRESS, steps.get(2).kind());
        assertEquals(30, steps.get(2).frame());
        assertEquals(Script.Kind.RELEASE, steps.get(3).kind());
        assertEquals(31, steps.get(3).frame());
        assertEquals(new Script.Step(40, Script.Kind.KEY_DOWN, 0, 0, 'd', 'D'), steps.get(4));
        assertEquals(new Script.Step(41, Script.Kind.KEY_UP, 0, 0, 'd', 'D'), steps.get(5));
        assertEquals(new Script.Step(50, Script.Kind.KEY_DOWN, 0, 0, (char) PConstants.CODED, PConstants.UP), steps.get(6));
        assertEquals(new Script.Step(53, Script.Kind.KEY_UP, 0, 0, (char) PConstants.CODED, PConstants.UP), steps.get(7));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "frames 90\\n  jump 3       | :2:3: unknown step \"jump\"",
        "mouse 10 ten              | :1:1: \"ten\" is not a whole number",
        "at 5 mouse 10             | :1:1: a value is missing",
        "at 0 press                | :1:1: frames count from 1, was 0",
        "key ctrl                  | :1:1: unknown key \"ctrl\"",
        "frames 0                  | :1:1: frames must be >= 1, was 0",
    })
    void read_mistake_namesLineAndColumn(String text, String expected) throws IOException {
        File file = write(text.replace("\\n", "\n"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Script.read(file));
        assertTrue(e.getMessage().startsWith(file.getPath() + expected), e.getMessage());
    }
}
