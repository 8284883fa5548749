/**
 * Separating axis theorem
 * Tutorial section 10: More advanced collision detection
 *
 * The tutorial's section 10 leaves other shapes to "the right math"; the video names the
 * separating axis theorem for convex polygons and rotated rectangles. Two convex shapes are
 * apart exactly when a straight line fits between them. To find one, shine a light across
 * each edge and look at the two shadows on the axis along the edge's normal: if they do not
 * overlap on some axis, that axis separates the shapes; if they overlap on every axis, the
 * shapes overlap. A shadow is a projection: each corner (x, y) lands on the axis (nx, ny) at
 * the dot product x * nx + y * ny, and the shadow runs from the smallest to the largest
 * (shadow() below). The axes are written out too (addAxes below): one per edge, along its
 * normal, the edge's (dx, dy) turned a quarter to (dy, -dx) and divided by its length. The
 * loop looks for the gap, and its answer colours the rectangle; the panel on the right lists
 * and draws the axes. The rectangle turns (a polygon, rotated about its centre); the
 * triangle follows the mouse. The axis drawn beside the shapes is the one with the widest
 * gap, or, while they overlap, the one with the least overlap: the shortest way out.
 *
 * Where Hitbox differs: neither source writes the test out; this code is ours. Hitbox's
 * box.overlaps(mover) runs beside it (l lets it decide): for two convex polygons it asks the
 * same axes, with exact signs in double, so it stays exact where these floats could round; it
 * too counts shadows that only touch as a gap, because touching is not colliding for every
 * pair.
 *
 * Try this: bring a corner of the triangle close to a corner of the rectangle and watch
 * which axes still find a gap; press 4, 5 or 6 for more sides (more axes); press space to
 * stop the turning.
 * Keys: 3-6 the mouse shape's sides, space stops the turning, l box.overlaps(mover)
 * decides / the loop, d shows the maths (the shadows' numbers, the light that casts them).
 */
import hitbox.*;
import hitbox.processing.*;
import java.util.ArrayList;
import java.util.List;

float cx = 280, cy = 215;     // the rectangle's centre
float angle = 0.35;
boolean turning = true;
int sides = 3;

Polygon box, mover;
List<SeparatingAxis.Axis> axes;
boolean overlapping;          // this frame's answer: the loop's, or the library's after l
boolean hitboxSays;           // box.overlaps(mover), beside the loop
boolean hitboxDecides;        // l
int separating = -1;          // the axis with the widest gap, or -1 if there is none
int shown = -1;               // the axis drawn beside the shapes: that one, or the least overlap
boolean showMaths;

void setup() {
  size(840, 440);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  if (turning) {
    angle += 0.006;
  }
  box = Polygon.of(Rect.centered(cx, cy, 170, 90)).rotated(angle, cx, cy);
  mover = Polygon.regular(mouseX, mouseY, 52, sides, -HALF_PI);

  // The theorem as a loop: on each axis, the two shadows [minA, maxA] and [minB, maxB];
  // a gap between them on any one axis means apart (shadows that only touch count as a gap).
  axes = new ArrayList<SeparatingAxis.Axis>();
  addAxes(box);     // every edge's normal, from both shapes
  addAxes(mover);
  separating = -1;
  for (int i = 0; i < axes.size(); i++) {
    SeparatingAxis.Axis a = axes.get(i);
    boolean gap = a.maxA() <= a.minB() || a.maxB() <= a.minA();
    if (gap && (separating < 0 || a.overlap() < axes.get(separating).overlap())) {
      separating = i;   // the widest gap so far
    }
  }
  // No gap on any axis: overlapping. Hitbox's call beside it: the same question.
  hitboxSays = box.overlaps(mover);
  overlapping = hitboxDecides ? hitboxSays : separating < 0;
  shown = separating >= 0 ? separating : leastOverlap();

  noStroke();
  fill(overlapping ? Palette.HIT : Palette.MISS);
  Draw.shape(g, box);
  stroke(Palette.PLAYER);
  strokeWeight(2);
  fill(Palette.PLAYER, 150);
  Draw.shape(g, mover);

  drawAxisInPlace(shown);
  drawPanel();

  String verdict = overlapping
      ? "the shadows overlap on all " + axes.size() + " axes: overlapping"
      : "axis " + (separating + 1) + " separates them: apart";
  Overlay.labelCentered(g, panelX / 2, mouseY > height - 90 ? 18 : height - 36, verdict, overlapping ? Overlay.HIT : Overlay.MISS);
  Overlay.hint(g, "move the triangle     3-6: sides     space: " + (turning ? "stop" : "start")
      + " turning     l: " + (hitboxDecides ? "the loop" : "box.overlaps(mover)") + " decides     d: show the maths");
}

// One axis per edge of p: the edge (dx, dy) turned a quarter, (dy, -dx), made length 1; on
// it, both shapes' shadows.
void addAxes(Polygon p) {
  for (int i = 0; i < p.size(); i++) {
    int next = (i + 1) % p.size();
    float dx = p.x(next) - p.x(i);
    float dy = p.y(next) - p.y(i);
    float length = sqrt(dx * dx + dy * dy);
    if (length > 0) {
      float nx = dy / length;
      float ny = -dx / length;
      float[] shadowA = shadow(box, nx, ny);
      float[] shadowB = shadow(mover, nx, ny);
      axes.add(new SeparatingAxis.Axis(nx, ny, shadowA[0], shadowA[1], shadowB[0], shadowB[1]));
    }
  }
}

// A shape's shadow on the axis (nx, ny): each corner projected onto it with the dot product,
// from the smallest to the largest.
float[] shadow(Polygon p, float nx, float ny) {
  float min = MAX_FLOAT;
  float max = -MAX_FLOAT;
  for (int i = 0; i < p.size(); i++) {
    float along = p.x(i) * nx + p.y(i) * ny;
    min = min(min, along);
    max = max(max, along);
  }
  return new float[] {min, max};
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key >= '3' && key <= '6') {
    sides = key - '0';
  } else if (key == ' ') {
    turning = !turning;
  }
}
