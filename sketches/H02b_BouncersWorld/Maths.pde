// The "show the maths" overlay (d): what the world sees (the grid's cells, every body's box,
// this frame's contacts with their normals) and the counts.

boolean showMaths = false;

void drawMaths() {
  if (showMaths) {
    WorldDraw.debug(g, world);
  }
  Overlay.hint(g, "b: bouncers bounce off each other too   d: show the maths (cells, boxes, contacts and their normals)");
  if (!showMaths) {
    return;
  }
  int contacts = world.collisions().size();
  Overlay.label(g, 8, 8, world.size() + " bodies: " + bouncers.size() + " bouncers, " + obstacles.size()
      + " obstacles, 4 walls\nbouncers meet " + (bounceOffEachOther ? "obstacles, walls and each other" : "obstacles and walls (their mask)")
      + "\ncontacts this frame: " + contacts + "   bouncers that hit an obstacle: " + hitsThisFrame + "   so far: " + totalHits);
}
