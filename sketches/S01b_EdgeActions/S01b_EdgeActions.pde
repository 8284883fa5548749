/**
 * Edges: wrap, next screen, game over
 * Tutorial section 1: Edges
 *
 * Bouncing is one thing to do when the ball reaches an edge; the tutorial names others:
 * teleport it to the other side (Pac-Man), move to the next screen (Zelda), end the game
 * (Pong). The test hardly changes, only what happens next. The tutorial gives no code for
 * these; below they are written as its section 1 writes its ifs, the ball's centre against
 * 0, width, 0 and height, and that code runs by default. Press l for Hitbox's Edges instead:
 * its wrap (Edges.circleWrapX) waits until the ball has wholly left before it brings it in at
 * the other side, so it is never drawn half on each side; its game over tests the ball's edge.
 *
 * Try this: in Pong, add a paddle at the left (another edge, with its own numbers); in
 * Zelda, keep a map of the screens visited; make the ball wrap across but bounce down.
 * Keys: w wrap (Pac-Man), n next screen (Zelda), g game over (Pong), s stop at the edge;
 * space serves again after a game over; l Hitbox's Edges / the written-out ifs; d shows the
 * maths.
 */
import hitbox.*;
import java.util.Set;
import hitbox.processing.*;

// The ball: position, radius and speed (pixels a frame).
float x = 300;
float y = 200;
float r = 24;
float xSpeed = 4.5;
float ySpeed = 3.2;

String action = "wrap";  // what happens at an edge: wrap, next screen, game over, stop
int screenX = 0;         // next screen: which screen of the world we are on
int screenY = 0;
boolean gameOver;        // game over: the ball went out at the left or the right
boolean hitboxDecides;   // l: Hitbox's Edges instead of the written-out ifs
boolean showMaths;       // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  x += xSpeed;
  y += ySpeed;
  // Which edges has the ball gone past? The same question in every mode: the centre against
  // 0, width, 0 and height, as section 1 asks it (Hitbox's Edges asks it of the ball's edge).
  boolean pastEdge = x < 0 || x > width || y < 0 || y > height;
  Set<Side> crossed = Edges.crossed(new Circle(x, y, r), width, height);

  if (action.equals("wrap") && hitboxDecides) {
    x = Edges.circleWrapX(x, r, width);   // wholly out at one side (x - r > width): in at the other
    y = Edges.circleWrapY(y, r, height);
  } else if (action.equals("wrap")) {
    // Pac-Man: past an edge, teleport the ball to the other side of the window.
    if (x > width) {
      x = 0;
    } else if (x < 0) {
      x = width;
    }
    if (y > height) {
      y = 0;
    } else if (y < 0) {
      y = height;
    }
  } else if (action.equals("next screen")) {
    // Zelda: once the centre is off the screen, the next screen comes in, the ball with it.
    if (x > width)  { screenX++; x -= width; }
    if (x < 0)      { screenX--; x += width; }
    if (y > height) { screenY++; y -= height; }
    if (y < 0)      { screenY--; y += height; }
  } else if (action.equals("game over") && hitboxDecides) {
    ySpeed = Edges.bounceY(crossed, ySpeed);
    if (crossed.contains(Side.LEFT) || crossed.contains(Side.RIGHT)) {
      endGame();
    }
  } else if (action.equals("game over")) {
    // Pong: bounce off the top and the bottom; past the left or the right, the game ends.
    if (y < 0 || y > height) {
      ySpeed *= -1;
    }
    if (x < 0 || x > width) {
      endGame();
    }
  } else {
    // Stop: stay at the edge it reached (Edges.circleClampX puts it back just inside).
    if (crossed.contains(Side.LEFT) || crossed.contains(Side.RIGHT)) xSpeed = 0;
    if (crossed.contains(Side.TOP) || crossed.contains(Side.BOTTOM)) ySpeed = 0;
    x = Edges.circleClampX(x, r, width);
    y = Edges.circleClampY(y, r, height);
  }

  drawScene();
  noStroke();
  boolean atEdge = hitboxDecides ? !crossed.isEmpty() : pastEdge;
  fill(atEdge ? Palette.HIT : Palette.PLAYER);
  circle(x, y, 2 * r);
  if (gameOver) {
    drawGameOver();
  }
  Overlay.label(g, 8, 8, "at an edge: " + action + (hitboxDecides ? ", Hitbox's Edges (l: the ifs)" : ", the ifs (l: Hitbox's Edges)"));
  if (showMaths) {
    drawMaths(crossed);
  }
  Overlay.hint(g, "w wrap   n next screen   g game over   s stop   space: serve   l: Hitbox's Edges   d: the maths");
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key == ' ' && gameOver) {
    serve();
  } else if (key == 'w' || key == 'n' || key == 'g' || key == 's') {
    action = key == 'w' ? "wrap" : key == 'n' ? "next screen" : key == 'g' ? "game over" : "stop";
    if (gameOver) {
      serve();
    } else if (xSpeed == 0 && ySpeed == 0) {  // coming back from a stop: give it a push
      xSpeed = 4.5;
      ySpeed = 3.2;
    }
  }
}
