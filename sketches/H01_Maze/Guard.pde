// A guard walks its beat, corner to corner along the cheapest route, and sees the player
// when the player is within guardView pixels and no building is in the way.
class Guard {
  int[][] beat;
  int next = 1;        // the beat corner it is heading for
  int[] route = new int[0];
  int step = 0;        // the route cell it is heading for
  float x;
  float y;
  float speed = 1.2;
  boolean seeing = false;

  Guard(int[][] beat) {
    this.beat = beat;
    x = grid.cellCenterX(beat[0][0]);
    y = grid.cellCenterY(beat[0][1]);
    plan();
  }

  int col() {
    return grid.colAt(x);
  }

  int row() {
    return grid.rowAt(y);
  }

  // The route from where it stands to the next corner of its beat (none if the corner is
  // off the map or in a building: then it stands still).
  void plan() {
    int[] corner = beat[next];
    route = grid.inGrid(corner[0], corner[1]) && grid.inGrid(col(), row())
        ? grid.path(col(), row(), corner[0], corner[1], costs) : new int[0];
    step = min(1, route.length - 1);
  }

  void walk() {
    if (route.length == 0) {
      return;
    }
    float tx = grid.cellCenterX(route[step] % grid.cols());
    float ty = grid.cellCenterY(route[step] / grid.cols());
    float d = dist(x, y, tx, ty);
    if (d > speed) {
      x += (tx - x) / d * speed;
      y += (ty - y) / d * speed;
      return;
    }
    x = tx;
    y = ty;
    step++;
    if (step >= route.length) {
      next = (next + 1) % beat.length;
      plan();
    }
  }

  boolean sees(float px, float py) {
    seeing = dist(x, y, px, py) < guardView && grid.lineOfSight(x, y, px, py);
    return seeing;
  }

  void draw() {
    pushStyle();
    stroke(Palette.BACKGROUND);
    strokeWeight(2);
    fill(seeing ? Palette.HIT : #2B2B33);
    float s = grid.cellWidth() * 0.8;
    triangle(x, y - s / 2, x - s / 2, y + s / 2, x + s / 2, y + s / 2);
    popStyle();
  }
}
