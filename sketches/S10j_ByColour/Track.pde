// The track, drawn once into an image, and the keys that drive the car.

// Grass everywhere, a loop of road with a start line, and a wall round the window.
PGraphics drawTrack() {
  PGraphics t = createGraphics(width, height);
  t.noSmooth();             // exact colours: no blended pixels on the edges
  t.beginDraw();
  t.background(GRASS);
  t.noFill();
  t.stroke(ROAD);
  t.strokeWeight(64);
  t.strokeJoin(ROUND);
  t.beginShape();
  t.vertex(120, 320);
  t.vertex(480, 320);
  t.vertex(540, 260);
  t.vertex(540, 120);
  t.vertex(470, 70);
  t.vertex(370, 80);
  t.vertex(300, 160);
  t.vertex(230, 80);
  t.vertex(130, 70);
  t.vertex(60, 130);
  t.vertex(60, 260);
  t.endShape(CLOSE);
  t.noStroke();
  t.fill(#F2F2F2);          // the start line: not grass, so it drives like road
  t.rect(236, 288, 6, 64);
  t.fill(WALL);
  t.rect(0, 0, width, 10);
  t.rect(0, 0, 10, height);
  t.rect(width - 10, 0, 10, height);
  t.rect(0, height - 28, width, 28);   // its lower part lies under the key hint
  t.endDraw();
  return t;
}

boolean upKey, downKey, leftKey, rightKey;

// Up speeds up, down brakes and then reverses, nothing pressed rolls to a stop. Returns the
// turn: in proportion to the speed, so the car cannot turn on the spot.
float drive() {
  if (upKey) {
    speed += 0.12;
  } else if (downKey) {
    speed -= 0.2;
  } else {
    speed *= 0.97;
  }
  float turn = 0.05 * constrain(speed / 2, -1, 1);
  if (leftKey) {
    return -turn;
  }
  return rightKey ? turn : 0;
}

void keyPressed() {
  setKey(true);
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'r') {
    startAgain();
  }
}

void keyReleased() {
  setKey(false);
}

void setKey(boolean down) {
  if (key == CODED) {
    if (keyCode == UP) {
      upKey = down;
    } else if (keyCode == DOWN) {
      downKey = down;
    } else if (keyCode == LEFT) {
      leftKey = down;
    } else if (keyCode == RIGHT) {
      rightKey = down;
    }
  }
}
