package hitbox.web;

import hitbox.Body;
import hitbox.BodyEvent;
import hitbox.BodyHit;
import hitbox.CharacterBody;
import hitbox.Collision;
import hitbox.CollisionFilter;
import hitbox.Ray;
import hitbox.Reaction;
import hitbox.World;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.teavm.jso.JSBody;
import org.teavm.jso.JSClass;
import org.teavm.jso.JSExport;
import org.teavm.jso.JSObject;
import org.teavm.jso.core.JSArray;

/** A world of bodies for JavaScript: {@link World}'s add, move, step, queries and rays. */
@JSClass(name = "World")
public final class WorldJs {
    private final World world = new World();
    private final Map<Body, BodyJs> bodies = new HashMap<>();
    private int next;

    /** Makes an empty world. */
    @JSExport
    public WorldJs() {
    }

    /**
     * Adds a body where the shape stands.
     *
     * @param shape the body's shape
     * @return the new body
     */
    @JSExport
    public BodyJs add(ShapeJs shape) {
        return wrap(world.add(shape.shape));
    }

    /**
     * Adds a grid's solid cells as one body.
     *
     * @param grid the grid
     * @return the new body
     */
    @JSExport
    public BodyJs addGrid(GridJs grid) {
        return wrap(world.add(grid.grid));
    }

    /**
     * Takes a body out of the world.
     *
     * @param body the body
     */
    @JSExport
    public void remove(BodyJs body) {
        world.remove(body.body);
        bodies.remove(body.body);
    }

    /**
     * Adds a body that walks: it stands on ground, walks slopes, climbs steps
     * ({@link hitbox.CharacterBody}).
     *
     * @param shape the character's shape
     * @return the new character; its body is {@code character.body}
     */
    @JSExport
    public CharacterJs addCharacter(ShapeJs shape) {
        CharacterBody c = world.addCharacter(shape.shape);
        return new CharacterJs(c, this, wrap(c.body()));
    }

    private BodyJs wrap(Body b) {
        BodyJs js = new BodyJs(b, next++);
        bodies.put(b, js);
        return js;
    }

    /** The wrapper of a body of this world. */
    BodyJs wrapped(Body b) {
        return bodies.get(b);
    }

    /** The filter that reacts to every body as the string says, null for "SLIDE". */
    static CollisionFilter filter(String reaction) {
        Reaction r = reaction == null ? Reaction.SLIDE : Reaction.valueOf(reaction);
        return (m, o) -> r;
    }

    /** A move's collisions as JavaScript objects. */
    JSArray<JSObject> collisions(List<Collision> met) {
        JSArray<JSObject> out = JSArray.create();
        for (Collision c : met) {
            out.push(collision(bodies.get(c.other()), c.reaction().name(), c.hit().t(), c.hit().nx(), c.hit().ny(),
                    c.hit().side().name(), c.x(), c.y(), c.landed()));
        }
        return out;
    }

    /** @return how many bodies the world holds */
    @JSExport
    public int size() {
        return world.size();
    }

    @JSBody(params = {"other", "reaction", "t", "nx", "ny", "side", "x", "y", "landed"},
            script = "return {other: other, reaction: reaction, t: t, nx: nx, ny: ny, side: side, x: x, y: y, landed: landed};")
    private static native JSObject collision(BodyJs other, String reaction, float t, float nx, float ny, String side,
                                             float x, float y, boolean landed);

    @JSBody(params = {"kind", "a", "b"}, script = "return {kind: kind, a: a, b: b};")
    private static native JSObject event(String kind, BodyJs a, BodyJs b);

    @JSBody(params = {"body", "distance", "x", "y", "nx", "ny"},
            script = "return {body: body, distance: distance, x: x, y: y, nx: nx, ny: ny};")
    private static native JSObject bodyHit(BodyJs body, float distance, float x, float y, float nx, float ny);

    /**
     * Moves a body by (dx, dy) through the others, reacting to each one met: "SLIDE" (the
     * default), "TOUCH" (stop), "CROSS" (pass and report) or "BOUNCE".
     *
     * @param body     the body
     * @param dx       the move, x part
     * @param dy       the move, y part
     * @param reaction how to react to every body met, or null for "SLIDE"
     * @return what it met, in order: {other, reaction, t, nx, ny, side, x, y, landed}
     */
    @JSExport
    public JSArray<JSObject> move(BodyJs body, float dx, float dy, String reaction) {
        return collisions(world.move(body.body, dx, dy, filter(reaction)));
    }

    /**
     * The pairs in contact, as they came, stayed or went since the last step: {kind: "ENTER"|"STAY"|"EXIT", a, b}.
     *
     * @return the events
     */
    @JSExport
    public JSArray<JSObject> step() {
        JSArray<JSObject> out = JSArray.create();
        for (BodyEvent e : world.step()) {
            out.push(event(e.kind().name(), bodies.get(e.a()), bodies.get(e.b())));
        }
        return out;
    }

    /**
     * The bodies whose shape holds the point.
     *
     * @param x the point's x
     * @param y the point's y
     * @return the bodies
     */
    @JSExport
    public JSArray<BodyJs> queryPoint(float x, float y) {
        return list(world.queryPoint(x, y));
    }

    /**
     * The bodies overlapping this one.
     *
     * @param body the body
     * @return the bodies
     */
    @JSExport
    public JSArray<BodyJs> overlapping(BodyJs body) {
        return list(world.overlapping(body.body));
    }

    private JSArray<BodyJs> list(List<Body> found) {
        JSArray<BodyJs> out = JSArray.create();
        for (Body b : found) {
            out.push(bodies.get(b));
        }
        return out;
    }

    /**
     * The first body a ray meets: {body, distance, x, y, nx, ny}, or null.
     *
     * @param ox          the origin's x
     * @param oy          the origin's y
     * @param dx          the direction's x part
     * @param dy          the direction's y part
     * @param maxDistance how far it reaches
     * @return the hit, or null
     */
    @JSExport
    public JSObject raycast(float ox, float oy, float dx, float dy, float maxDistance) {
        BodyHit h = world.raycastFirst(new Ray(ox, oy, dx, dy, maxDistance), b -> true);
        return h == null ? null : bodyHit(bodies.get(h.body()), h.hit().distance(), h.hit().x(), h.hit().y(),
                h.hit().nx(), h.hit().ny());
    }
}
