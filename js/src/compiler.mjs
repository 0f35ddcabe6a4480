// The compiler as WebAssembly (docs/web.md, "The compiler as WebAssembly"): lower(source, options)
// runs doublet::lower, built by scripts/build-wasm into js/dist/ — doublet-node.cjs in Node,
// doublet-web.mjs in browsers and workers. The result is { ok, output, manifest, diagnostics,
// includedFiles }; each diagnostic has file, line, column, severity, message and `text`, the
// `file:line:col: error: message` line the CLI prints.
const dist = new URL('../dist/', import.meta.url);
const isNode = typeof process === 'object' && typeof process.versions?.node === 'string';

// Node: the CommonJS module with Node's file system (NODERAWFS). Emscripten 3.1.6 would fetch()
// its .wasm when Node has fetch, which cannot read a file path: the bytes are handed over.
// settings: Emscripten's (noInitialRun, doubletInclude).
export async function loadNodeModule(settings = {}) {
  const { readFileSync } = await import('node:fs');
  const { createRequire } = await import('node:module');
  const { fileURLToPath } = await import('node:url');
  const path = fileURLToPath(new URL('doublet-node.cjs', dist));
  let factory;
  try {
    factory = createRequire(import.meta.url)(path);
  } catch (error) {
    throw new Error(`the WebAssembly compiler is not built (${path}): run bash scripts/build-wasm`);
  }
  // The process environment (NO_COLOR, TERM) as the native CLI sees it.
  const preRun = [(module) => Object.assign(module.ENV, process.env)];
  return factory({ ...settings, preRun, wasmBinary: readFileSync(new URL('doublet-node.wasm', dist)) });
}

async function loadWebModule(settings) {
  const { default: factory } = await import(new URL('doublet-web.mjs', dist).href);
  return factory(settings);
}

let modulePromise = null;
let currentInclude = null;

function compilerModule() {
  if (!modulePromise) {
    // doubletInclude: #include "name" asks the host (options.include) while lower() runs.
    const settings = { noInitialRun: true, doubletInclude: (requested, includer) => currentInclude?.(requested, includer) ?? null };
    modulePromise = isNode ? loadNodeModule(settings) : loadWebModule(settings);
  }
  return modulePromise;
}

/**
 * Lowers a GLSL shader with doubles. options: stage ('vert'|'frag'|'comp', or taken from
 * fileName's extension), target ('es300', 'webgl2', 'wgsl', ...), mode ('df64', 'exact', ...),
 * modeFor ({NAME: MODE}), defines ({NAME: VALUE}), includeDirs (Node only), include
 * ((requested, includerPath) => ({path, contents}) | null), guard, gpuShader5, guardUniform,
 * hiSuffix, loSuffix, optimize, disabledLints, lintErrors, constantRangeErrors.
 */
export async function lower(source, options = {}) {
  const module = await compilerModule();
  const { include, ...rest } = options;
  const request = { ...rest, hostIncludes: typeof include === 'function' };
  const sourceBytes = module.lengthBytesUTF8(source) + 1;
  const optionsText = JSON.stringify(request);
  const optionsBytes = module.lengthBytesUTF8(optionsText) + 1;
  const sourcePtr = module._malloc(sourceBytes);
  const optionsPtr = module._malloc(optionsBytes);
  currentInclude = include ?? null;
  try {
    module.stringToUTF8(source, sourcePtr, sourceBytes);
    module.stringToUTF8(optionsText, optionsPtr, optionsBytes);
    const resultPtr = module._doublet_lower_json(sourcePtr, optionsPtr);
    const result = JSON.parse(module.UTF8ToString(resultPtr));
    module._free(resultPtr);
    return result;
  } finally {
    currentInclude = null;
    module._free(sourcePtr);
    module._free(optionsPtr);
  }
}
