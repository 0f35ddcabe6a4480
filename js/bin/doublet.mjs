#!/usr/bin/env node
// `doublet lower` as WebAssembly (docs/web.md, "The compiler as WebAssembly"): the native CLI's
// lower command, built by scripts/build-wasm into js/dist/, with the same options, diagnostics,
// exit status and output bytes; files are read and written through Node's file system.
//   node js/bin/doublet.mjs lower globe.vert --target webgl2 -o globe.webgl2.vert --manifest globe.json
import { loadNodeModule } from '../src/compiler.mjs';

const module = await loadNodeModule({ noInitialRun: true });
// callMain runs `doublet` with these arguments; EXIT_RUNTIME ends the process with its status.
module.callMain(process.argv.slice(2));
