// The determinism test: the WebAssembly engine, run by node, resolves every shipped case and runs the first 10
// frames of every shipped scene under every preset to the native build's bits (every body's state after every
// frame), and writes the same trace of them byte for byte (recorded up to the budget trace_sums.cpp sets and
// explains).
//
//   node determinism.mjs --native NATIVE_PROGRAM --wasm PROGRAM.js --scenes SCENES_FOLDER
//
// Both programs are impulse-trace-sums (trace_sums.cpp), which prints one SHA-256 per trace; the native one comes
// from the engine preset (cmake --workflow --preset engine), the WebAssembly one from the web preset. The native
// program and two shares of the WebAssembly one run at once. Where two digests differ, both traces of the first
// such name are written out and the first line where they part is shown.

import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

function option(name) {
  const i = process.argv.indexOf(name);
  if (i < 0 || i + 1 >= process.argv.length) {
    console.error(`determinism.mjs: ${name} is missing`);
    process.exit(2);
  }
  return process.argv[i + 1];
}

const native = option('--native');
const wasm = option('--wasm');
const scenes = option('--scenes');
if (!existsSync(native)) {
  console.error(`determinism.mjs: the native program ${native} is missing: build it first ` +
                `(cmake --workflow --preset engine)`);
  process.exit(2);
}

// Runs a program to its end; resolves to its output, lines "digest  name".
function run(command, args, label) {
  return new Promise((resolve, reject) => {
    const child = spawn(command, args, { stdio: ['ignore', 'pipe', 'inherit'] });
    let out = '';
    child.stdout.on('data', (chunk) => { out += chunk; });
    child.on('error', reject);
    child.on('close', (code) => {
      if (code !== 0) reject(new Error(`${label} exited with ${code}`));
      else resolve(out);
    });
  });
}

function digests(text) {
  const map = new Map();
  for (const line of text.split('\n')) {
    const match = /^([0-9a-f]{64})  (\S+)$/.exec(line);
    if (match) map.set(match[2], match[1]);
  }
  return map;
}

const shares = 2;
const started = Date.now();
const [nativeText, ...wasmTexts] = await Promise.all([
  run(native, [scenes], 'the native program'),
  ...Array.from({ length: shares }, (_, i) =>
    run(process.execPath, [wasm, scenes, '--shard', `${i}/${shares}`], `the WebAssembly program (share ${i})`)),
]);
const expected = digests(nativeText);
const got = digests(wasmTexts.join('\n'));

const differing = [];
const missing = [];
for (const [name, digest] of expected) {
  if (!got.has(name)) missing.push(name);
  else if (got.get(name) !== digest) differing.push(name);
}
const same = expected.size - differing.length - missing.length;
console.log(`determinism: ${expected.size} runs (every shipped case, and 10 frames of every shipped scene, under ` +
            `every preset: states after every frame, traces to trace_sums.cpp's budget) in ${((Date.now() - started) / 1000).toFixed(0)} s`);
if (expected.size === 0) {
  console.log('determinism: the native program listed no trace');
  process.exit(1);
}

if (differing.length > 0) {
  // The first difference, line by line.
  const name = differing[0];
  const folder = mkdtempSync(join(tmpdir(), 'impulse-determinism-'));
  try {
    const a = join(folder, 'native.json'), b = join(folder, 'wasm.json');
    spawnSync(native, [scenes, '--only', name, '--write', a]);
    spawnSync(process.execPath, [wasm, scenes, '--only', name, '--write', b]);
    const left = readFileSync(a, 'utf8').split('\n'), right = readFileSync(b, 'utf8').split('\n');
    let line = 0;
    while (line < left.length && left[line] === right[line]) ++line;
    console.log(`determinism: ${name} first differs at line ${line + 1}:`);
    console.log(`  native:      ${(left[line] ?? '(end)').trim()}`);
    console.log(`  WebAssembly: ${(right[line] ?? '(end)').trim()}`);
  } finally {
    rmSync(folder, { recursive: true, force: true });
  }
}
for (const name of differing) console.log(`determinism: differs: ${name}`);
for (const name of missing) console.log(`determinism: the WebAssembly program wrote no ${name}`);
console.log(`${same} passed, ${differing.length + missing.length} failed`);
process.exit(differing.length + missing.length === 0 ? 0 : 1);
