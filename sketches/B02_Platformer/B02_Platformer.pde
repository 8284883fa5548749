/**
 * A platformer on a world of bodies
 * Beyond the tutorial: the world, a platformer
 *
 * Section 7 pictures a platforming game like Mario or Sonic the Hedgehog and snaps one
 * player to one ground; section 8 loops over a list of obstacles. A game has many things,
 * each wanting its own answer. Here every one is a body in a World, and the player is a
 * CharacterBody: one call, player.move(vx, vy), walks it through all of them this frame. It
 * runs along the floor of tiles without catching on the seams between them, walks up and down
 * the slope at its running speed and stands still on it, climbs the stairs (stepHeight) and
 * keeps to them going down (snap), stands on the thin platforms from above but jumps up through
 * them from below (oneWay(Side.TOP)), rides the moving platform (a carrier takes along what
 * stands on it), and passes through the coins, which are sensors: reported, never blocking.
 * After the move, player.onGround() says it stands on something and player.onCeiling() that it
 * bumped its head; world.step() ends the frame and says which pairs of bodies came into
 * contact, and a coin the player enters is collected.
 *
 * With no key pressed, a demo plays the level; the first arrow key hands the player to you.
 *
 * Try this: make the slope steeper than maxSlope (45 degrees), starting it at (0, 200), and
 * watch the player slide down it; set stepHeight(0) and the stairs are walls; make the tiles 10 pixels wide and run along
 * them (no snag at any seam); make a platform oneWay(Side.NONE) and jump into it from below.
 * Keys: LEFT and RIGHT run, UP or SPACE jumps, d shows the maths (every body's box, the grid's
 * cells, this frame's contacts and their normals, what the player stands on).
 */
import hitbox.*;
import hitbox.processing.*;

float gravity = 0.5;
float jumpSpeed = -11;
float runSpeed = 3;

World world = new World();
CharacterBody player;                          // a body that walks: slopes, steps, ground
Body lift;                                     // the moving platform
Body slope;
ArrayList<Body> tiles = new ArrayList<Body>();
ArrayList<Body> platforms = new ArrayList<Body>();
ArrayList<Body> coins = new ArrayList<Body>();
float vy = 0;
int collected = 0;
float liftSpeed = 1.5;
ArrayList<Collision> met = new ArrayList<Collision>();   // the player's collisions this frame

boolean left, right, jump;                     // the keys held
boolean demo = true;                           // until an arrow key is pressed

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
  // The floor: a row of tiles, each its own body.
  for (int x = 0; x < width; x += 40) {
    tiles.add(world.add(new Rect(x, 360, 40, 40)));
  }
  // The slope at the left, and the stairs at the right: four steps 10 pixels high.
  slope = world.add(Polygon.of(0, 310, 130, 360, 0, 360));
  tiles.add(slope);
  for (int i = 0; i < 4; i++) {
    tiles.add(world.add(new Rect(450 + 25 * i, 350 - 10 * i, 150 - 25 * i, 10)));
  }
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
  // The player climbs steps up to 12 pixels high, and stays on the ground going down them.
  player = world.addCharacter(new Rect(4, 280, 18, 26)).stepHeight(12).snap(12);
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
  if (lift.pivotX() > 400 || lift.pivotX() < 200) {
    liftSpeed = -liftSpeed;
  }
  world.move(lift, liftSpeed, 0, (me, other) -> null);

  if (demo) {
    playDemo();   // Demo.pde: presses the keys for you
  }
  float vx = (right ? runSpeed : 0) - (left ? runSpeed : 0);
  if (jump && player.onGround()) {
    vy = jumpSpeed;
  }
  vy = min(vy + gravity, 12);
  // One call walks the player through every body: along the ground, up the slope and the
  // stairs, through the coins.
  met.clear();
  met.addAll(player.move(vx, vy));
  if (player.onGround() || player.onCeiling()) {
    vy = 0;   // landed, or bumped its head
  }
  // The frame ends: which pairs came into contact? A coin the player enters is collected.
  for (BodyEvent e : world.step()) {
    if (e.kind() == BodyEvent.Kind.ENTER && e.involves(player.body()) && coins.contains(e.other(player.body()))) {
      Body coin = e.other(player.body());
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
  Draw.shape(g, player.body().shape());
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
