// Types of js/src/bundler-plugin.mjs (docs/web.md, "Bundler plugin").
import type { LowerOptions } from './compiler';

export interface LoweredShader {
  code: string;
  manifest: Record<string, unknown>;
  target: string;
  mode: string;
}

/** A Vite/Rollup plugin: `import shader from './a.vert?doublet&target=webgl2'` gives a LoweredShader. */
export default function doublet(defaults?: Omit<LowerOptions, 'fileName' | 'include'>): {
  name: 'doublet';
  resolveId(source: string, importer?: string): Promise<string | null>;
  load(id: string): Promise<{ code: string; map: { mappings: string } } | null>;
};
