// The mouse sets a goal; the keys move the player and switch modes.

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
  } else if (key == 'p') {
    pixelMode = !pixelMode;
    placeBox();  // back to the centre of the cell it is in
  } else if (key == 'm') {
    fromPicture = !fromPicture;
    loadTown();
  } else if (key == CODED) {
    if (pixelMode) {
      setArrow(keyCode, true);
    } else if (keyCode == UP) {
      step(0, -1);
    } else if (keyCode == DOWN) {
      step(0, 1);
    } else if (keyCode == LEFT) {
      step(-1, 0);
    } else if (keyCode == RIGHT) {
      step(1, 0);
    }
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

// Cell mode: one step along the map, if the cell next door can be walked into.
void step(int dc, int dr) {
  if (grid.canMove(playerCol, playerRow, dc, dr)) {
    playerCol += dc;
    playerRow += dr;
    placeBox();
  }
}
