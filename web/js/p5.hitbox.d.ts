// Types of the p5.js add-on (p5.hitbox.js): p5.collide2D's functions, answered by Hitbox.
type V = { x: number; y: number };
export interface CollideFunctions {
  collideRectRect(x: number, y: number, w: number, h: number, x2: number, y2: number, w2: number, h2: number): boolean;
  collideCircleCircle(cx: number, cy: number, d: number, cx2: number, cy2: number, d2: number): boolean;
  collideRectCircle(rx: number, ry: number, rw: number, rh: number, cx: number, cy: number, d: number): boolean;
  collidePointCircle(x: number, y: number, cx: number, cy: number, d: number): boolean;
  collidePointEllipse(x: number, y: number, cx: number, cy: number, dx: number, dy: number): boolean;
  collidePointRect(px: number, py: number, x: number, y: number, w: number, h: number): boolean;
  collidePointLine(px: number, py: number, x1: number, y1: number, x2: number, y2: number, buffer?: number): boolean;
  collideLineCircle(x1: number, y1: number, x2: number, y2: number, cx: number, cy: number, d: number): boolean;
  collideLineLine(x1: number, y1: number, x2: number, y2: number, x3: number, y3: number, x4: number, y4: number,
                  calcIntersection?: boolean): boolean | { x: number | false; y: number | false };
  collideLineRect(x1: number, y1: number, x2: number, y2: number, rx: number, ry: number, rw: number, rh: number,
                  calcIntersection?: boolean): boolean | { left: any; right: any; top: any; bottom: any };
  collidePointPoly(px: number, py: number, vertices: V[]): boolean;
  collideCirclePoly(cx: number, cy: number, d: number, vertices: V[], interior?: boolean): boolean;
  collideRectPoly(rx: number, ry: number, rw: number, rh: number, vertices: V[], interior?: boolean): boolean;
  collideLinePoly(x1: number, y1: number, x2: number, y2: number, vertices: V[]): boolean;
  collidePolyPoly(p1: V[], p2: V[], interior?: boolean): boolean;
  collidePointTriangle(px: number, py: number, x1: number, y1: number, x2: number, y2: number, x3: number, y3: number): boolean;
  collidePointArc(px: number, py: number, ax: number, ay: number, arcRadius: number, arcHeading: number, arcAngle: number,
                  buffer?: number): boolean;
  collideDebug(debug: boolean): void;
  collideRectRectVector(p: V, sz: V, p2: V, sz2: V): boolean;
  collideCircleCircleVector(p1: V, d1: number, p2: V, d2: number): boolean;
  collideRectCircleVector(r: V, sz: V, c: V, d: number): boolean;
  collidePointCircleVector(p: V, c: V, d: number): boolean;
  collidePointEllipseVector(p: V, c: V, sz: V): boolean;
  collidePointRectVector(p: V, r: V, sz: V): boolean;
  collidePointLineVector(p: V, a: V, b: V, buffer?: number): boolean;
  collideLineCircleVector(a: V, b: V, c: V, d: number): boolean;
  collideLineLineVector(a: V, b: V, c: V, d: V, calcIntersection?: boolean): boolean | { x: number | false; y: number | false };
  collideLineRectVector(a: V, b: V, r: V, sz: V, calcIntersection?: boolean): boolean | object;
  collidePointPolyVector(p: V, vertices: V[]): boolean;
  collideCirclePolyVector(c: V, d: number, vertices: V[], interior?: boolean): boolean;
  collideRectPolyVector(r: V, sz: V, vertices: V[], interior?: boolean): boolean;
  collideLinePolyVector(a: V, b: V, vertices: V[]): boolean;
  collidePolyPolyVector(p1: V[], p2: V[], interior?: boolean): boolean;
  collidePointTriangleVector(p: V, a: V, b: V, c: V): boolean;
  collidePointArcVector(p: V, a: V, arcRadius: number, arcHeading: number, arcAngle: number, buffer?: number): boolean;
}
export const functions: CollideFunctions;
/** The add-on for p5 2.x: p5.registerAddon(hitboxAddon). Setup waits for the module. */
export function hitboxAddon(p5: any, fn: any, lifecycles?: any): void;
export function addTo(target: object): void;
/** Resolves to the Hitbox module once its WebAssembly has loaded. */
export const ready: Promise<typeof import('./hitbox.js')>;
