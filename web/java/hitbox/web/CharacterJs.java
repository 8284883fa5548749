package hitbox.web;

import hitbox.CharacterBody;
import hitbox.Vec;
import org.teavm.jso.JSBody;
import org.teavm.jso.JSClass;
import org.teavm.jso.JSExport;
import org.teavm.jso.JSObject;
import org.teavm.jso.JSProperty;
import org.teavm.jso.core.JSArray;

/**
 * A body that walks ({@link CharacterBody}) for JavaScript: {@code world.addCharacter(shape)},
 * then {@code move(dx, dy)} every frame and {@code onGround}, {@code onWall},
 * {@code onCeiling}, {@code ground}, {@code groundNormal} after it. The settings chain as in
 * Java ({@code .maxSlope(50).stepHeight(8).snap(4)}); their values are read from
 * {@code settings}, for a JavaScript object cannot have a method and a property of one name.
 */
@JSClass(name = "Character")
public final class CharacterJs {
    final CharacterBody character;
    private final WorldJs world;
    private final BodyJs body;

    CharacterJs(CharacterBody character, WorldJs world, BodyJs body) {
        this.character = character;
        this.world = world;
        this.body = body;
    }

    /** @return its body in the world (position, shape, sensor flag, one-way side) */
    @JSExport
    @JSProperty
    public BodyJs getBody() {
        return body;
    }

    /**
     * Walks this frame by (dx, dy): along ground, up and down slopes, up steps, sliding on
     * walls ({@link CharacterBody#move(float, float, hitbox.CollisionFilter)}).
     *
     * @param dx       the move, x part
     * @param dy       the move, y part
     * @param reaction how to react to every body met, or null for "SLIDE"
     * @return what it met, in order: {other, reaction, t, nx, ny, side, x, y, landed}
     */
    @JSExport
    public JSArray<JSObject> move(float dx, float dy, String reaction) {
        return world.collisions(character.move(dx, dy, WorldJs.filter(reaction)));
    }

    /** @return whether it stands on ground after its last move */
    @JSExport
    @JSProperty
    public boolean getOnGround() {
        return character.onGround();
    }

    /** @return whether its last move met a wall */
    @JSExport
    @JSProperty
    public boolean getOnWall() {
        return character.onWall();
    }

    /** @return whether its last move met a ceiling */
    @JSExport
    @JSProperty
    public boolean getOnCeiling() {
        return character.onCeiling();
    }

    /** @return the body it stands on, or null */
    @JSExport
    @JSProperty
    public BodyJs getGround() {
        return character.ground() == null ? null : world.wrapped(character.ground());
    }

    @JSBody(params = {"x", "y"}, script = "return {x: x, y: y};")
    private static native JSObject vec(float x, float y);

    /** @return the normal of the ground it stands on, {x, y} pointing out of the ground, or null */
    @JSExport
    @JSProperty
    public JSObject getGroundNormal() {
        Vec n = character.groundNormal();
        return n == null ? null : vec(n.x(), n.y());
    }

    @JSBody(params = {"maxSlope", "stepHeight", "snap", "upX", "upY"},
            script = "return {maxSlope: maxSlope, stepHeight: stepHeight, snap: snap, upX: upX, upY: upY};")
    private static native JSObject settings(float maxSlope, float stepHeight, float snap, float upX, float upY);

    /** @return {maxSlope, stepHeight, snap, upX, upY}: what the setters below set */
    @JSExport
    @JSProperty
    public JSObject getSettings() {
        Vec up = character.up();
        return settings(character.maxSlope(), character.stepHeight(), character.snap(), up.x(), up.y());
    }

    /**
     * How steep a surface may be and still be ground (45 by default).
     *
     * @param degrees from 0 to less than 90
     * @return this character
     */
    @JSExport
    public CharacterJs maxSlope(float degrees) {
        character.maxSlope(degrees);
        return this;
    }

    /**
     * How high a step it climbs when walking into it (0 by default).
     *
     * @param px pixels, 0 or more
     * @return this character
     */
    @JSExport
    public CharacterJs stepHeight(float px) {
        character.stepHeight(px);
        return this;
    }

    /**
     * How far down it keeps to the ground when walking down a slope or off a step (0 by default).
     *
     * @param px pixels, 0 or more
     * @return this character
     */
    @JSExport
    public CharacterJs snap(float px) {
        character.snap(px);
        return this;
    }

    /**
     * Which way is up ((0, -1) by default, y growing down); (0, 0) makes every surface a wall.
     *
     * @param x its x part
     * @param y its y part
     * @return this character
     */
    @JSExport
    public CharacterJs up(float x, float y) {
        character.up(x, y);
        return this;
    }
}
