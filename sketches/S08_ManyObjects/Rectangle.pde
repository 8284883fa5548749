// The tutorial's obstacle class (its Rectangle): where an obstacle is and how big, plus how
// long to show it red after it blocked the box.
class Obstacle {
  float x;
  float y;
  float w;
  float h;
  int litUntil = 0;   // red until the box has moved this many frames

  Obstacle(float x, float y, float w, float h) {
    this.x = x;
    this.y = y;
    this.w = w;
    this.h = h;
  }

  // It blocked the box's move: light up for 12 frames.
  void hit() {
    litUntil = moves + 12;
  }

  boolean lit() {
    return moves < litUntil;
  }

  // Does a box at (bx, by), bw x bh, overlap this obstacle? The rectangle/rectangle test.
  boolean overlaps(float bx, float by, float bw, float bh) {
    return Collide.rectRect(bx, by, bw, bh, x, y, w, h);
  }

  void draw() {
    noStroke();
    fill(lit() ? Palette.HIT : Palette.OBSTACLE);
    rect(x, y, w, h);
  }
}
