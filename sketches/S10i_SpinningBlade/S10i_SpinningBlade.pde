/**
 * Spinning blade: a turning sweep against thin walls
 * Beyond the tutorial: fast objects that turn (neither source goes into them)
 *
 * A blade turns fast about its hub: 0.45 radians a frame, so its tip jumps about 67 pixels,
 * far more than the thin posts are wide. Testing only where the blade is at the end of each
 * frame, or sweeping it in a straight line (it does not move, it turns), misses the posts:
 * the blade passes through. Sweep.turningTimeOfImpact(blade, hubX, hubY, vx, vy, turn, post)
 * follows the turn itself, stops the blade where it first touches a post, and the blade
 * bounces back the other way.
 *
 * Try this: turn faster (the turning sweep still catches every post); make a post thinner;
 * move the hub with the mouse while the blade spins.
 * Keys: t switches between the turning sweep and the end-of-frame test, d shows the maths.
 */
import hitbox.*;
import hitbox.processing.*;

float hubX = 300, hubY = 200;
float angle = 0;                 // the blade's angle now
float spin = 0.45;               // radians a frame (the sign is the direction)
float bladeLength = 300, bladeWidth = 6;
boolean turningSweep = true;     // t: the turning sweep, or only the end-of-frame test

Shape[] posts = {
    new Rect(418, 248, 3, 40),
    new Circle(219, 274, 2),
    new Segment(340, 72, 352, 84),
};
int[] flash = new int[3];
int passedThrough;               // posts crossed without a hit (the end-of-frame test's misses)
int hits;                        // posts the turning sweep stopped at
Hit lastHit;                     // this frame's hit, for the overlay
float lastTurn;                  // this frame's turn, for the overlay
boolean showMaths;

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  Polygon blade = bladeAt(angle);
  lastTurn = spin;
  lastHit = null;
  int hitPost = -1;
  if (turningSweep) {
    // The whole idea: where, during this frame's turn, does the blade first touch a post?
    for (int i = 0; i < posts.length; i++) {
      Hit h = Sweep.turningTimeOfImpact(blade, hubX, hubY, 0, 0, spin, posts[i]);
      if (h != null && !h.alreadyOverlapping() && (lastHit == null || h.t() < lastHit.t())) {
        lastHit = h;
        hitPost = i;
      }
    }
  }
  if (lastHit != null) {
    angle += lastHit.t() * spin;  // stop where it touches, and bounce back
    spin = -spin;
    flash[hitPost] = 3;   // red for 3 frames
    hits++;
  } else {
    float before = angle;
    angle += spin;
    // The end-of-frame test: did a post lie in the swept fan without being touched at the end?
    for (int i = 0; i < posts.length; i++) {
      Hit h = Sweep.turningTimeOfImpact(blade, hubX, hubY, 0, 0, angle - before, posts[i]);
      if (h != null && !h.alreadyOverlapping() && !bladeAt(angle).overlaps(posts[i])) {
        passedThrough++;
        flash[i] = 3;
      }
    }
  }

  noStroke();
  for (int i = 0; i < posts.length; i++) {
    fill(flash[i] > 0 ? Palette.HIT : Palette.OBSTACLE);
    stroke(flash[i] > 0 ? Palette.HIT : Palette.OBSTACLE);
    strokeWeight(3);
    Draw.shape(g, posts[i]);
    flash[i] = max(0, flash[i] - 1);
  }
  noStroke();
  fill(turningSweep ? Palette.PLAYER : Palette.ACCENT);
  Draw.shape(g, bladeAt(angle));
  fill(Palette.NEUTRAL);
  circle(hubX, hubY, 14);

  if (showMaths) {
    drawMaths(blade);
  }
  Overlay.hint(g, (turningSweep ? "turning sweep: " + hits + " hits" : "end-of-frame test: " + passedThrough + " posts passed through")
      + "     t: switch     d: show the maths");
}

// The blade at an angle: a long thin rectangle centred on the hub, as a polygon, turned about the hub.
Polygon bladeAt(float angle) {
  return Polygon.of(Rect.centered(hubX, hubY, bladeLength, bladeWidth)).rotated(angle, hubX, hubY);
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 't') {
    turningSweep = !turningSweep;
  }
}
