// The mouse sets a goal; the arrow keys move the player.

void mousePressed() {
  int c = grid.colAt(mouseX);
  int r = grid.rowAt(mouseY);
  if (grid.inGrid(c, r)) {
    goalCol = c;
    goalRow = r;
  }
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == '8') {
    diagonals = !diagonals;
  } else if (key == CODED) {
    setArrow(keyCode, true);
  }
}

void keyReleased() {
  if (key == CODED) {
    setArrow(keyCode, false);
  }
}

void setArrow(int code, boolean down) {
  if (code == LEFT) {
    leftDown = down;
  } else if (code == RIGHT) {
    rightDown = down;
  } else if (code == UP) {
    upDown = down;
  } else if (code == DOWN) {
    downDown = down;
  }
}
