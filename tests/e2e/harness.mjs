// The e2e harness's test registry (run.mjs prints its summary): test() runs one named test unless
// E2E_ONLY filters it out, skip()/skipTest() count a test as skipped, assert()/assertClose() fail
// it; and the paths the tests share.
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
export const repo = path.resolve(here, '../..');
export const webDist = path.join(repo, 'web/dist');
export const sharedMeshes = path.resolve(repo, '../shared/meshes');
export const artifacts = path.join(repo, 'tests/artifacts');
export const nativeCli = process.env.KERGEN_CLI ?? path.join(repo, 'build/kergen');
export const only = (process.env.E2E_ONLY ?? '').split('|').filter(Boolean); // "a|b": tests whose name holds a or b

export const results = [];
export const skipped = [];

export async function test(name, fn) {
  if (only.length && !only.some((s) => name.includes(s))) return;
  const t = Date.now();
  try {
    await fn();
    results.push({ name, ok: true });
    console.log(`ok   ${name} (${Date.now() - t} ms)`);
  } catch (err) {
    if (err instanceof SkipTest) {
      skipped.push({ name, why: err.message });
      console.log(`skip ${name}: ${err.message}`);
      return;
    }
    results.push({ name, ok: false, err });
    console.log(`FAIL ${name}: ${err?.message ?? err}`);
  }
}

// Thrown by a test whose subject is missing from this build (counted as skipped, not passed).
class SkipTest extends Error {}
export const skipTest = (why) => {
  throw new SkipTest(why);
};

export function skip(name, why) {
  if (only.length && !only.some((s) => name.includes(s))) return;
  skipped.push({ name, why });
  console.log(`skip ${name}: ${why}`);
}

export function assert(cond, message) {
  if (!cond) throw new Error(message);
}

export function assertClose(actual, expected, rel, what) {
  const err = Math.abs(actual - expected) / Math.max(Math.abs(expected), Number.MIN_VALUE);
  assert(
    Number.isFinite(actual) && err <= rel,
    `${what}: got ${actual}, expected ${expected} (relative error ${err.toExponential(2)} > ${rel})`,
  );
}
