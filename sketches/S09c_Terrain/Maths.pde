// The maths: every cell's terrain number, the terrain under the player and the speed it
// gives, and each route's cost added up, cell type by cell type.
void drawMaths() {
  pushStyle();
  textSize(9);
  textAlign(CENTER, CENTER);
  fill(255, 150);
  for (int r = 0; r < grid.rows(); r++) {
    for (int c = 0; c < grid.cols(); c++) {
      text(terrain[r][c], grid.cellCenterX(c), grid.cellCenterY(r));
    }
  }
  noFill();
  stroke(Overlay.GUIDE);
  strokeWeight(2);
  Draw.shape(g, grid.cellRect(playerCol(), playerRow()));
  popStyle();

  int t = terrainUnderPlayer();
  String under = "under the player's centre: col " + playerCol() + ", row " + playerRow()
      + "\nterrain[" + playerRow() + "][" + playerCol() + "] = " + t + " (" + (t == FOREST ? "forest" : "grass") + "): speed " + Overlay.number(speed) + " px a frame"
      + "\ncoins looked at this frame: " + looked + " (in the cells under the player), of " + (placed - collected);
  Overlay.label(g, 8, grid.height() - 100, under + "\n\n" + costLine("shortest", shortest) + "\n" + costLine("cheapest", cheapest),
      t == FOREST ? Overlay.HIT : Overlay.MISS);
}

// "12 grass x 1 + 4 forest x 3 = 24": the cells a route enters, by type, times their cost.
String costLine(String name, int[] route) {
  if (route.length == 0) {
    return name + ": no route";
  }
  int grass = 0;
  int forest = 0;
  int diagonalSteps = 0;
  for (int i = 1; i < route.length; i++) {
    int c = route[i] % grid.cols();
    if (terrain[route[i] / grid.cols()][c] == FOREST) {
      forest++;
    } else {
      grass++;
    }
    if (c != route[i - 1] % grid.cols() && route[i] / grid.cols() != route[i - 1] / grid.cols()) {
      diagonalSteps++;
    }
  }
  return name + ": " + grass + " grass x " + Overlay.number(costs.cost(GRASS)) + " + " + forest + " forest x "
      + Overlay.number(costs.cost(FOREST))
      + (diagonalSteps > 0 ? " (" + diagonalSteps + " diagonal, each x 1.41)" : "")
      + " = " + Overlay.number((float) costs.withDiagonals().costOf(grid, route));
}
