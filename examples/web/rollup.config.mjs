// Builds src/main.js into dist/ (DOUBLET_EXAMPLE_OUT overrides it); shaders imported with
// `?doublet` are lowered at build time (@doublet/host/bundler-plugin, docs/web.md). DOUBLET_MODE
// sets the plugin's default mode (the test builds fp32 too, to show what it measures).
import { nodeResolve } from '@rollup/plugin-node-resolve';
import doublet from '@doublet/host/bundler-plugin';

export default {
  input: 'src/main.js',
  output: { dir: process.env.DOUBLET_EXAMPLE_OUT ?? 'dist', format: 'es' },
  plugins: [nodeResolve(), doublet({ mode: process.env.DOUBLET_MODE ?? 'df64' })],
};
