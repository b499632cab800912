// Browser end-to-end tests of the demo page (web/), in Debian's Chromium via playwright-core.
//
//   node tests/e2e/run.mjs        (npm run test:e2e)
//
// Builds the page when its sources (web/, wasm/, dist/) are newer than web/dist, serves web/dist
// on 127.0.0.1 (a free port), and checks: the sample generators (samples-check.mjs); every gallery
// sample's kernel against its hand-derived / 2D-clipped expectation; the animation (play, scrubber,
// partial counts, jump to end); files through the picker (OFF, binary and ascii STL, OBJ) and drag
// & drop; princeton/350.off against the native CLI; error messages (out-of-range index, open,
// non-manifold, unparseable); cancel on a large input with a responsive page; export; light/dark;
// the page's states (demo-states.mjs: states, witness faces, open meshes and allowOpen, repair)
// and views (demo-features.mjs: inscribed ball, section plane, fitting, ?url= and links, GLB/glTF,
// keyboard, axe-core). Screenshots go to tests/artifacts/. Prints `e2e: N passed, M failed`;
// exits 1 on failure. This file is the harness (build, server, Chromium, the order of the suites,
// the summary); the tests live beside it: harness.mjs (test/skip/assert, E2E_ONLY, shared paths),
// page-state.mjs, mesh-files.mjs and demo-view-tools.mjs (helpers), gallery-and-files.mjs,
// progress-and-messages.mjs, export-and-cancel.mjs, demo-states.mjs, demo-features.mjs,
// demo-refusals.mjs, first-visit.mjs, big-meshes.mjs, three-app-test.mjs, examples.mjs, cells-page.mjs
// (the volume-mesh page, cells.html).
// Environment: CHROMIUM (default /usr/bin/chromium), KERGEN_CLI (default build/kergen),
// E2E_HEADFUL=1, E2E_ONLY=<substring of test names>.

import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { checkSamples } from './samples-check.mjs';
import { serve } from './page-tools.mjs';
import { examplesTests } from './examples.mjs';
import { demoStateTests } from './demo-states.mjs';
import { demoFeatureTests } from './demo-features.mjs';
import { demoRefusalTests } from './demo-refusals.mjs';
import { firstVisitTests } from './first-visit.mjs';
import {
  test,
  skip,
  skipTest,
  assert,
  assertClose,
  results,
  skipped,
  repo,
  webDist,
  sharedMeshes,
  artifacts,
} from './harness.mjs';
import { loadSample, loadFile, waitFinished, markPending, jumpToEnd } from './page-state.mjs';
import { samplesAndAnimation, fileTests } from './gallery-and-files.mjs';
import { progressAndControls, realMeshesAndMessages } from './progress-and-messages.mjs';
import { exportAndDrop, cancelTest } from './export-and-cancel.mjs';
import { themeAndBigFile, bigKernelTest } from './big-meshes.mjs';
import { threeAppTest } from './three-app-test.mjs';
import { cellsPageTests } from './cells-page.mjs';

// ---------------------------------------------------------------------------------------------
// Build and serve

function newestMtime(dir, skipDirs = []) {
  let newest = 0;
  if (!fs.existsSync(dir)) return 0;
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const p = path.join(dir, entry.name);
    if (entry.isDirectory()) {
      if (!skipDirs.includes(p) && entry.name !== 'node_modules') newest = Math.max(newest, newestMtime(p, skipDirs));
    } else newest = Math.max(newest, fs.statSync(p).mtimeMs);
  }
  return newest;
}

function buildIfNeeded() {
  const built = path.join(webDist, 'index.html');
  const sources = Math.max(
    newestMtime(path.join(repo, 'web'), [webDist]),
    newestMtime(path.join(repo, 'wasm')),
    newestMtime(path.join(repo, 'dist')),
    fs.statSync(path.join(repo, 'package.json')).mtimeMs,
  );
  if (fs.existsSync(built) && fs.statSync(built).mtimeMs >= sources) {
    console.log('e2e: web/dist is up to date');
    return;
  }
  assert(
    fs.existsSync(path.join(repo, 'dist/kergen.wasm')),
    'dist/kergen.wasm is missing: run `npm run build:wasm` first',
  );
  console.log('e2e: building the page (vite build --config web/vite.config.js)');
  const r = spawnSync(
    process.execPath,
    [path.join(repo, 'node_modules/vite/bin/vite.js'), 'build', '--config', 'web/vite.config.js', '--logLevel', 'warn'],
    { cwd: repo, stdio: 'inherit' },
  );
  assert(r.status === 0, 'vite build failed');
}

async function main() {
  fs.mkdirSync(artifacts, { recursive: true });
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-e2e-'));

  // 1. The sample generators, in Node.
  for (const r of checkSamples()) {
    await test(r.name, async () => assert(r.ok, r.detail));
  }

  buildIfNeeded();
  const served = new Map(); // test files the page can fetch: '/__files/<name>' → path
  const server = await serve(webDist, served);
  const base = `http://127.0.0.1:${server.address().port}/`;
  console.log(`e2e: serving web/dist at ${base}`);
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-e2e-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: !process.env.E2E_HEADFUL,
    args: [
      '--no-sandbox',
      '--disable-gpu',
      '--disable-quic',
      '--no-first-run',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
      '--use-angle=swiftshader',
      '--enable-unsafe-swiftshader',
    ],
    viewport: { width: 1280, height: 800 },
    acceptDownloads: true,
    colorScheme: 'light',
  });
  const page = context.pages()[0] ?? (await context.newPage());
  const pageErrors = [];
  page.on('pageerror', (e) => pageErrors.push(`pageerror: ${e.message}`));
  page.on('console', (m) => {
    if (m.type() === 'error') pageErrors.push(`console.error: ${m.text()}`);
  });

  try {
    await page.goto(base, { waitUntil: 'load' });
    await samplesAndAnimation(page);
    await fileTests(page, tmp);
    await progressAndControls(page, tmp);
    await realMeshesAndMessages(page, tmp);
    await exportAndDrop(page, tmp);
    await cancelTest(page, tmp);
    // The helpers the demo suites take as one object (they are not imported by those files).
    const helpers = {
      test,
      skip,
      skipTest,
      assert,
      assertClose,
      loadSample,
      loadFile,
      waitFinished,
      markPending,
      jumpToEnd,
      artifacts,
      sharedMeshes,
      served,
    };
    await demoStateTests(page, context, base, tmp, helpers);
    await demoFeatureTests(page, context, base, tmp, helpers);
    await demoRefusalTests(page, context, base, tmp, { ...helpers, webDist });
    await firstVisitTests(page, context, base, helpers);
    await themeAndBigFile(page, tmp, served);
    await bigKernelTest(page, tmp);
    await threeAppTest(context, tmp);
    await examplesTests(context, tmp, { test, assert, artifacts });
    await cellsPageTests(context, base, tmp, { test, assert, assertClose, artifacts });

    await test('no uncaught errors or console errors in the page', async () => {
      assert(pageErrors.length === 0, pageErrors.slice(0, 5).join(' | '));
    });
  } finally {
    await context.close();
    server.close();
    fs.rmSync(profile, { recursive: true, force: true });
    fs.rmSync(tmp, { recursive: true, force: true });
  }
}

try {
  await main();
} catch (err) {
  results.push({ name: 'harness', ok: false, err });
  console.log(`FAIL harness: ${err?.stack ?? err}`);
}
const failed = results.filter((r) => !r.ok).length;
if (skipped.length) console.log(`e2e: ${skipped.length} skipped (${skipped.map((s) => s.name).join('; ')})`);
console.log(`e2e: ${results.length - failed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
