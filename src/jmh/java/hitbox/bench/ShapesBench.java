package hitbox.bench;

import java.util.Random;
import java.util.concurrent.TimeUnit;

import hitbox.Capsule;
import hitbox.Contact;
import hitbox.Ellipse;
import hitbox.Hit;
import hitbox.Polygon;
import hitbox.Rect;
import hitbox.Sweep;
import org.dyn4j.collision.continuous.ConservativeAdvancement;
import org.dyn4j.collision.continuous.TimeOfImpact;
import org.dyn4j.collision.narrowphase.Gjk;
import org.dyn4j.collision.narrowphase.Penetration;
import org.dyn4j.geometry.Circle;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Rectangle;
import org.dyn4j.geometry.Transform;
import org.dyn4j.geometry.Vector2;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * The curved shapes and the turning sweep against dyn4j 6.0.0 (GJK for overlap, GJK + EPA for
 * contact, conservative advancement for the turning time of impact), 256 pairs per call for
 * the pair tests, on the same random pairs (about half of them overlapping).
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class ShapesBench {
    static final int N = 256;
    float[] x = new float[N + 1], y = new float[N + 1], a = new float[N + 1], b = new float[N + 1];
    float[] x2 = new float[N + 1], y2 = new float[N + 1];
    Ellipse[] ellipses = new Ellipse[N + 1];
    Capsule[] capsules = new Capsule[N + 1];
    hitbox.Circle[] circles = new hitbox.Circle[N + 1];
    Convex[] dynEllipses = new Convex[N + 1], dynCapsules = new Convex[N + 1], dynCircles = new Convex[N + 1];
    Transform[] eT = new Transform[N + 1], cT = new Transform[N + 1], tT = new Transform[N + 1], bT = new Transform[N + 1];
    Ellipse[] turned = new Ellipse[N + 1];
    Rect[] boxes = new Rect[N + 1];
    Convex[] dynBoxes = new Convex[N + 1];
    final Gjk gjk = new Gjk();
    final ConservativeAdvancement ca = new ConservativeAdvancement();
    Polygon blade = Polygon.of(Rect.centered(200, 200, 160, 4)).rotated(0, 200, 200);
    Rect post = new Rect(241, 241, 2, 2);
    Convex dynBlade = new Rectangle(160, 4), dynPost = new Rectangle(2, 2);
    Transform bladeT = new Transform(), postT = new Transform();
    Polygon[] octagons = new Polygon[N + 1];
    hitbox.Shape[] mixed = new hitbox.Shape[N + 1];
    float[] vx = new float[N + 1], vy = new float[N + 1];

    @Setup
    public void setup() {
        Random rnd = new Random(5);
        for (int i = 0; i <= N; i++) {
            x[i] = rnd.nextInt(300);
            y[i] = rnd.nextInt(300);
            a[i] = 10 + rnd.nextInt(40);
            b[i] = 10 + rnd.nextInt(40);
            ellipses[i] = new Ellipse(x[i], y[i], a[i], b[i]);
            dynEllipses[i] = new org.dyn4j.geometry.Ellipse(2 * a[i], 2 * b[i]);
            dynCircles[i] = new Circle(b[i]);
            circles[i] = new hitbox.Circle(x[i], y[i], b[i]);
            eT[i] = new Transform();
            eT[i].setTranslation(x[i], y[i]);
            // A capsule along x, length 2 a, radius b / 2 (dyn4j's Capsule(width, height) is the same, centred).
            x2[i] = x[i] + 2 * a[i];
            y2[i] = y[i];
            capsules[i] = new Capsule(x[i], y[i], x2[i], y2[i], b[i] / 2);
            dynCapsules[i] = new org.dyn4j.geometry.Capsule(2 * a[i] + b[i], b[i]);
            cT[i] = new Transform();
            cT[i].setTranslation(x[i] + a[i], y[i]);
            float angle = (float) (rnd.nextDouble() * Math.PI);
            turned[i] = new Ellipse(x[i], y[i], a[i], b[i], angle);
            tT[i] = new Transform();
            tT[i].setRotation(angle);
            tT[i].setTranslation(x[i], y[i]);
            // A box a by b with its corner at the centre.
            boxes[i] = new Rect(x[i], y[i], a[i], b[i]);
            dynBoxes[i] = new Rectangle(a[i], b[i]);
            bT[i] = new Transform();
            bT[i].setTranslation(x[i] + a[i] / 2, y[i] + b[i] / 2);
        }
        for (int i = 0; i <= N; i++) {
            float[] xy = new float[16];
            for (int k = 0; k < 8; k++) {
                xy[2 * k] = x[i] + (float) (b[i] * Math.cos(Math.PI * k / 4));
                xy[2 * k + 1] = y[i] + (float) (b[i] * Math.sin(Math.PI * k / 4));
            }
            octagons[i] = Polygon.of(xy);
        }
        for (int i = 0; i <= N; i++) {
            // every kind in turn: the shape calls' dispatch when a loop sees them all
            hitbox.Shape[] kinds = {circles[i], boxes[i], octagons[i], capsules[i], ellipses[i], turned[i]};
            mixed[i] = kinds[i % kinds.length];
        }
        for (int i = 0; i < N; i++) {
            // Towards the next octagon, past its centre: most of them hit.
            vx[i] = 1.5f * (x[i + 1] - x[i]);
            vy[i] = 1.5f * (y[i + 1] - y[i]);
        }
        bladeT.setTranslation(200, 200);
        postT.setTranslation(242, 242);
    }

    @Benchmark
    public int ellipseEllipse_hitbox() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (ellipses[i].overlaps(ellipses[i + 1])) {
                n++;
            }
        }
        return n;
    }

    @Benchmark
    public int ellipseEllipse_dyn4j() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (gjk.detect(dynEllipses[i], eT[i], dynEllipses[i + 1], eT[i + 1])) {
                n++;
            }
        }
        return n;
    }

    @Benchmark
    public int ellipseCircle_hitbox() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (ellipses[i].overlaps(circles[i + 1])) {
                n++;
            }
        }
        return n;
    }

    @Benchmark
    public int ellipseCircle_dyn4j() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (gjk.detect(dynEllipses[i], eT[i], dynCircles[i + 1], eT[i + 1])) {
                n++;
            }
        }
        return n;
    }

    @Benchmark
    public int capsuleCapsule_hitbox() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (capsules[i].overlaps(capsules[i + 1])) {
                n++;
            }
        }
        return n;
    }

    @Benchmark
    public int capsuleCapsule_dyn4j() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (gjk.detect(dynCapsules[i], cT[i], dynCapsules[i + 1], cT[i + 1])) {
                n++;
            }
        }
        return n;
    }

    @Benchmark
    public int capsuleCircle_hitbox() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (capsules[i].overlaps(circles[i + 1])) {
                n++;
            }
        }
        return n;
    }

    @Benchmark
    public int capsuleCircle_dyn4j() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (gjk.detect(dynCapsules[i], cT[i], dynCircles[i + 1], eT[i + 1])) {
                n++;
            }
        }
        return n;
    }

    @Benchmark
    public double ellipseContact_hitbox() {
        double s = 0;
        for (int i = 0; i < N; i++) {
            Contact c = ellipses[i].contact(ellipses[i + 1]);
            s += c == null ? 0 : c.depth();
        }
        return s;
    }

    @Benchmark
    public double ellipseContact_dyn4j() {
        double s = 0;
        Penetration p = new Penetration();
        for (int i = 0; i < N; i++) {
            if (gjk.detect(dynEllipses[i], eT[i], dynEllipses[i + 1], eT[i + 1], p)) {
                s += p.getDepth();
            }
        }
        return s;
    }

    @Benchmark
    public double capsuleContact_hitbox() {
        double s = 0;
        for (int i = 0; i < N; i++) {
            Contact c = capsules[i].contact(capsules[i + 1]);
            s += c == null ? 0 : c.depth();
        }
        return s;
    }

    @Benchmark
    public double capsuleContact_dyn4j() {
        double s = 0;
        Penetration p = new Penetration();
        for (int i = 0; i < N; i++) {
            if (gjk.detect(dynCapsules[i], cT[i], dynCapsules[i + 1], cT[i + 1], p)) {
                s += p.getDepth();
            }
        }
        return s;
    }

    /** Circle i against circle i + 1 asked of the shapes: {@code Circle.overlaps(Circle)}'s dispatch and fast path. */
    @Benchmark
    public int circleCircle_shape() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (circles[i].overlaps(circles[i + 1])) {
                n++;
            }
        }
        return n;
    }

    /** Box i against box i + 1 asked of the shapes: {@code Rect.overlaps(Rect)}'s dispatch. */
    @Benchmark
    public int rectRect_shape() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (boxes[i].overlaps(boxes[i + 1])) {
                n++;
            }
        }
        return n;
    }

    /** Every kind against the next kind, asked of the shapes: the dispatch when the receiver's kind varies. */
    @Benchmark
    public int mixed_shape() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (mixed[i].overlaps(mixed[i + 1])) {
                n++;
            }
        }
        return n;
    }

    /** Every kind's point test and bounding box, asked of the shapes. */
    @Benchmark
    public float mixedContainsBounds_shape() {
        float s = 0;
        for (int i = 0; i < N; i++) {
            s += mixed[i].contains(x[i + 1], y[i + 1]) ? 1 : 0;
            s += mixed[i].bounds().w();
        }
        return s;
    }

    /** Turned ellipses (each by its own angle) against the next: the other shape taken into the ellipse's frame. */
    @Benchmark
    public int turnedEllipseEllipse_hitbox() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (turned[i].overlaps(turned[i + 1])) {
                n++;
            }
        }
        return n;
    }

    @Benchmark
    public int turnedEllipseEllipse_dyn4j() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (gjk.detect(dynEllipses[i], tT[i], dynEllipses[i + 1], tT[i + 1])) {
                n++;
            }
        }
        return n;
    }

    /** A straight time of impact: each ellipse moving (60, 40) into the next one's box. */
    @Benchmark
    public float ellipseSweep_hitbox() {
        float s = 0;
        for (int i = 0; i < N; i++) {
            Hit h = Sweep.timeOfImpact(ellipses[i], 60, 40, boxes[i + 1]);
            s += h == null ? 2 : h.t();
        }
        return s;
    }

    @Benchmark
    public double ellipseSweep_dyn4j() {
        double s = 0;
        Vector2 v = new Vector2(60, 40), still = new Vector2(0, 0);
        for (int i = 0; i < N; i++) {
            TimeOfImpact toi = new TimeOfImpact();
            s += ca.getTimeOfImpact(dynEllipses[i], eT[i], v, 0, dynBoxes[i + 1], bT[i + 1], still, 0, toi) ? toi.getTime() : 2;
        }
        return s;
    }

    /** Ellipse i against capsule i + 1. */
    @Benchmark
    public int ellipseCapsule_hitbox() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (ellipses[i].overlaps(capsules[i + 1])) {
                n++;
            }
        }
        return n;
    }

    /** Octagon i moving (no turn, then a turn of 1 radian about its centre) towards octagon i + 1. */
    @Benchmark
    public float turningPoly8_hitbox() {
        float s = 0;
        for (int i = 0; i < N; i++) {
            Hit h = Sweep.turningTimeOfImpact(octagons[i], x[i], y[i], vx[i], vy[i], 0, octagons[i + 1]);
            s += h == null ? 2 : h.t();
        }
        return s;
    }

    @Benchmark
    public float turningPoly8Turn_hitbox() {
        float s = 0;
        for (int i = 0; i < N; i++) {
            Hit h = Sweep.turningTimeOfImpact(octagons[i], x[i], y[i], vx[i], vy[i], 1, octagons[i + 1]);
            s += h == null ? 2 : h.t();
        }
        return s;
    }

    /** One turning time of impact: a blade turning a quarter turn into a small post. */
    @Benchmark
    public float turningBlade_hitbox() {
        Hit h = Sweep.turningTimeOfImpact(blade, 200, 200, 0, 0, (float) (Math.PI / 2), post);
        return h == null ? 2 : h.t();
    }

    @Benchmark
    public double turningBlade_dyn4j() {
        TimeOfImpact toi = new TimeOfImpact();
        boolean hit = ca.getTimeOfImpact(dynBlade, bladeT, new Vector2(0, 0), Math.PI / 2, dynPost, postT, new Vector2(0, 0), 0, toi);
        return hit ? toi.getTime() : 2;
    }
}
