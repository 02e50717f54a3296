// Steps a shipped scene in rbsim.js (the WebAssembly build) and compares every body's x and q,
// step by step, with the native program's trace of the same scene (rbsim run SCENE --trace, whose
// %.17g numbers read back exactly): issue 59's "bit-identical to the native build".
//   node --no-experimental-fetch trace_check.js SITE_DIR NATIVE_TRACE.csv SCENE [KEY=VALUE ...]
// Prints the first step at which a number differs (with its distance in units in the last place)
// or that all agree, and exits 1 on a difference, 2 on bad arguments.
"use strict";
const fs = require("fs");
const path = require("path");

function usage(message) {
  console.error(`trace_check: ${message}\nusage: node trace_check.js SITE_DIR NATIVE_TRACE.csv SCENE [KEY=VALUE ...]`);
  process.exit(2);
}

// The native trace's x, y, z, qw, qx, qy, qz per step: {step: [[7 numbers] per body]}.
function readTrace(file) {
  const lines = fs.readFileSync(file, "utf8").trim().split("\n");
  const header = lines[0].split(",");
  const columns = ["x", "y", "z", "qw", "qx", "qy", "qz"].map((name) => header.indexOf(name));
  if (columns.includes(-1) || header[0] !== "step") usage(`${file} is not an rbsim trace (step,t,body,x,...,qz)`);
  const steps = new Map();
  for (const line of lines.slice(1)) {
    const cells = line.split(",");
    const step = Number(cells[0]);
    if (!steps.has(step)) steps.set(step, []);
    steps.get(step).push({name: cells[2], values: columns.map((c) => Number(cells[c]))});
  }
  return steps;
}

// How many doubles lie between a and b (0: the same bits).
function ulps(a, b) {
  const view = new DataView(new ArrayBuffer(16));
  view.setFloat64(0, a);
  view.setFloat64(8, b);
  const ordered = (i) => { const v = view.getBigInt64(i); return v < 0n ? -(v & 0x7fffffffffffffffn) : v; };
  const d = ordered(0) - ordered(8);
  return d < 0n ? -d : d;
}

async function main() {
  const [site, traceFile, scene, ...overrides] = process.argv.slice(2);
  if (!scene) usage("three arguments expected");
  const createRbsim = require(path.resolve(site, "rbsim.js"));
  const rbsim = await createRbsim({locateFile: (file) => path.resolve(site, file)});
  const trace = readTrace(traceFile);
  const world = rbsim.World.fromScene(scene, overrides);
  if (trace.size === 0) {  // particles or 2D bodies alone: the API reads rigid bodies
    console.log(`${scene}: no rigid body to compare (the native trace is empty)`);
    return;
  }
  const last = Math.max(...trace.keys());
  const names = ["x", "y", "z", "qw", "qx", "qy", "qz"];
  for (let step = 0; step <= last; ++step) {
    if (step > 0) world.step(1);
    const rows = trace.get(step);
    if (!rows) continue;
    const x = world.positions(), q = world.orientations();
    if (rows.length !== world.bodyCount()) {
      console.log(`${scene}: step ${step}: the native trace has ${rows.length} bodies, the page's World ${world.bodyCount()}`);
      process.exit(1);
    }
    for (let i = 0; i < rows.length; ++i) {
      const ours = [x[3 * i], x[3 * i + 1], x[3 * i + 2], q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]];
      for (let k = 0; k < 7; ++k) {
        if (!Object.is(ours[k], rows[i].values[k])) {
          console.log(`${scene}: first difference at step ${step}, body ${i} (${rows[i].name}), ${names[k]}: ` +
                      `native ${rows[i].values[k]}, wasm ${ours[k]} (${ulps(ours[k], rows[i].values[k])} ulp)`);
          process.exit(1);
        }
      }
    }
  }
  console.log(`${scene}: every body's x and q equal the native trace's bit for bit over ${last} steps (${world.bodyCount()} bodies)`);
  world.delete();
}

main().catch((error) => { console.error(`trace_check: ${error.message || error}`); process.exit(2); });
