#!/usr/bin/env node
// Frame time of the demo page while the view is orbited around a big kernel, in headless
// Chromium (SwiftShader WebGL): a UV sphere (default 250 × 400 = 199,200 triangles; nearly
// convex, so its kernel has ~310k vertices) is dropped on the page, the whole kernel is shown,
// and the mouse drags the view for ~3 s while requestAnimationFrame deltas are recorded.
//
//   node bench/frame_bench.mjs [--nlat A --nlon B] [--drags N] [--shot FILE.png] [--dist DIR]
//
// --dist: the built page to serve (default web/dist; e.g. an older build, to compare).
//
// Prints the kernel's size, the frame count, and the median / 90th percentile / longest frame
// delta per drag (a frame is rendered on every animation frame while the camera moves). Needs
// dist/ and web/dist (npm run build:wasm, npm run build:web).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve, launch, dragFrameDeltas } from '../tests/e2e/page-tools.mjs';
import { radialSphere } from '../web/samples.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const opt = (name, dflt) => (args.includes(name) ? args[args.indexOf(name) + 1] : dflt);
const nlat = Number(opt('--nlat', '250'));
const nlon = Number(opt('--nlon', '400'));
const drags = Number(opt('--drags', '3'));
const shot = opt('--shot', '');
const dist = path.resolve(opt('--dist', path.join(repo, 'web/dist')));

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-frames-'));
const file = path.join(tmp, `sphere-${nlat}x${nlon}.off`);
const m = radialSphere(nlat, nlon, () => 1);
const lines = ['OFF', `${m.positions.length / 3} ${m.indices.length / 3} 0`];
for (let i = 0; i < m.positions.length; i += 3)
  lines.push(`${m.positions[i]} ${m.positions[i + 1]} ${m.positions[i + 2]}`);
for (let i = 0; i < m.indices.length; i += 3) lines.push(`3 ${m.indices[i]} ${m.indices[i + 1]} ${m.indices[i + 2]}`);
fs.writeFileSync(file, lines.join('\n') + '\n');

const server = await serve(dist, new Map([['/__files/sphere.off', file]]));
const { page, close } = await launch();
const pct = (xs, p) => [...xs].sort((a, b) => a - b)[Math.min(xs.length - 1, Math.floor(p * xs.length))];
try {
  console.log(
    `load average ${os
      .loadavg()
      .map((x) => x.toFixed(1))
      .join(' ')}`,
  );
  await page.goto(`http://127.0.0.1:${server.address().port}/?sample=none`);
  await page.evaluate(async () => {
    const blob = await (await fetch('/__files/sphere.off')).blob();
    const dt = new DataTransfer();
    dt.items.add(new File([blob], 'sphere.off'));
    document.getElementById('status').dataset.state = 'pending';
    document
      .getElementById('viewport')
      .dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  });
  await page.waitForFunction(() => document.getElementById('status').dataset.state === 'done', null, {
    timeout: 600000,
    polling: 500,
  });
  await page.click('#jump-end');
  await page.waitForTimeout(1000);
  const size = await page.evaluate(() =>
    ['vertices', 'edges', 'faces'].map((k) => document.getElementById(`stat-${k}`).dataset.value),
  );
  console.log(`UV sphere ${nlat} x ${nlon}: kernel V/E/F ${size.join('/')}`);
  for (let d = 0; d < drags; d++) {
    const frames = await dragFrameDeltas(page, { ms: 3000 });
    console.log(
      `drag ${d + 1}: ${frames.length} frames in ~3 s; frame delta median ${pct(frames, 0.5).toFixed(0)} ms, ` +
        `p90 ${pct(frames, 0.9).toFixed(0)} ms, longest ${Math.max(...frames).toFixed(0)} ms ` +
        `(${(1000 / pct(frames, 0.5)).toFixed(1)} frames/s at the median)`,
    );
  }
  if (shot) {
    await page.waitForTimeout(1500);
    await page.locator('#viewport').screenshot({ path: shot });
  }
} finally {
  await close();
  server.close();
  fs.rmSync(tmp, { recursive: true, force: true });
}
