/** A falling square rock, and what the two tests said about it this frame. */
class Rock {
  float x, y, vx, vy;     // its top-left corner, and its speed
  float size = 10;
  int verdict = NOTHING;   // NOTHING, HIT, FALSE_HIT or MISS

  Rock(float x, float y, float vx, float vy) {
    this.x = x;
    this.y = y;
    this.vx = vx;
    this.vy = vy;
  }

  void fall() {
    x += vx;
    y += vy;
  }

  void draw() {
    noStroke();
    fill(colourOf(verdict));
    rect(x, y, size, size);
  }
}
