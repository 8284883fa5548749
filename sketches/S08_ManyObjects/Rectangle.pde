// The tutorial's Rectangle class, with its field names: where an obstacle is and how big,
// plus how long to show it red after it flipped the box's speed.
class Rectangle {
  float x;
  float y;
  float rectWidth;
  float rectHeight;
  int litUntil = 0;   // red until the box has moved this many frames

  Rectangle(float x, float y, float rectWidth, float rectHeight) {
    this.x = x;
    this.y = y;
    this.rectWidth = rectWidth;
    this.rectHeight = rectHeight;
  }

  // It blocked the box's move: light up for 12 frames.
  void hit() {
    litUntil = moves + 12;
  }

  boolean lit() {
    return moves < litUntil;
  }

  // Does a box at (bx, by), bw x bh, overlap this rectangle? The rectangle/rectangle test.
  boolean overlaps(float bx, float by, float bw, float bh) {
    return Collide.rectRect(bx, by, bw, bh, x, y, rectWidth, rectHeight);
  }
}
