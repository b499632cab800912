// Locations used by the package tests.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
export const distWasm = path.join(repoRoot, 'dist', 'kergen.wasm');
export const distGlue = path.join(repoRoot, 'dist', 'kergen.mjs');
export const sharedMeshes = path.resolve(repoRoot, '..', 'shared', 'meshes');
// The native CLI to compare with (override with KERGEN_CLI=/path/to/kergen).
export const nativeCli = process.env.KERGEN_CLI || path.join(repoRoot, 'build', 'kergen');

export function assertBuilt() {
  for (const f of [distWasm, distGlue]) {
    if (!fs.existsSync(f))
      throw new Error(`${path.relative(repoRoot, f)} is missing: run \`npm run build:wasm\` first`);
  }
}

/** Why shared meshes are unavailable (a skip message), or '' when present. */
export function sharedMeshesMissing() {
  return fs.existsSync(sharedMeshes) ? '' : `shared meshes not found at ${sharedMeshes}: skipping`;
}

/** .off files of a shared-mesh folder, sorted. */
export function offFiles(folder) {
  const dir = path.join(sharedMeshes, folder);
  if (!fs.existsSync(dir)) return [];
  return fs
    .readdirSync(dir)
    .filter((f) => f.endsWith('.off'))
    .sort()
    .map((f) => path.join(dir, f));
}

/** Why Vite cannot run under this Node (a skip message), or '' (Vite 7 and 8 need Node >= 20.19). */
export function viteUnsupported() {
  const [major, minor] = process.versions.node.split('.').map(Number);
  return major > 20 || (major === 20 && minor >= 19)
    ? ''
    : `Vite needs Node >= 20.19 (this is ${process.version}); the package itself is tested here by the other files`;
}
