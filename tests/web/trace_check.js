// Steps a shipped scene in rbsim.js (the WebAssembly build) and compares every body's x and q,
// step by step, with the native program's trace of the same scene (rbsim run SCENE --trace, whose
// %.17g numbers read back exactly): issue 59's "bit-identical to the native build". A compared
// scene is each of its Worlds, against the trace's rows of that World (bodies named "k/NAME").
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

// The rows of World k of n: of a compared scene, those whose body is named "k/NAME".
function rowsOf(trace, k, n) {
  if (n === 1) return trace;
  const prefix = `${k}/`;
  const rows = new Map();
  for (const [step, bodies] of trace) rows.set(step, bodies.filter((b) => b.name.startsWith(prefix)));
  return rows;
}

// Steps World k and compares it with its rows; returns a message on the first difference.
function compareWorld(rbsim, scene, overrides, k, rows) {
  const world = rbsim.World.fromPhase(scene, overrides, k);
  const last = Math.max(...rows.keys());
  const names = ["x", "y", "z", "qw", "qx", "qy", "qz"];
  try {
    for (let step = 0; step <= last; ++step) {
      if (step > 0) world.step(1);
      const bodies = rows.get(step);
      if (!bodies) continue;
      const x = world.positions(), q = world.orientations();
      if (bodies.length !== world.bodyCount()) {
        return `step ${step}: the native trace has ${bodies.length} bodies, the wasm World ${world.bodyCount()}`;
      }
      for (let i = 0; i < bodies.length; ++i) {
        const ours = [x[3 * i], x[3 * i + 1], x[3 * i + 2], q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]];
        for (let c = 0; c < 7; ++c) {
          if (!Object.is(ours[c], bodies[i].values[c])) {
            return `first difference at step ${step}, body ${i} (${bodies[i].name}), ${names[c]}: ` +
                   `native ${bodies[i].values[c]}, wasm ${ours[c]} (${ulps(ours[c], bodies[i].values[c])} ulp)`;
          }
        }
      }
    }
    return `${last} steps (${world.bodyCount()} bodies)`;
  } finally {
    world.delete();
  }
}

async function main() {
  const [site, traceFile, scene, ...overrides] = process.argv.slice(2);
  if (!scene) usage("three arguments expected");
  const createRbsim = require(path.resolve(site, "rbsim.js"));
  const rbsim = await createRbsim({locateFile: (file) => path.resolve(site, file)});
  const trace = readTrace(traceFile);
  if (trace.size === 0) {  // particles or 2D bodies alone: the API reads rigid bodies
    console.log(`${scene}: no rigid body to compare (the native trace is empty)`);
    return;
  }
  const labels = rbsim.World.phaseLabels(scene, overrides);
  const results = labels.map((label, k) => compareWorld(rbsim, scene, overrides, k, rowsOf(trace, k, labels.length)));
  const differs = results.findIndex((r) => r.startsWith("first difference") || r.startsWith("step "));
  if (differs >= 0) {
    console.log(`${scene}${labels.length > 1 ? ` (${labels[differs]})` : ""}: ${results[differs]}`);
    process.exit(1);
  }
  const what = labels.length > 1 ? `each of its ${labels.length} Worlds (${labels.join(", ")})` : "every body's x and q";
  console.log(`${scene}: ${what} equal the native trace's bit for bit over ${results[0]}`);
}

main().catch((error) => { console.error(`trace_check: ${error.message || error}`); process.exit(2); });
