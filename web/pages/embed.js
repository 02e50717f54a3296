// The example page's script (embed.html): the World from rbsim.js, stepped once an animation
// frame at the scene's dt, drawn as flat-shaded triangles sorted back to front (painter's
// algorithm) through a pinhole camera aimed at the bodies' bounding box.
// window.rbsimHook is what the browser test reads (tests/web/): the World and a promise that
// resolves once it is built.
"use strict";

const params = new URLSearchParams(location.search);
const sceneName = params.get("scene") || "contact_stacking";
const overrides = params.getAll("set");
const worldIndex = Number(params.get("world") || 0);  // of a scene that compares settings: which World
const canvas = document.getElementById("view");
const context = canvas.getContext("2d");
const statusLine = document.getElementById("status");
let resolveReady, rejectReady;
window.rbsimHook = {ready: new Promise((resolve, reject) => { resolveReady = resolve; rejectReady = reject; })};

// A pinhole camera looking at `target` from `eye`, y up: project(x, y, z) gives [pixel x, pixel
// y, depth]; ray(px, py) the world ray through a pixel, {origin, direction}.
function makeCamera(eye, target) {
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const unit = (a) => { const n = Math.hypot(a[0], a[1], a[2]); return [a[0] / n, a[1] / n, a[2] / n]; };
  const forward = unit(sub(target, eye));
  const right = unit(cross(forward, [0, 1, 0]));
  const up = cross(right, forward);
  const focal = 0.5 * canvas.height / Math.tan(0.5 * 50 * Math.PI / 180);  // 50 degrees vertical field of view
  return {
    project(x, y, z) {
      const d = [x - eye[0], y - eye[1], z - eye[2]];
      const depth = d[0] * forward[0] + d[1] * forward[1] + d[2] * forward[2];
      const u = d[0] * right[0] + d[1] * right[1] + d[2] * right[2];
      const v = d[0] * up[0] + d[1] * up[1] + d[2] * up[2];
      return [0.5 * canvas.width + focal * u / depth, 0.5 * canvas.height - focal * v / depth, depth];
    },
    ray(px, py) {
      const u = px - 0.5 * canvas.width, v = 0.5 * canvas.height - py;
      const direction = [0, 1, 2].map((k) => focal * forward[k] + u * right[k] + v * up[k]);
      return {origin: eye, direction: unit(direction)};
    },
  };
}

// Aims the camera at every vertex's bounding box, from the front, above and to the right.
function frameBodies(world) {
  const low = [Infinity, Infinity, Infinity], high = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < world.bodyCount(); ++i) {
    const p = world.vertices(i);
    for (let k = 0; k < p.length; ++k) {
      low[k % 3] = Math.min(low[k % 3], p[k]);
      high[k % 3] = Math.max(high[k % 3], p[k]);
    }
  }
  const centre = [0, 1, 2].map((k) => 0.5 * (low[k] + high[k]));
  const size = Math.max(1, Math.hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]));
  return makeCamera([centre[0] + 0.5 * size, centre[1] + 0.45 * size, centre[2] + 1.2 * size], centre);
}

function colourOf(i) {
  const hue = (i * 137.508) % 360;  // the golden angle: neighbours get distinct hues
  return [hue, 55, 55];
}

function draw(world, camera, triangles) {
  context.clearRect(0, 0, canvas.width, canvas.height);
  context.lineWidth = 0.6;
  const light = [0.35, 0.85, 0.4];
  const faces = [];
  for (let i = 0; i < world.bodyCount(); ++i) {
    const p = world.vertices(i), t = triangles[i];
    const screen = [];
    for (let k = 0; k < p.length; k += 3) screen.push(camera.project(p[k], p[k + 1], p[k + 2]));
    for (let k = 0; k < t.length; k += 3) {
      const a = t[k], b = t[k + 1], c = t[k + 2];
      const sa = screen[a], sb = screen[b], sc = screen[c];
      if (sa[2] <= 0 || sb[2] <= 0 || sc[2] <= 0) continue;  // behind the camera
      if ((sb[0] - sa[0]) * (sc[1] - sa[1]) - (sb[1] - sa[1]) * (sc[0] - sa[0]) >= 0) continue;  // faces away
      const e1 = [p[3 * b] - p[3 * a], p[3 * b + 1] - p[3 * a + 1], p[3 * b + 2] - p[3 * a + 2]];
      const e2 = [p[3 * c] - p[3 * a], p[3 * c + 1] - p[3 * a + 1], p[3 * c + 2] - p[3 * a + 2]];
      const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
      const shade = Math.max(0, (n[0] * light[0] + n[1] * light[1] + n[2] * light[2]) / (Math.hypot(n[0], n[1], n[2]) || 1));
      faces.push({depth: sa[2] + sb[2] + sc[2], points: [sa, sb, sc], body: i, shade});
    }
  }
  faces.sort((f, g) => g.depth - f.depth);
  for (const f of faces) {
    const [hue, saturation, lightness] = colourOf(f.body);
    context.fillStyle = context.strokeStyle = `hsl(${hue} ${saturation}% ${Math.round(lightness * (0.45 + 0.55 * f.shade))}%)`;
    context.beginPath();
    context.moveTo(f.points[0][0], f.points[0][1]);
    context.lineTo(f.points[1][0], f.points[1][1]);
    context.lineTo(f.points[2][0], f.points[2][1]);
    context.closePath();
    context.fill();
    context.stroke();  // over the antialiased seam between two triangles of one face
  }
}

