/**
 * Collision by colour: a car on a drawn track
 * Tutorial section 10: Collision by colour (named by the video)
 *
 * Among the tricks the video on rectangle collision names for shapes too complex for simple
 * tests is "detecting collision by colour". A racing game can read its track that way, and
 * this sketch does: the track is only a picture (grass, road, a wall round the edge), and the
 * car asks the canvas what colour is under each of its four wheels with get(), before the car
 * itself is drawn. Every wheel on the grass takes some of its top speed away, and wall colour
 * under a wheel means stop. It reads where the wheels WOULD be after this frame's move, as
 * section 6 looks before it moves, so no wheel ever ends up on the wall.
 *
 * Where Hitbox differs: it has no call for this, because there is no shape to test: the
 * colours are the sketch's own drawing, so the test is get() and ==. The library only places
 * the wheels (the car's corners: its rectangle as a polygon, turned). The track is drawn
 * without smoothing, so every pixel is exactly one of its colours; a smoothed edge would be
 * a blend that matches none.
 *
 * Try this: draw a puddle in another colour that makes the car skid; read the colour after
 * drawing the car and see the test find the car itself.
 * Keys: arrows drive (up faster, down brakes and reverses, left and right steer), r back to
 * the start, d shows the maths (the points read and their colours).
 */
import hitbox.*;
import hitbox.processing.*;

color GRASS = #4C9A45;
color ROAD = #5B5F66;
color WALL = #B5523B;
PGraphics track;          // the picture the car drives on (Track.pde)

float x, y;               // the car's centre
float angle;              // where it points, in radians (0: to the right)
float speed;              // pixels a frame along that direction; negative in reverse
float carLength = 28;
float carWidth = 16;
Polygon wheels;                 // where the wheels were read this frame
color[] under = new color[4];   // and the colour found under each
int wheelsOnGrass;
boolean hitWall;
float topSpeed = 4;

void setup() {
  size(600, 400);
  track = drawTrack();
  startAgain();
}

void startAgain() {
  x = 200;
  y = 320;
  angle = 0;
  speed = 0;
}

void draw() {
  image(track, 0, 0);       // the canvas holds only the track now
  float turn = drive();     // the arrow keys: speed, and how far to turn (Track.pde)

  // Look before you move: where would the car be, and what colour is under its wheels there?
  float nextAngle = angle + turn;
  float nextX = x + cos(nextAngle) * speed, nextY = y + sin(nextAngle) * speed;
  wheels = Polygon.of(Rect.centered(nextX, nextY, carLength, carWidth)).rotated(nextAngle, nextX, nextY);
  wheelsOnGrass = 0;
  hitWall = false;
  for (int i = 0; i < 4; i++) {
    under[i] = get(round(wheels.x(i)), round(wheels.y(i)));
    if (under[i] == GRASS) {
      wheelsOnGrass++;
    }
    if (under[i] == WALL) {
      hitWall = true;
    }
  }
  if (hitWall) {
    speed = 0;              // a wall: stop, and do not turn into it
  } else {
    angle = nextAngle;
    x += cos(angle) * speed;
    y += sin(angle) * speed;
  }

  // The grass slows it down: each wheel on it takes 0.75 off the top speed.
  topSpeed = 4 - 0.75 * wheelsOnGrass;
  if (speed > topSpeed) {
    speed = max(topSpeed, speed - 0.2);
  }
  speed = max(speed, -topSpeed / 2);

  drawCar();                // Maths.pde, with the overlay
}
