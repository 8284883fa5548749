// One ball: where it is along its lane, its speed, and what this shot has seen.
class Ball {
  float x;
  float y;
  float vx;
  boolean done;        // stopped at the wall, or left the window: this shot is over
  boolean hitNow;      // its test found the wall this frame
  boolean tunnelled;   // this shot, it got past the wall
  ArrayList<float[]> samples = new ArrayList<float[]>();  // every x it landed on, and 1 if it hit

  Ball(float y) {
    this.y = y;
  }

  void start(float x0, float speed) {
    x = x0;
    vx = speed;
    done = false;
    hitNow = false;
    tunnelled = false;
    samples.clear();
    samples.add(new float[] {x0, 0});
  }

  // After each move: where it landed, and whether its test found the wall.
  void landed(boolean hit) {
    hitNow = hit;
    samples.add(new float[] {x, hit ? 1 : 0});
    tunnelled |= !hit && x > wallX + wallW;
    done = hit || x > width + r;
  }
}
