// Times the browser's compile of lowered shaders, one page per shader in headless chromium.
//   node compile-time.mjs [--limit-ms 10000] [--rounds 1] FILE...
// FILE: GLSL ES 3.00 (`.frag`, `.vert`: timed in WebGL2) or WGSL (`.wgsl`, the stage from its entry
// point; timed in WebGPU). Prints one JSON line per file and round:
//   {"file", "api", "stage", "ok": true, "ms", "compile_ms", "draw_ms"} or {..., "ok": false, "error"}.
// `ms` is measured in the page (compile-time-page.mjs): source text to a runnable pipeline, without
// the browser's start-up. A shader that has no pipeline after the limit is reported and its browser
// killed (the GPU process of a shader that does not compile can grow by tens of MB/s), and the next
// file gets a fresh browser. Exit 0 when every file compiled within the limit, 1 when one did not,
// 2 when there is no browser here.
import fs from 'fs';
import os from 'os';
import path from 'path';
import { findChromium, launchKillable, pageOutcome, serve, takeOption } from './session.mjs';

const here = path.dirname(new URL(import.meta.url).pathname);
const args = process.argv.slice(2);
const option = (name, fallback) => takeOption(args, name, fallback);
const limitMs = Number(option('--limit-ms', '10000'));
const rounds = Number(option('--rounds', '1'));
if (!args.length || args.some((f) => !fs.existsSync(f))) {
  console.error('usage: node compile-time.mjs [--limit-ms N] [--rounds N] FILE...');
  process.exit(1);
}
const chromium = await findChromium('compile-time');
if (!chromium) process.exit(2);

const stageOf = (file, code) =>
  file.endsWith('.wgsl') ? (/@compute/.test(code) ? 'comp' : /@fragment/.test(code) ? 'frag' : 'vert') : path.extname(file).slice(1);

const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'doublet-compile-time-'));
for (const f of ['compile-time.html', 'compile-time-page.mjs']) fs.copyFileSync(path.join(here, f), path.join(dir, f));
args.forEach((file, i) => {
  const code = fs.readFileSync(file, 'utf8');
  fs.writeFileSync(path.join(dir, `job-${i}.json`),
                   JSON.stringify({ api: file.endsWith('.wgsl') ? 'webgpu' : 'webgl2', stage: stageOf(file, code), code }));
});
const server = await serve(dir);
const port = server.address().port;

let session = null;
let status = 0;
for (let round = 0; round < rounds; ++round) {
  for (let i = 0; i < args.length; ++i) {
    const job = JSON.parse(fs.readFileSync(path.join(dir, `job-${i}.json`), 'utf8'));
    const base = { file: args[i], api: job.api, stage: job.stage };
    let line;
    try {
      if (!session) session = await launchKillable(chromium);
      const page = await session.browser.newPage();
      const messages = [];
      page.on('pageerror', (error) => messages.push(error.message));
      await page.goto(`http://127.0.0.1:${port}/compile-time.html?job=job-${i}.json`, { timeout: limitMs + 20000 });
      // The page's own timing decides; the wait is longer so that a slow page still reports its figure.
      const outcome = await pageOutcome(page, limitMs + 20000);
      await page.close();
      if (outcome.error !== undefined) {
        line = { ...base, ok: false, error: outcome.error.split('\n').slice(0, 12).join('\n') };
      } else {
        const r = outcome.result;
        line = { ...base, ok: r.ms <= limitMs, ms: +r.ms.toFixed(1), compile_ms: +r.compile_ms.toFixed(1),
                 draw_ms: +r.draw_ms.toFixed(1) };
        if (!line.ok) line.error = `took ${r.ms.toFixed(0)} ms (limit ${limitMs} ms)`;
      }
    } catch (e) {
      line = { ...base, ok: false, error: /Timeout/.test(e.message) ? `no pipeline after ${limitMs + 20000} ms` : e.message };
      if (session) await session.kill().catch(() => {});
      session = null;
    }
    if (!line.ok) status = 1;
    process.stdout.write(JSON.stringify(line) + '\n');
  }
}
if (session) await session.kill().catch(() => {});
server.close();
fs.rmSync(dir, { recursive: true, force: true });
process.exit(status);
