/**
 * A platformer on a world of bodies
 * Beyond the tutorial: the world, a platformer
 *
 * Section 7 pictures a platforming game like Mario or Sonic the Hedgehog and snaps one
 * player to one ground; section 8 loops over a list of obstacles. A game has many things,
 * each wanting its own answer. Here every one is a body in a World, and one call,
 * world.move(player, vx, vy, filter), moves the player through all of them this frame: it
 * slides along the floor of tiles without catching on the seams between them, stands on the
 * thin platforms from above but jumps up through them from below (oneWay(Side.TOP)), rides the
 * moving platform (a carrier takes along what stands on it), and passes through the coins,
 * which are sensors: reported, never blocking. The collisions it returns say where the player
 * landed (a normal pointing down) or bumped its head; world.step() ends the frame and says
 * which pairs of bodies came into contact, and a coin the player enters is collected.
 *
 * With no key pressed, a demo plays the level; the first arrow key hands the player to you.
 *
 * Try this: make the tiles 10 pixels wide and run along them (no snag at any seam); make a
 * platform oneWay(Side.NONE) and jump into it from below; make the coins solid (sensor(false)).
 * Keys: LEFT and RIGHT run, UP or SPACE jumps, d shows the maths (every body's box, the grid's
 * cells, this frame's contacts and their normals).
 */
import hitbox.*;
import hitbox.processing.*;

float gravity = 0.5;
float jumpSpeed = -11;
float runSpeed = 3;

World world = new World();
Body player;
Body lift;                                     // the moving platform
ArrayList<Body> tiles = new ArrayList<Body>();
ArrayList<Body> platforms = new ArrayList<Body>();
ArrayList<Body> coins = new ArrayList<Body>();
float vy = 0;
boolean onGround = false;
int collected = 0;
float liftSpeed = 1.5;
ArrayList<Collision> met = new ArrayList<Collision>();   // the player's collisions this frame

boolean left, right, jump;                     // the keys held
boolean demo = true;                           // until an arrow key is pressed

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
  // The floor: a row of tiles, each its own body, and two on top of it at the right.
  for (int x = 0; x < width; x += 40) {
    tiles.add(world.add(new Rect(x, 360, 40, 40)));
  }
  tiles.add(world.add(new Rect(520, 320, 40, 40)));
  tiles.add(world.add(new Rect(560, 320, 40, 40)));
  // The window's sides.
  world.add(new Rect(-40, -400, 40, 800));
  world.add(new Rect(width, -400, 40, 800));
  // Platforms: stood on from above, jumped through from below and from the sides.
  platforms.add(world.add(new Rect(50, 275, 110, 10)).oneWay(Side.TOP));
  platforms.add(world.add(new Rect(420, 235, 100, 10)).oneWay(Side.TOP));
  platforms.add(world.add(new Rect(210, 190, 100, 10)).oneWay(Side.TOP));
  // The moving platform carries what stands on it; it is one-way too.
  lift = world.add(new Rect(160, 295, 80, 12)).carrier(true).oneWay(Side.TOP);
  placeCoins();
  player = world.add(new Rect(20, 300, 18, 26));
}

void placeCoins() {
  float[][] at = {{110, 255}, {300, 342}, {560, 302}, {470, 215}, {260, 170}, {330, 275}};
  for (float[] p : at) {
    coins.add(world.add(new Circle(p[0], p[1], 7)).sensor(true));
  }
}

void draw() {
  // The moving platform: there and back, through nothing (it ignores everything), carrying
  // what stands on it.
  if (lift.x() > 400 || lift.x() < 200) {
    liftSpeed = -liftSpeed;
  }
  world.move(lift, liftSpeed, 0, (me, other) -> null);

  if (demo) {
    playDemo();   // Demo.pde: presses the keys for you
  }
  float vx = (right ? runSpeed : 0) - (left ? runSpeed : 0);
  if (jump && onGround) {
    vy = jumpSpeed;
  }
  vy = min(vy + gravity, 12);
  // One call moves the player through every body, each as the filter says.
  met.clear();
  met.addAll(world.move(player, vx, vy, (me, other) -> Reaction.SLIDE));
  onGround = false;
  for (Collision c : met) {
    if (c.reaction() == Reaction.SLIDE && c.ny() > 0) {
      onGround = true;   // landed: the normal points down, into what it stands on
      vy = 0;
    } else if (c.reaction() == Reaction.SLIDE && c.ny() < 0) {
      vy = 0;            // bumped its head
    }
  }
  // The frame ends: which pairs came into contact? A coin the player enters is collected.
  for (BodyEvent e : world.step()) {
    if (e.kind() == BodyEvent.Kind.ENTER && e.involves(player) && coins.contains(e.other(player))) {
      Body coin = e.other(player);
      coins.remove(coin);
      world.remove(coin);
      collected++;
    }
  }
  if (coins.isEmpty()) {
    placeCoins();   // all collected: a new round
  }
  drawScene();
}

void drawScene() {
  background(Palette.BACKGROUND);
  noStroke();
  fill(Palette.OBSTACLE);
  for (Body t : tiles) {
    Draw.shape(g, t.shape());
  }
  stroke(Palette.BACKGROUND);   // the seams between the tiles
  noFill();
  for (Body t : tiles) {
    Draw.shape(g, t.shape());
  }
  noStroke();
  fill(Palette.NEUTRAL);
  for (Body p : platforms) {
    Draw.shape(g, p.shape());
  }
  fill(Palette.MISS);
  Draw.shape(g, lift.shape());
  fill(Palette.ACCENT);
  for (Body c : coins) {
    Draw.shape(g, c.shape());
  }
  fill(Palette.PLAYER);
  Draw.shape(g, player.shape());
  drawMaths();   // Maths.pde
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
    return;
  }
  if (key == CODED || key == ' ') {
    if (demo) {
      demo = false;
      left = right = jump = false;
    }
    setKey(true);
  }
}

void keyReleased() {
  if (!demo) {
    setKey(false);
  }
}

void setKey(boolean down) {
  if (key == ' ' || keyCode == UP) {
    jump = down;
  } else if (keyCode == LEFT) {
    left = down;
  } else if (keyCode == RIGHT) {
    right = down;
  }
}
