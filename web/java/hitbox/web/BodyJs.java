package hitbox.web;

import hitbox.Body;
import hitbox.Side;
import org.teavm.jso.JSClass;
import org.teavm.jso.JSExport;
import org.teavm.jso.JSProperty;

/** A body of a {@link WorldJs}: a shape in its own frame and a pose, as {@link Body}. */
@JSClass(name = "Body")
public final class BodyJs {
    final Body body;
    /** Its number in its world, in the order added, for JavaScript to tell bodies apart. */
    final int id;

    BodyJs(Body body, int id) {
        this.body = body;
        this.id = id;
    }

    /** @return its number in its world, in the order added */
    @JSExport
    @JSProperty
    public int getId() {
        return id;
    }

    /** @return where its pivot stands, x ({@code Body.pivotX}) */
    @JSExport
    @JSProperty
    public float getPivotX() {
        return body.pivotX();
    }

    /** @return where its pivot stands, y ({@code Body.pivotY}) */
    @JSExport
    @JSProperty
    public float getPivotY() {
        return body.pivotY();
    }

    /** @return the angle, radians */
    @JSExport
    @JSProperty
    public float getAngle() {
        return body.angle();
    }

    /** @return the shape where the body is now */
    @JSExport
    @JSProperty
    public ShapeJs getShape() {
        return new ShapeJs(body.shape());
    }

    /**
     * Puts the body at (x, y) without meeting anything on the way.
     *
     * @param x the new x
     * @param y the new y
     * @return this body
     */
    @JSExport
    public BodyJs moveTo(float x, float y) {
        body.moveTo(x, y);
        return this;
    }

    /**
     * Turns the body to an angle, radians.
     *
     * @param angle the angle
     * @return this body
     */
    @JSExport
    public BodyJs turnTo(float angle) {
        body.turnTo(angle);
        return this;
    }

    /**
     * Makes the body a sensor (it reports, never blocks) or not.
     *
     * @param sensor whether it is a sensor
     * @return this body
     */
    @JSExport
    public BodyJs sensor(boolean sensor) {
        body.sensor(sensor);
        return this;
    }

    /**
     * Lets movers through from every side but one: "TOP" for a platform jumped onto from below,
     * "NONE" for a solid body.
     *
     * @param side the side that blocks
     * @return this body
     */
    @JSExport
    public BodyJs oneWay(String side) {
        body.oneWay(Side.valueOf(side));
        return this;
    }

    /** @return whether the body is a sensor */
    @JSExport
    @JSProperty
    public boolean getIsSensor() {
        return body.isSensor();
    }
}
