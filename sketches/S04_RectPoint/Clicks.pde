// A ring where the last click landed, fading out: white if it counted, grey if it missed.

float lastClickX = -100;
float lastClickY = -100;
boolean lastCounted;
int lastClickFrame = -1000;

void rememberClick(boolean counted) {
  lastClickX = mouseX;
  lastClickY = mouseY;
  lastCounted = counted;
  lastClickFrame = frameCount;
}

void drawLastClick() {
  int age = frameCount - lastClickFrame;
  if (age > 60) {
    return;
  }
  noFill();
  stroke(lastCounted ? Palette.NEUTRAL : Palette.OBSTACLE, 255 - age * 4);
  strokeWeight(2);
  circle(lastClickX, lastClickY, 14 + age / 2);
}
