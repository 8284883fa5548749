// Drawing the town, the route and the side panel (the maths overlay is in Maths.pde).

color colourOf(int terrain) {
  return townColours.colorOf(terrain);
}

void drawTown() {
  noStroke();
  for (int r = 0; r < grid.rows(); r++) {
    for (int c = 0; c < grid.cols(); c++) {
      fill(colourOf(grid.get(c, r)));
      Draw.shape(g, grid.cellRect(c, r));
    }
  }
}

void drawRoute() {
  pushStyle();
  noFill();
  stroke(Palette.ACCENT);
  strokeWeight(3);
  beginShape();
  for (int cell : route) {
    vertex(grid.cellCenterX(cell % grid.cols()), grid.cellCenterY(cell / grid.cols()));
  }
  endShape();
  stroke(Palette.HIT);
  noFill();
  circle(grid.cellCenterX(goalCol), grid.cellCenterY(goalRow), grid.cellWidth());
  popStyle();
}

void drawPanel() {
  float x = mapWidth + 12;
  textAlign(LEFT, TOP);
  textSize(14);
  fill(Palette.NEUTRAL);
  text("Town " + grid.cols() + " x " + grid.rows(), x, 10);
  textSize(12);
  text("from " + (fromPicture ? "data/town.png" : "data/town.txt"), x, 30);
  float y = 56;
  String[] names = {"street", "building", "park", "river"};
  for (int t = 0; t < 4; t++) {
    fill(colourOf(t));
    rect(x, y + t * 18, 12, 12);
    fill(Palette.NEUTRAL);
    text(names[t] + (t == BUILDING ? ": solid" : ": costs " + Overlay.number(costs.cost(t))), x + 18, y + t * 18 - 1);
  }
  fill(Palette.ACCENT);
  text(route.length == 0 ? "no route to the goal"
      : "route: " + (route.length - 1) + " steps,\ncost " + Overlay.number((float) costs.costOf(grid, route)), x, 140);
  fill(Palette.NEUTRAL);
  text("moving " + (pixelMode ? "in pixels" : "cell by cell") + "\nplayer: col " + playerIndexX + ", row " + playerIndexY, x, 180);
  fill(seen ? Palette.HIT : Palette.MISS);
  text(seen ? "SEEN by a guard!" : "unseen", x, 220);
  fill(Palette.NEUTRAL);
  text("times seen: " + sightings, x, 238);
}
