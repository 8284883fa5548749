// The demo: with no key pressed, it presses the keys for you, step by step. Each step walks
// to an x, or jumps (and waits to land), or waits for the moving platform to come near.

// {kind, x}: kind 0 walk to x, 1 jump (holding the direction to x), 2 wait until the moving
// platform's middle is within 10 pixels of x.
float[][] demoSteps = {
  {0, 70}, {1, 70}, {0, 112},      // down the slope, up through the low platform; its coin
  {2, 203}, {0, 215},              // wait for the moving platform, step down onto it
  {2, 380}, {1, 450}, {0, 470},    // ride it (its coin), jump to the right platform; its coin
  {0, 560},                        // off its end onto the stairs, up to the top; its coin
  {0, 300},                        // down the stairs to the floor; its coin
  {2, 300}, {1, 300},              // wait for the moving platform, jump up through it
  {2, 260}, {1, 262},              // ride it under the high platform, up through that; its coin
  {0, 40}                          // off its end, up the slope, back to the start
};
int demoStep = 0;
boolean demoAirborne = false;

void playDemo() {
  float[] s = demoSteps[demoStep];
  float x = player.body().pivotX();
  boolean onGround = player.onGround();
  left = false;
  right = false;
  jump = false;
  boolean done = false;
  if (s[0] == 0) {
    right = x < s[1] - 1.5;
    left = x > s[1] + 1.5;
    done = !left && !right && onGround;
    jump = onGround && (left || right) && player.onWall();
  } else if (s[0] == 1) {
    right = x < s[1] - 1.5;
    left = x > s[1] + 1.5;
    if (!demoAirborne) {
      jump = onGround;          // jump once it stands on something
      demoAirborne = onGround;
    } else if (onGround) {      // and wait to land
      demoAirborne = false;
      done = true;
    }
  } else {
    done = abs(lift.pivotX() - s[1]) < 10;
  }
  if (done) {
    demoStep = (demoStep + 1) % demoSteps.length;
  }
}
