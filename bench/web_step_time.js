// Steps a shipped scene in the browser build under node and prints its load and step times:
// beside `rbsim run SCENE --steps N --no-render`, what WebAssembly costs against the native program
// (docs/web.md, "Speed").
//   node --no-experimental-fetch bench/web_step_time.js SITE_DIR SCENE STEPS
"use strict";
const path = require("path");

async function main() {
  const [site, scene, stepsText] = process.argv.slice(2);
  const steps = Number(stepsText);
  if (!scene || !(steps >= 0)) {
    console.error("usage: node web_step_time.js SITE_DIR SCENE STEPS");
    process.exit(2);
  }
  const rbsim = await require(path.resolve(site, "rbsim.js"))({locateFile: (file) => path.resolve(site, file)});
  const t0 = process.hrtime.bigint();
  const world = rbsim.World.fromScene(scene);
  const t1 = process.hrtime.bigint();
  world.step(steps);
  const t2 = process.hrtime.bigint();
  console.log(`${scene}: load ${(Number(t1 - t0) / 1e6).toFixed(1)} ms, ${steps} steps ${(Number(t2 - t1) / 1e6).toFixed(1)} ms ` +
              `(${(Number(t2 - t1) / 1e6 / Math.max(steps, 1)).toFixed(4)} ms a step), ${world.bodyCount()} bodies`);
  world.delete();
}

main().catch((error) => { console.error(`web_step_time: ${error.message || error}`); process.exit(1); });
