package hitbox.internal;

/**
 * The earliest of several candidate entries of one swept test (a box, a few discs), and
 * whether any started inside already: how {@link Sweep} takes the union of the pieces a
 * rounded box or a capsule is made of. Candidates carry the outward normal of the piece's
 * face where it is entered; the {@link Hit} made from them points the other way, from the
 * mover into the obstacle, as every normal in Hitbox does.
 */
public final class Earliest {
    public double t = Slabs.INF;
    /** The outward normal of the obstacle's face at the earliest entry (not unit length). */
    public double nx;
    public double ny;
    public boolean inside;
    /**
     * The latest exit of the pieces entered or started in (the union is convex, so this is
     * when the path leaves it), -infinity if none: where a search may stop.
     */
    public double until = Double.NEGATIVE_INFINITY;

    /** A clip's entry, if it is the earliest so far. */
    public void clip(Slabs.Clip clip, double limit) {
        if (clip.insideAtStart()) {
            inside = true;
        }
        offer(clip.firstTime(limit), clip.nx, clip.ny);
        if (clip.insideAtStart() || clip.firstTime(limit) != Slabs.INF) {
            until = Math.max(until, clip.exit);
        }
    }

    /** A point {@code d + t v} entering the open disc of radius reach around the origin. */
    public void disc(double dx, double dy, double vx, double vy, double reach, double limit) {
        double te = Discs.entry(dx, dy, vx, vy, reach, limit);
        if (te == Double.NEGATIVE_INFINITY) {
            inside = true;
        } else {
            offer(te, dx + te * vx, dy + te * vy);
        }
        if (te != Slabs.INF) {
            // The exit, (-b + sqrt(b^2 - a c)) / a: never, for a point at rest inside.
            double a = vx * vx + vy * vy, b = dx * vx + dy * vy, c = dx * dx + dy * dy - reach * reach;
            double out = a > 0 ? (-b + Math.sqrt(Math.max(b * b - a * c, 0))) / a : Slabs.INF;
            until = Math.max(until, out);
        }
    }

    /** Keeps (te, outward normal) if it comes first; at a tie the earlier offer stays. */
    public void offer(double te, double outX, double outY) {
        if (te < t) {
            t = te;
            nx = outX;
            ny = outY;
        }
    }

    /**
     * Back to nothing found, as a new one starts, for a thread's entry used again.
     *
     * @return this entry
     */
    public Earliest reset() {
        t = Slabs.INF;
        nx = 0;
        ny = 0;
        inside = false;
        until = Double.NEGATIVE_INFINITY;
        return this;
    }

    /** Did the shapes already overlap, or is there an entry within the limit? */
    public boolean found() {
        return inside || t != Slabs.INF;
    }
}
