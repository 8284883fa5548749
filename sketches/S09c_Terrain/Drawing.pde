// Drawing the terrain, the two routes and the legend (the maths overlay is in Maths.pde).

color grassColour = #5FA84F;
color waterColour = #3D78C8;
color forestColour = #2C5E34;

void drawMap() {
  noStroke();
  for (int r = 0; r < grid.rows(); r++) {
    for (int c = 0; c < grid.cols(); c++) {
      int t = terrain[r][c];
      fill(t == WATER ? waterColour : t == FOREST ? forestColour : grassColour);
      Draw.shape(g, grid.cellRect(c, r));
    }
  }
}

// A route through the centres of its cells, moved a few pixels so two routes lie side by side.
void drawRoute(int[] route, float offset, color colour) {
  pushStyle();
  noFill();
  stroke(colour);
  strokeWeight(3);
  beginShape();
  for (int i = 0; i < route.length; i++) {
    int c = route[i] % grid.cols();
    int r = route[i] / grid.cols();
    vertex(grid.cellCenterX(c) + offset, grid.cellCenterY(r) + offset);
  }
  endShape();
  popStyle();
}

void drawGoal() {
  pushStyle();
  noFill();
  stroke(Palette.HIT);
  strokeWeight(3);
  circle(grid.cellCenterX(goalCol), grid.cellCenterY(goalRow), cell - 4);
  popStyle();
}

void drawLegend() {
  textSize(12);
  textAlign(LEFT, TOP);
  float y = grid.height() + 3;
  fill(Palette.NEUTRAL);
  text(describe("shortest", shortest), 8, y);
  fill(Palette.ACCENT);
  text(describe("cheapest", cheapest), 300, y);
}

String describe(String name, int[] route) {
  if (route.length == 0) {
    return name + ": no route";
  }
  return name + ": " + (route.length - 1) + " steps, time " + Overlay.number((float) costs.withDiagonals().costOf(grid, route));
}
