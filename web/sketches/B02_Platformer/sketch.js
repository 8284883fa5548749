// Beyond the tutorial: a platformer on a world of bodies (hitbox.World). The player slides
// along the ground and the walls; arrow keys or A/D run, space or up jumps; a coin is a
// sensor. Try this: add a one-way platform with body.oneWay('TOP').
let world, player, coin, vy = 0, onGround = false, coins = 0;
const solids = [[0, 360, 600, 40], [0, 0, 20, 360], [580, 0, 20, 360], [150, 280, 120, 20], [340, 210, 120, 20]];

function setup() {
  createCanvas(600, 400);
  world = new hitbox.World();
  for (const [x, y, w, h] of solids) world.add(hitbox.rect(x, y, w, h));
  player = world.add(hitbox.rect(60, 300, 24, 36));
  coin = world.add(hitbox.circle(400, 180, 10)).sensor(true);
}

function draw() {
  background(32);
  let dx = 0;
  if (keyIsDown(LEFT_ARROW) || keyIsDown(65)) dx -= 4;
  if (keyIsDown(RIGHT_ARROW) || keyIsDown(68)) dx += 4;
  if (window.scriptedRun) dx = 3;
  vy = Math.min(vy + 0.6, 12);
  if (onGround && (keyIsDown(32) || keyIsDown(UP_ARROW) || (window.scriptedRun && frameCount % 40 === 0))) vy = -11;
  onGround = false;
  for (const c of world.move(player, dx, vy, null)) {
    if (c.other === coin || c.other.id === coin.id) continue;
    if (c.landed) onGround = true;
    if (c.ny > 0.5 && vy < 0) vy = 0;
  }
  if (onGround) vy = 0;
  for (const b of world.overlapping(player)) {
    if (b.id === coin.id) {
      coins++;
      coin.moveTo(random(60, 540), random(120, 320));
    }
  }
  noStroke();
  fill('#4C7CC3');
  for (const [x, y, w, h] of solids) rect(x, y, w, h);
  fill('#F2C14E');
  circle(coin.x, coin.y, 20);
  fill('#4CC36A');
  const b = player.shape.bounds;
  rect(b.x, b.y, b.w, b.h);
  fill(255);
  text('coins: ' + coins + (onGround ? '   on the ground' : ''), 30, 30);
}
