package hitbox.web;

import hitbox.Contact;
import hitbox.Hit;
import hitbox.RayHit;
import hitbox.Rect;
import hitbox.Separation;
import org.teavm.jso.JSBody;
import org.teavm.jso.JSObject;

/** The answers as plain JavaScript objects, and null for no answer (the library's own rule). */
final class Js {
    private Js() {
    }

    @JSBody(params = {"nx", "ny", "depth"}, script = "return {nx: nx, ny: ny, depth: depth};")
    private static native JSObject contact(float nx, float ny, float depth);

    @JSBody(params = {"t", "nx", "ny", "side"}, script = "return {t: t, nx: nx, ny: ny, side: side};")
    private static native JSObject hit(float t, float nx, float ny, String side);

    @JSBody(params = {"distance", "x", "y", "nx", "ny"},
            script = "return {distance: distance, x: x, y: y, nx: nx, ny: ny};")
    private static native JSObject rayHit(float distance, float x, float y, float nx, float ny);

    @JSBody(params = {"distance", "ax", "ay", "bx", "by"},
            script = "return {distance: distance, ax: ax, ay: ay, bx: bx, by: by};")
    private static native JSObject separation(float distance, float ax, float ay, float bx, float by);

    @JSBody(params = {"x", "y", "w", "h"}, script = "return {x: x, y: y, w: w, h: h};")
    static native JSObject box(float x, float y, float w, float h);

    static JSObject of(Contact c) {
        return c == null ? null : contact(c.nx(), c.ny(), c.depth());
    }

    static JSObject of(Hit h) {
        return h == null ? null : hit(h.t(), h.nx(), h.ny(), h.side().name());
    }

    static JSObject of(RayHit h) {
        return h == null ? null : rayHit(h.distance(), h.x(), h.y(), h.nx(), h.ny());
    }

    static JSObject of(Separation s) {
        return s == null ? null : separation(s.distance(), s.ax(), s.ay(), s.bx(), s.by());
    }

    static JSObject of(Rect r) {
        return r == null ? null : box(r.x(), r.y(), r.w(), r.h());
    }
}
