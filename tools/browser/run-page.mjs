// Opens one page of a directory in Debian's headless chromium and prints what the page reports.
//   node run-page.mjs DIR [--page index.html] [--timeout-ms 120000] [--screenshot FILE] [--viewport 1280x800]
// DIR is served read-only on a loopback HTTP port (WebGPU needs a secure context; file:// pages can use
// neither modules nor fetch). The page reports by setting `window.doubletResult` to a JSON-serialisable
// value or to a Promise of one; this script waits for it and prints JSON.stringify(result) on stdout.
// The page's console and errors go to stderr, prefixed.
// Exit status: 0 result printed; 1 the page threw before reporting, timed out, or failed to load;
// 2 no browser here (chromium or playwright-core missing): callers treat 2 as "skip", not as failure.
// playwright-core drives the system browser at $CHROMIUM (default /usr/bin/chromium): nothing is downloaded.
import fs from 'fs';
import { findChromium, launch, pageOutcome, serve, takeOption } from './session.mjs';

const usage = 'usage: node run-page.mjs DIR [--page index.html] [--timeout-ms N] [--screenshot FILE] [--viewport WxH]';
const args = process.argv.slice(2);
const option = (name, fallback) => takeOption(args, name, fallback);
const pageName = option('--page', 'index.html');
const timeoutMs = Number(option('--timeout-ms', '120000'));
const screenshot = option('--screenshot', '');
const [width, height] = option('--viewport', '1280x800').split('x').map(Number);
const dir = args[0];
if (!dir || args.length !== 1 || !fs.existsSync(dir)) {
  console.error(usage);
  process.exit(1);
}
const chromium = await findChromium('run-page');
if (!chromium) process.exit(2);
const server = await serve(dir);

let browser;
const finish = async (status) => {
  if (browser) await browser.close().catch(() => {});
  server.close();
  process.exit(status);
};
try {
  browser = await launch(chromium);
} catch (e) {
  console.error(`run-page: cannot start the browser: ${e.message}`);
  await finish(2);
}
try {
  const page = await browser.newPage({ viewport: { width, height } });
  page.on('console', message => console.error(`[page ${message.type()}] ${message.text()}`));
  page.on('pageerror', error => { console.error(`[page error] ${error.message}`); });
  const port = server.address().port;
  await page.goto(`http://127.0.0.1:${port}/${pageName}`, { timeout: timeoutMs });
  const outcome = await pageOutcome(page, timeoutMs);
  if (screenshot) await page.screenshot({ path: screenshot, fullPage: true });
  if (outcome.error !== undefined) {
    console.error(`run-page: the page failed: ${outcome.error}`);
    await finish(1);
  }
  process.stdout.write(JSON.stringify(outcome.result) + '\n');
  await finish(0);
} catch (e) {
  console.error(`run-page: ${e.message}`);
  await finish(1);
}
