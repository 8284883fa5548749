package processing.utils;

/**
 * A stand-in for the one class the build needs from {@code org.processing:utils:4.5.7}.
 *
 * <p>Processing's preprocessor ({@code org.processing:preprocessor:4.5.7}) names this class in
 * the {@code throws} clause of {@code PdePreprocessor.write}, and its POM depends on
 * {@code org.processing:utils:4.5.7}, which Maven Central does not serve (upstream
 * processing/processing4 issue #1568). Delete this file, and depend on that artifact instead,
 * the day it appears on Central.
 */
public class SketchException extends Exception {
    private static final long serialVersionUID = 1L;

    /**
     * @param message what went wrong
     */
    public SketchException(String message) {
        super(message);
    }
}
