// Beyond the tutorial: a platformer on a world of bodies (hitbox.World). The player is a
// character (world.addCharacter): it stands on ground, walks up and down the ramp at the speed
// it is given, climbs low steps (stepHeight) and keeps to the ground going down (snap); after
// each move it says whether it is on the ground and which way the ground faces. Arrow keys or
// A/D run, space or up jumps; a coin is a sensor. Try this: make the ramp steeper than
// maxSlope (45 degrees) and watch it become a wall; add a one-way platform with
// body.oneWay('TOP').
let world, player, coin, vy = 0, coins = 0;
const solids = [[0, 360, 600, 40], [0, 0, 20, 360], [580, 0, 20, 360], [120, 250, 100, 16], [400, 290, 180, 70]];
const ramp = [[260, 360], [400, 290], [400, 360]];   // rises 70 over 140: about 27 degrees

function setup() {
  createCanvas(600, 400);
  world = new hitbox.World();
  for (const [x, y, w, h] of solids) world.add(hitbox.rect(x, y, w, h));
  world.add(hitbox.polygon(ramp));
  // under test it starts nearer the ramp, to be on it when the picture is taken
  player = world.addCharacter(hitbox.rect(window.scriptedRun ? 200 : 60, 300, 24, 36)).maxSlope(45).stepHeight(6).snap(4);
  coin = world.add(hitbox.circle(490, 250, 10)).sensor(true);
}

function draw() {
  background(32);
  let dx = 0;
  if (keyIsDown(LEFT_ARROW) || keyIsDown(65)) dx -= 3;
  if (keyIsDown(RIGHT_ARROW) || keyIsDown(68)) dx += 3;
  if (window.scriptedRun) dx = 3;   // under test: walk right, up the ramp
  vy = Math.min(vy + 0.6, 12);      // gravity
  if (player.onGround && (keyIsDown(32) || keyIsDown(UP_ARROW))) vy = -11;
  player.move(dx, vy, null);
  if (player.onGround || (player.onCeiling && vy < 0)) vy = 0;
  for (const b of world.overlapping(player.body)) {
    if (b.id === coin.id) {
      coins++;
      coin.moveTo(random(60, 540), random(120, 320));
    }
  }
  noStroke();
  fill('#4C7CC3');
  for (const [x, y, w, h] of solids) rect(x, y, w, h);
  beginShape();
  for (const [x, y] of ramp) vertex(x, y);
  endShape(CLOSE);
  fill('#F2C14E');
  circle(coin.x, coin.y, 20);
  fill('#4CC36A');
  const b = player.body.shape.bounds;
  rect(b.x, b.y, b.w, b.h);
  fill(255);
  const n = player.groundNormal;
  text('coins: ' + coins + (player.onGround ? '   on the ground, its normal (' + nf(n.x, 1, 2) + ', ' + nf(n.y, 1, 2) + ')' : '   in the air')
      + (player.onWall ? '   at a wall' : ''), 30, 30);
  window.playerState = { x: b.x, y: b.y, w: b.w, h: b.h, onGround: player.onGround, n };
}
