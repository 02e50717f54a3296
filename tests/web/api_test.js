// The JavaScript API of the browser build (web/src/rbsim_js.cpp) under node: physics read back
// through it, and bad input refused with the native program's message.
//   node --no-experimental-fetch api_test.js SITE_DIR
// Prints one line a check; exits 1 when one fails.
"use strict";
const path = require("path");

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? "ok" : "FAILED"}: ${what}`);
  if (!ok) failures += 1;
}
function throwsWith(f, words) {
  try {
    f();
  } catch (error) {
    return error instanceof Error && words.every((w) => error.message.includes(w)) ? "" : String(error.message || error);
  }
  return "nothing thrown";
}

// A ball dropped from 2 m with v0 = (1, 0, 0), no contact in 0.5 s: with dlm, whose half kicks
// integrate constant gravity exactly, x and y are x0 + v0 t and y0 - g t^2 / 2 to rounding.
const ballScene = JSON.stringify({
  world: {gravity: [0, -9.81, 0], dt: 1 / 60, integrator: "dlm", duration: 1},
  bodies: [{name: "ball", shape: {type: "sphere", radius: 0.25}, mass: 1, position: [0, 2, 0], velocity: [1, 0, 0]}],
});

async function main() {
  const site = process.argv[2];
  const createRbsim = require(path.resolve(site, "rbsim.js"));
  const rbsim = await createRbsim({locateFile: (file) => path.resolve(site, file)});

  const ball = rbsim.World.fromJson(ballScene);
  ball.step(30);
  const x = ball.positions(), q = ball.orientations();
  const t = 30 / 60;
  check(x instanceof Float64Array && x.length === 3 && q.length === 4, "positions and orientations are Float64Arrays of 3 and 4 per body");
  check(Math.abs(x[0] - 1 * t) < 1e-12 && Math.abs(x[1] - (2 - 0.5 * 9.81 * t * t)) < 1e-12,
        `free fall: x = ${x[0]}, y = ${x[1]} m after ${t} s (analytic ${t}, ${2 - 0.5 * 9.81 * t * t})`);
  check(q[0] === 1 && q[1] === 0 && q[2] === 0 && q[3] === 0, "no spin, q stays (1, 0, 0, 0)");
  check(ball.time() === 0.5 && ball.stepCount() === 30 && ball.sceneSteps() === 60, "time, steps taken and the scene's length");
  const v = ball.vertices(0);
  let far = 0;
  for (let k = 0; k < v.length; k += 3) far = Math.max(far, Math.hypot(v[k] - x[0], v[k + 1] - x[1], v[k + 2] - x[2]));
  check(v.length > 0 && Math.abs(far - 0.25) < 1e-9 && ball.triangles(0).length % 3 === 0,
        `the sphere's world vertices lie on its radius about x (${far} m)`);
  ball.delete();

  const overridden = rbsim.World.fromJson(ballScene, ["world.gravity=[0,0,0]"]);
  overridden.step(30);
  check(overridden.positions()[1] === 2, "an override (the native --set) applies: no gravity, y stays 2 m");
  overridden.delete();

  let message = throwsWith(() => rbsim.World.fromScene("contact_solvers"), ["contact_solvers.json", "compare", "World.fromPhase"]);
  check(message === "", `fromScene refuses a compared scene, naming the file and fromPhase ${message}`);
  const labels = rbsim.World.phaseLabels("contact_solvers");
  check(labels.length === 2 && labels[0] === "PGS" && labels[1] === "soft step", `a compared scene's Worlds: ${labels.join(", ")}`);
  check(rbsim.World.phaseLabels("contact_response").length === 1, "a plain scene is one World");
  const pgs = rbsim.World.fromPhase("contact_solvers", [], 0), soft = rbsim.World.fromPhase("contact_solvers", [], 1);
  const sameStart = pgs.stateHash() === soft.stateHash();
  pgs.step(120);
  soft.step(120);
  check(sameStart && pgs.stateHash() !== soft.stateHash(), "the two solvers' Worlds start alike and part as they step");
  pgs.delete();
  soft.delete();
  message = throwsWith(() => rbsim.World.fromPhase("contact_solvers", [], 2), ["world 2 of 2"]);
  check(message === "", `a World past the phase's last is refused ${message}`);
  message = throwsWith(() => rbsim.World.fromJson(ballScene, ["bodies.ball.mass=-1"]), ["mass"]);
  check(message === "", `a negative mass is refused, naming the field ${message}`);
  message = throwsWith(() => rbsim.World.fromScene("no_such_scene"), ["no_such_scene"]);
  check(message === "", `a missing scene is refused, naming it ${message}`);
  message = throwsWith(() => rbsim.World.fromJson(ballScene, "world.dt=0.1"), ["array"]);
  check(message === "", `overrides that are not an array are refused ${message}`);

  const stack = rbsim.World.fromScene("contact_response");
  const hash = stack.stateHash();
  check(throwsWith(() => stack.step(-1), ["0 or more"]) === "" && stack.stateHash() === hash, "step(-1) is refused and changes nothing");
  check(throwsWith(() => stack.vertices(99), ["out of range"]) === "", "a body index out of range is refused");
  check(stack.grab(0, 50, 0, 0, 1, 0) === -1 && stack.grabbed() === -1, "a ray that meets nothing grabs nothing");
  const p = stack.positions();
  const i = 1;
  const grabbed = stack.grab(p[3 * i], p[3 * i + 1] + 5, p[3 * i + 2], 0, -1, 0);
  check(grabbed === i, `a ray down onto body ${i} grabs it (grabbed ${grabbed})`);
  stack.moveGrab(p[3 * i], p[3 * i + 1] + 1, p[3 * i + 2]);
  stack.step(60);
  check(stack.positions()[3 * i + 1] > p[3 * i + 1] + 0.5, "the grabbed body follows the anchor 1 m up");
  stack.release();
  check(stack.grabbed() === -1, "release ends the drag");
  stack.delete();
  process.exit(failures ? 1 : 0);
}

main().catch((error) => { console.error(`api_test: ${error.message || error}`); process.exit(1); });
