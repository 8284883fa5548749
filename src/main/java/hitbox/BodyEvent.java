package hitbox;

import hitbox.internal.*;

/**
 * A change in whether two bodies are in contact, as {@link World#step()} reports it: Matter.js's
 * {@code collisionStart}, {@code collisionActive} and {@code collisionEnd}, Box2D's begin and
 * end contact. {@link World#step(java.util.List)} reports the changes alone (ENTER and EXIT,
 * never STAY); the contacts that go on are then read from the world when needed.
 *
 * <p>Two bodies are in contact during a step when their layers accept each other and either
 * their shapes overlap at the step's end or a {@link World#move} during the step met one with
 * the other (so a player standing on a floor, which touches it without overlapping, is in
 * contact while it keeps moving into it). Sensors count like any other body.
 *
 * @param kind whether the contact began, goes on or ended, never null
 * @param a    the body added to the world first, never null
 * @param b    the other body, never null
 */
public record BodyEvent(Kind kind, Body a, Body b) {

    /** Whether a contact began, goes on or ended. */
    public enum Kind {
        /** The two bodies came into contact during this step: reported once. */
        ENTER,
        /** The two bodies were in contact at the last step and still are. */
        STAY,
        /** The two bodies were in contact at the last step and are not now, or one was removed: reported once. */
        EXIT
    }

    /**
     * Makes an event, checking its values.
     *
     * @param kind whether the contact began, goes on or ended
     * @param a    one body
     * @param b    the other body
     * @throws IllegalArgumentException if an argument is null, or a and b are the same body
     */
    public BodyEvent {
        Check.notNull("kind", kind);
        Check.notNull("a", a);
        Check.notNull("b", b);
        if (a == b) {
            throw new IllegalArgumentException("a and b must be two bodies, were both " + a);
        }
    }

    /**
     * Is this event about this body?
     *
     * @param body the body, not null
     * @return true if it is a or b
     * @throws IllegalArgumentException if {@code body} is null
     */
    public boolean involves(Body body) {
        Check.notNull("body", body);
        return a == body || b == body;
    }

    /**
     * The body in contact with the given one.
     *
     * @param body a or b, not null
     * @return the other of the two; null if {@code body} is neither
     * @throws IllegalArgumentException if {@code body} is null
     */
    public Body other(Body body) {
        Check.notNull("body", body);
        return a == body ? b : b == body ? a : null;
    }
}
