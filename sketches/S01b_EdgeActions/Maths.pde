// The scene for each action, the game over and the serve, and the "show the maths" overlay.

// Each screen of the next-screen world has its own ground colour.
color[] grounds = {#1E2A22, #2A2620, #1E2634, #2C2030};

/** The background: a screen of the world, Pong's court, or the plain window. */
void drawScene() {
  if (action.equals("next screen")) {
    background(grounds[Math.floorMod(screenX + 2 * screenY, grounds.length)]);
    // Rocks and bushes from the screen's own seed: the same screen always looks the same.
    randomSeed(screenX * 7919 + screenY * 104729);
    noStroke();
    for (int i = 0; i < 9; i++) {
      fill(random(1) < 0.5 ? Palette.OBSTACLE : Palette.MISS, 70);
      circle(random(width), random(40, height - 30), random(24, 70));
    }
    Overlay.labelBeside(g, width - 8, 16, -1, 0, "screen " + screenX + ", " + screenY, Overlay.TEXT);
  } else if (action.equals("game over")) {
    background(Palette.BACKGROUND);
    // Pong's court: walls at the top and the bottom, the goal lines at the left and the right.
    stroke(Palette.NEUTRAL);
    strokeWeight(6);
    line(0, 0, width, 0);
    line(0, height, width, height);
    stroke(Palette.HIT);
    line(0, 0, 0, height);
    line(width, 0, width, height);
    Overlay.guide(g, width / 2, 0, width / 2, height);
  } else {
    background(Palette.BACKGROUND);
  }
}

/** The ball went out at the left or the right: it stops, and GAME OVER is written. */
void endGame() {
  gameOver = true;
  xSpeed = 0;
  ySpeed = 0;
}

/** Serves again: the ball from the middle, to the side it did not go out of. */
void serve() {
  gameOver = false;
  xSpeed = x > width / 2 ? -4.5 : 4.5;
  ySpeed = 3.2;
  x = width / 2;
  y = height / 2;
}

void drawGameOver() {
  fill(Palette.NEUTRAL);
  textAlign(CENTER, CENTER);
  textSize(48);
  text("GAME OVER", width / 2, height / 2 - 20);
  textSize(16);
  text("the ball went out at the " + (x > width / 2 ? "right" : "left") + "     space: serve again", width / 2, height / 2 + 24);
}

/** Where the ball's edges are, the edges it has crossed, and the rule of this action. */
void drawMaths(Set<Side> crossed) {
  Overlay.guide(g, x - r, y, 0, y);
  Overlay.guide(g, x + r, y, width, y);
  Overlay.guide(g, x, y - r, x, 0);
  Overlay.guide(g, x, y + r, x, height);
  String rule;
  if (action.equals("wrap") && !hitboxDecides) {
    rule = "the centre past the right, x > width (" + Overlay.number(x) + " > " + width + "): x = 0;\n"
        + "past the left, x < 0: x = width; the same down the page";
  } else if (action.equals("wrap")) {
    rule = "wholly out at the right, x - r > width (" + Overlay.number(x - r) + " > " + width + "),\n"
        + "it comes in at the left, at x = -r; the same at every edge (Edges.circleWrapX/Y)";
    // Where it is coming in (or going out) on the other side: the same ball, one loop away.
    float loop = width + 2 * r;
    noFill();
    stroke(Overlay.GUIDE);
    strokeWeight(1.5);
    circle(x > width / 2 ? x - loop : x + loop, y, 2 * r);
  } else if (action.equals("next screen")) {
    rule = "the centre off the screen at the right, x > width: the next screen comes in,\n"
        + "screenX + 1, and x - width; the same at every edge. The centre now: ("
        + Overlay.number(x) + ", " + Overlay.number(y) + ")";
  } else if (action.equals("game over") && !hitboxDecides) {
    rule = "top, bottom: y < 0 || y > height (" + Overlay.number(y) + "): ySpeed *= -1\n"
        + "left, right: x < 0 || x > width (" + Overlay.number(x) + "): game over";
  } else if (action.equals("game over")) {
    rule = "top, bottom: y - r < 0, y + r > height (" + Overlay.number(y - r) + ", " + Overlay.number(y + r) + "): bounce\n"
        + "left, right: x - r < 0, x + r > width (" + Overlay.number(x - r) + ", " + Overlay.number(x + r) + "): game over";
  } else {
    rule = "an edge crossed: that speed = 0, and the ball put back\n"
        + "inside: x kept between r and width - r (Edges.circleClampX)";
  }
  Overlay.label(g, 8, 30, "crossed: " + (crossed.isEmpty() ? "NONE" : crossed) + "\n" + rule,
      crossed.isEmpty() ? Overlay.MISS : Overlay.HIT);
}
