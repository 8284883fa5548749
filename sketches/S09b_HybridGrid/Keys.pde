// The keys: LEFT / RIGHT run while held, UP or SPACE jumps, l and d switch.

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key == ' ') {
    jumpPressed = true;
  } else if (key == CODED) {
    if (keyCode == LEFT) {
      leftDown = true;
    } else if (keyCode == RIGHT) {
      rightDown = true;
    } else if (keyCode == UP) {
      jumpPressed = true;
    }
  }
}

void keyReleased() {
  if (key == CODED) {
    if (keyCode == LEFT) {
      leftDown = false;
    } else if (keyCode == RIGHT) {
      rightDown = false;
    }
  }
}
