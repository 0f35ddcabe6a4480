// A Vite/Rollup plugin (docs/web.md, "Bundler plugin"): `import shader from './orbit.vert?doublet&target=webgl2'`
// lowers the shader at build time with the WebAssembly compiler (./compiler.mjs) and yields
// { code, manifest, target, mode }. Query parameters: target, mode, and any other option of
// lower() given to the plugin as a default (doublet({ mode: 'df64-int', defines: {...} })).
// #includes are searched next to the shader, then in the plugin's includeDirs, and watched.
import { readFile } from 'node:fs/promises';
import { dirname, isAbsolute, resolve } from 'node:path';
import { lower } from './compiler.mjs';

const marker = 'doublet';

function splitId(id) {
  const at = id.indexOf('?');
  return at < 0 ? [id, null] : [id.slice(0, at), new URLSearchParams(id.slice(at + 1))];
}

export default function doublet(defaults = {}) {
  return {
    name: 'doublet',
    async resolveId(source, importer) {
      const [path, query] = splitId(source);
      if (!query?.has(marker)) return null;
      const base = importer ? dirname(splitId(importer)[0]) : process.cwd();
      return `${isAbsolute(path) ? path : resolve(base, path)}?${query}`;
    },
    async load(id) {
      const [path, query] = splitId(id);
      if (!query?.has(marker)) return null;
      const options = { ...defaults, fileName: path,
                        includeDirs: [dirname(path), ...(defaults.includeDirs ?? [])] };
      for (const [key, value] of query) if (key !== marker) options[key] = value;
      this.addWatchFile?.(path);
      const result = await lower(await readFile(path, 'utf8'), options);
      for (const file of result.includedFiles) this.addWatchFile?.(resolve(file));
      const report = (severity) => result.diagnostics.filter((d) => d.severity === severity).map((d) => d.text).join('\n');
      if (!result.ok) this.error(`doublet: ${path} did not lower:\n${report('error')}`);
      if (report('warning')) this.warn(report('warning'));
      const shader = { code: result.output, manifest: result.manifest,
                       target: options.target ?? 'es300', mode: options.mode ?? 'df64' };
      return { code: `export default ${JSON.stringify(shader)};\n`, map: { mappings: '' } };
    },
  };
}
