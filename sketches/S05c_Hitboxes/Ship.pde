/**
 * A little rocket, drawn with Processing shapes. Its outline is also kept as library shapes
 * (a Polygon for the body and one for each fin), so it can be tested exactly.
 */
class Ship {
  float x, y;        // the centre of its bounding box
  Polygon body, leftFin, rightFin;

  Ship(float x, float y) {
    this.x = x;
    this.y = y;
    // Points around (0, 0), then moved to (x, y): the nose at the top, the fins at the bottom.
    body = Polygon.of(0, -54, 18, -20, 18, 44, -18, 44, -18, -20).translated(x, y);
    leftFin = Polygon.of(-18, 14, -18, 44, -42, 54).translated(x, y);
    rightFin = Polygon.of(18, 14, 42, 54, 18, 44).translated(x, y);
  }

  /** The exact test: does the rock reach into the body or a fin? */
  boolean touches(Rect rock) {
    return body.overlaps(rock) || leftFin.overlaps(rock) || rightFin.overlaps(rock);
  }

  /** The exact test for a point, for the maths overlay's areas. */
  boolean contains(float px, float py) {
    return body.contains(px, py) || leftFin.contains(px, py) || rightFin.contains(px, py);
  }

  void draw() {
    drawIn(#D8DCE4, #E8504A);
  }

  /** The rocket in two colours: the body's and the fins'. */
  void drawIn(color bodyColour, color finColour) {
    noStroke();
    fill(finColour);
    outline(leftFin);
    outline(rightFin);
    fill(bodyColour);
    outline(body);
    fill(#5AA9F0);
    circle(x, y - 6, 16);   // the window, inside the body
  }

  void outline(Polygon p) {
    beginShape();
    for (int i = 0; i < p.size(); i++) {
      vertex(p.x(i), p.y(i));
    }
    endShape(CLOSE);
  }
}
