#!/usr/bin/env node
// `doublet lower` as WebAssembly (docs/web.md, "The compiler as WebAssembly"): the native CLI's
// lower command, built by scripts/build-wasm into js/dist/, with the same options, diagnostics,
// exit status and output bytes; files are read and written through Node's file system.
//   node js/bin/doublet.mjs lower globe.vert --target webgl2 -o globe.webgl2.vert --manifest globe.json
import v8 from 'node:v8';
import { loadNodeModule } from '../src/compiler.mjs';

// One short process per command: V8's optimizing tier would recompile the hot parts of 4 MB of
// WebAssembly in the background and costs more than it saves before the process ends; the
// baseline tier alone (Liftoff) starts about twice as fast with a third of the CPU time (docs/web.md,
// "Size and speed"). DOUBLET_WASM_TIER_UP=1, or a node option that names a WebAssembly tier (such
// as `node --no-liftoff-only`), keeps V8's default (for very large shaders). Set before the module
// is compiled, which loadNodeModule does.
if (!process.env.DOUBLET_WASM_TIER_UP && !process.execArgv.some((a) => /liftoff|tier-up|turbofan/.test(a)))
  v8.setFlagsFromString('--liftoff-only');
const module = await loadNodeModule({ noInitialRun: true });
// callMain runs `doublet` with these arguments; EXIT_RUNTIME ends the process with its status.
module.callMain(process.argv.slice(2));
