// The mouse sets a goal; the keys switch modes, and move the player in pixels or with l.

void mousePressed() {
  int c = grid.colAt(mouseX);
  int r = grid.rowAt(mouseY);
  if (grid.inGrid(c, r)) {
    goalCol = c;
    goalRow = r;
  }
}

// Every key but section 9's arrows (the first tab): l, p, m, d, and the arrows in pixel mode
// or with Grid.canMove.
void otherKeys() {
  if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key == 'd') {
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

// Cell mode with l: one step along the map, if Grid.canMove says the cell next door can be
// walked into.
void step(int dc, int dr) {
  if (grid.canMove(playerIndexX, playerIndexY, dc, dr)) {
    playerIndexX += dc;
    playerIndexY += dr;
    placeBox();
  }
}