createRbsim().then((rbsim) => {
  let world = null, camera = null, triangles = [], playing = params.get("paused") !== "1";
  const start = () => {
    if (world) world.delete();
    world = rbsim.World.fromPhase(sceneName, overrides, worldIndex);
    triangles = [];
    for (let i = 0; i < world.bodyCount(); ++i) triangles.push(world.triangles(i));
    camera = frameBodies(world);
    window.rbsimHook.world = world;
  };
  const show = () => {
    draw(world, camera, triangles);
    statusLine.textContent = `${sceneName}: ${world.bodyCount()} bodies, t = ${world.time().toFixed(3)} s, step ${world.stepCount()}`;
  };
  try {
    start();
  } catch (error) {
    statusLine.textContent = String(error.message || error);
    rejectReady(error);
    return;
  }
  const label = rbsim.World.phaseLabels(sceneName, overrides)[worldIndex];
  document.getElementById("title").textContent = `rbsim: ${sceneName}${label ? ` (${label})` : ""}`;
  const playButton = document.getElementById("play");
  const setPlaying = (on) => { playing = on; playButton.textContent = on ? "Pause" : "Play"; };
  setPlaying(playing);
  playButton.onclick = () => setPlaying(!playing);
  document.getElementById("step").onclick = () => { setPlaying(false); world.step(1); show(); };
  document.getElementById("restart").onclick = () => { dragPlane = null; start(); show(); };
  // One step an animation frame: the scene plays at its own dt per frame; a trace of it matches
  // the native program's step for step (the browser test compares them).
  const frame = () => {
    if (playing) world.step(1);
    show();
    requestAnimationFrame(frame);
  };
  // Dragging, as window mode does: a press on a body grabs it with a spring (World.grab), moving
  // the pointer moves the spring's anchor in the plane through the grabbed point facing the
  // camera, releasing ends it. A press on empty space does nothing.
  let dragPlane = null;
  const pointerRay = (event) => {
    const box = canvas.getBoundingClientRect();
    return camera.ray((event.clientX - box.left) * canvas.width / box.width, (event.clientY - box.top) * canvas.height / box.height);
  };
  canvas.addEventListener("pointerdown", (event) => {
    const {origin, direction} = pointerRay(event);
    if (world.grab(...origin, ...direction) < 0) return;
    dragPlane = {point: Array.from(world.grabAnchor()), normal: direction};
    canvas.setPointerCapture(event.pointerId);
  });
  canvas.addEventListener("pointermove", (event) => {
    if (!dragPlane) return;
    const {origin, direction} = pointerRay(event);
    const n = dragPlane.normal;
    const along = direction[0] * n[0] + direction[1] * n[1] + direction[2] * n[2];
    if (Math.abs(along) < 1e-9) return;
    const s = ((dragPlane.point[0] - origin[0]) * n[0] + (dragPlane.point[1] - origin[1]) * n[1] + (dragPlane.point[2] - origin[2]) * n[2]) / along;
    world.moveGrab(origin[0] + s * direction[0], origin[1] + s * direction[1], origin[2] + s * direction[2]);
  });
  const endDrag = () => { if (dragPlane) { world.release(); dragPlane = null; } };
  canvas.addEventListener("pointerup", endDrag);
  canvas.addEventListener("pointercancel", endDrag);
  window.rbsimHook.show = show;
  window.rbsimHook.camera = () => camera;
  show();
  resolveReady(world);
  requestAnimationFrame(frame);
}, (error) => { statusLine.textContent = String(error); rejectReady(error); });
