// Opens one HTML file from the file system (a file:// URL, no server) in Debian's headless chromium
// and prints what the page reports, with run-page.mjs's protocol and exit statuses:
//   node open-file.mjs FILE [--timeout-ms 120000] [--screenshot PNG]
// The page reports by setting `window.doubletResult` (a value or a Promise of one); this prints
// JSON.stringify(result). Exit 0 result printed; 1 the page failed, timed out or did not load;
// 2 no browser here. It checks that a page such as `doublet demo --web`'s needs no server: from
// file:// the browser refuses fetch() and module imports of neighbouring files.
import fs from 'fs';
import path from 'path';
import { pathToFileURL } from 'url';
import { takeOption } from './session.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => takeOption(args, name, fallback);
const timeoutMs = Number(option('--timeout-ms', '120000'));
const screenshot = option('--screenshot', '');
const file = args[0];
if (!file || args.length !== 1 || !fs.statSync(file, { throwIfNoEntry: false })?.isFile()) {
  console.error('usage: node open-file.mjs FILE [--timeout-ms N] [--screenshot PNG]');
  process.exit(1);
}
const executablePath = process.env.CHROMIUM || '/usr/bin/chromium';
let chromium;
try {
  ({ chromium } = await import('playwright-core'));
} catch (e) {
  console.error(`open-file: playwright-core is not installed (npm ci in ${path.dirname(new URL(import.meta.url).pathname)}): ${e.message}`);
  process.exit(2);
}
if (!fs.existsSync(executablePath)) {
  console.error(`open-file: no browser at ${executablePath} (apt-get install chromium)`);
  process.exit(2);
}

let browser;
const finish = async status => {
  if (browser) await browser.close().catch(() => {});
  process.exit(status);
};
try {
  // The switches of run-page.mjs: WebGL2 on the CPU (SwiftShader), nothing from the network.
  browser = await chromium.launch({
    executablePath,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync',
           '--enable-unsafe-swiftshader'],
  });
} catch (e) {
  console.error(`open-file: cannot start ${executablePath}: ${e.message}`);
  await finish(2);
}
try {
  const url = pathToFileURL(path.resolve(file)).href;
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  page.on('console', message => console.error(`[page ${message.type()}] ${message.text()}`));
  page.on('pageerror', error => console.error(`[page error] ${error.message}`));
  // A request for anything but the file itself means the page is not self-contained: a failure.
  const others = [];
  page.on('request', request => {
    if (request.url() !== url) others.push(request.url());
  });
  await page.goto(url, { timeout: timeoutMs });
  await page.waitForFunction(() => window.doubletResult !== undefined || window.doubletError !== undefined,
                             null, { timeout: timeoutMs, polling: 50 });
  const outcome = await page.evaluate(async () => {
    if (window.doubletError !== undefined) return { error: String(window.doubletError) };
    try {
      return { result: await window.doubletResult };
    } catch (e) {
      return { error: String(e && e.stack || e) };
    }
  });
  if (screenshot) await page.screenshot({ path: screenshot, fullPage: true });
  if (outcome.error === undefined && others.length) outcome.error = `it requested more than ${url}: ${others.join(', ')}`;
  if (outcome.error !== undefined) {
    console.error(`open-file: the page failed: ${outcome.error}`);
    await finish(1);
  }
  process.stdout.write(JSON.stringify(outcome.result) + '\n');
  await finish(0);
} catch (e) {
  console.error(`open-file: ${e.message}`);
  await finish(1);
}
