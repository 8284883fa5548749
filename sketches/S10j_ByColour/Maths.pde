// The car, the speed line, and the "show the maths" overlay (d): the points read and the
// colours found there.

boolean showMaths = false;
String[] wheelNames = {"rear left", "front left", "front right", "rear right"};

void drawCar() {
  pushMatrix();
  translate(x, y);
  rotate(angle);
  noStroke();
  fill(Palette.PLAYER);
  rect(-carLength / 2, -carWidth / 2, carLength, carWidth, 3);
  fill(30, 40, 60);
  rect(2, -carWidth / 2 + 3, 6, carWidth - 6, 2);   // the windscreen, at the front
  popMatrix();

  if (showMaths) {
    drawMaths();
  }
  Overlay.label(g, 14, 14, "speed " + nf(speed, 1, 1) + "   top speed " + nf(topSpeed, 1, 2)
      + " (" + wheelsOnGrass + (wheelsOnGrass == 1 ? " wheel" : " wheels") + " on the grass)"
      + (hitWall ? "   a wall: stopped" : ""), hitWall || wheelsOnGrass > 0 ? Overlay.HIT : Overlay.TEXT);
  Overlay.hint(g, "arrows: drive   r: back to the start   d: show the maths");
}

String colourName(color c) {
  if (c == GRASS) {
    return "grass";
  } else if (c == ROAD) {
    return "road";
  } else if (c == WALL) {
    return "wall";
  }
  return c == #F2F2F2 ? "start line" : "something else";
}

// Where get() read, as rings round the points, and what it found, with a swatch of each colour.
// The points are where the wheels would be after this frame's move: where they are now,
// unless a wall stopped the car.
void drawMaths() {
  float cx = (wheels.x(0) + wheels.x(2)) / 2;
  float cy = (wheels.y(0) + wheels.y(2)) / 2;
  for (int i = 0; i < 4; i++) {
    readPoint(wheels.x(i), wheels.y(i), under[i]);
    float ox = wheels.x(i) + (wheels.x(i) - cx) * 1.5;   // well clear of the car
    float oy = wheels.y(i) + (wheels.y(i) - cy) * 1.5;
    Overlay.labelCentered(g, ox, oy, "" + i, under[i] == GRASS || under[i] == WALL ? Overlay.HIT : Overlay.TEXT);
  }

  String[] lines = new String[5];
  lines[0] = "get() where the wheels would be,\nbefore the car is drawn:";
  for (int i = 0; i < 4; i++) {
    lines[i + 1] = "         " + i + " " + wheelNames[i] + ": " + colourName(under[i]) + "  " + rgb(under[i]);
  }
  String text = join(lines, "\n") + "\n" + (hitWall ? "a wheel on the wall: stop" : "no wall: move")
      + "\ntop speed = 4 - 0.75 x " + wheelsOnGrass + " on the grass = " + nf(topSpeed, 1, 2);
  // Beside the car, towards the middle of the window, where the infield is.
  float w = labelWidth(text);
  float h = text.split("\n").length * 15 + 4;
  float ux = width / 2 - x;
  float uy = height / 2 - y;
  float len = max(1, dist(0, 0, ux, uy));
  ux /= len;
  uy /= len;
  float reach = w / 2 * abs(ux) + h / 2 * abs(uy) + 18;
  float left = constrain(x + ux * reach - w / 2, 2, width - w - 2);
  float top = constrain(y + uy * reach - h / 2, 2, height - h - 2);
  Overlay.label(g, left, top, text, Overlay.TEXT);
  for (int i = 0; i < 4; i++) {
    stroke(Overlay.TEXT);
    strokeWeight(1);
    fill(under[i]);
    rect(left + 8, top + 2 + (i + 2) * 15 + 3, 14, 10);
  }
}

// How wide Overlay.label draws this text: its longest line at size 12, and 8 pixels.
float labelWidth(String text) {
  pushStyle();
  textSize(12);
  float longest = 0;
  for (String line : text.split("\n")) {
    longest = max(longest, textWidth(line));
  }
  popStyle();
  return longest + 8;
}

// A point get() read: a white ring with the colour it found inside.
void readPoint(float px, float py, color found) {
  stroke(Overlay.TEXT);
  strokeWeight(1.5);
  fill(found);
  circle(px, py, 9);
}

String rgb(color c) {
  return "(" + (int) red(c) + ", " + (int) green(c) + ", " + (int) blue(c) + ")";
}
