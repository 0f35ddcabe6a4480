// What every browser script here shares: Debian's headless chromium driven by playwright-core (nothing
// downloaded), and a read-only loopback HTTP server for a directory (WebGPU needs a secure context;
// file:// pages can use neither modules nor fetch). docs/web.md, "The browser harness".
import fs from 'fs';
import http from 'http';
import path from 'path';

export const executablePath = process.env.CHROMIUM || '/usr/bin/chromium';

// Removes `name VALUE` from args and returns VALUE (fallback when absent): the scripts' option parser.
export function takeOption(args, name, fallback) {
  const i = args.indexOf(name);
  if (i < 0) return fallback;
  const value = args[i + 1];
  args.splice(i, 2);
  return value;
}

// Resolves to playwright-core's chromium, or null with the reason printed (callers exit 2: "no browser").
export async function findChromium(who) {
  let chromium;
  try {
    ({ chromium } = await import('playwright-core'));
  } catch (e) {
    console.error(`${who}: playwright-core is not installed (npm ci in ${path.dirname(new URL(import.meta.url).pathname)}): ${e.message}`);
    return null;
  }
  if (!fs.existsSync(executablePath)) {
    console.error(`${who}: no browser at ${executablePath} (apt-get install chromium)`);
    return null;
  }
  return chromium;
}

// WebGL2 and WebGPU on the CPU (SwiftShader): no GPU on these machines. --enable-unsafe-webgpu is
// what makes navigator.gpu.requestAdapter() answer headless (docs/web.md).
const launchOptions = {
  executablePath,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
         '--disable-background-networking', '--disable-component-update', '--disable-sync',
         '--enable-unsafe-swiftshader', '--enable-unsafe-webgpu'],
};

export function launch(chromium) {
  return chromium.launch(launchOptions);
}

// A browser that can be killed outright (a shader that hangs the GPU process does not let close()
// finish): {browser, kill()}.
export async function launchKillable(chromium) {
  const server = await chromium.launchServer(launchOptions);
  const browser = await chromium.connect(server.wsEndpoint());
  return { browser, kill: () => server.kill() };
}

const contentTypes = {
  '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.json': 'application/json',
  '.png': 'image/png', '.css': 'text/css',
};

// Serves `dir` read-only on a loopback port; resolves to the listening server.
export async function serve(dir) {
  const root = path.resolve(dir);
  const server = http.createServer((request, response) => {
    const file = path.resolve(root, '.' + decodeURIComponent(new URL(request.url, 'http://x').pathname));
    if (!file.startsWith(root + path.sep) && file !== root) {
      response.writeHead(403).end();
      return;
    }
    if (file === path.join(root, 'favicon.ico')) {
      response.writeHead(204).end();  // browsers ask for it; a 404 would be logged as a page error
      return;
    }
    fs.readFile(file, (error, data) => {
      if (error) {
        response.writeHead(404).end();
        return;
      }
      response.writeHead(200, { 'Content-Type': contentTypes[path.extname(file)] || 'text/plain' }).end(data);
    });
  });
  await new Promise(resolve => server.listen(0, '127.0.0.1', resolve));
  return server;
}

// Waits until the page sets window.doubletResult (a value or a Promise) or window.doubletError, and
// returns {result} or {error}.
export async function pageOutcome(page, timeoutMs) {
  await page.waitForFunction(() => window.doubletResult !== undefined || window.doubletError !== undefined,
                             null, { timeout: timeoutMs, polling: 50 });
  return page.evaluate(async () => {
    if (window.doubletError !== undefined) return { error: String(window.doubletError) };
    try {
      return { result: await window.doubletResult };
    } catch (e) {
      return { error: String(e && e.stack || e) };
    }
  });
}
