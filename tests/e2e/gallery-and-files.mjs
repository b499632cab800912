// Browser tests of the demo page: the front door, every gallery sample and the animation; files
// through the picker in every format the package reads. Called by run.mjs.
import fs from 'node:fs';
import path from 'node:path';
import { SAMPLES, sampleById } from '../../web/samples.js';
import { expectedKernel } from './samples-check.mjs';
import { writeBinarySTL } from './page-tools.mjs';
import { test, skip, assert, assertClose } from './harness.mjs';
import { writeOFF, writeOBJ, writePLY, writeAsciiSTL, packageReadsFile } from './mesh-files.mjs';
import { lPrismFiles } from '../node/lib/example-meshes.mjs';
import { readState, waitFinished, loadSample, loadFile, scrubTo, jumpToEnd, shoot } from './page-state.mjs';

// The front door, every gallery sample, and the animation.
export async function samplesAndAnimation(page) {
  // 2. The front door: the default sample loads and renders.
  await test('page opens with the star prism and a WebGL view', async () => {
    const s = await waitFinished(page);
    const exp = expectedKernel(sampleById('star-prism'));
    assert(s.status === exp.status, `status ${s.status} (${s.statusText}) ${JSON.stringify(s.message)}`);
    assert(
      Number(s.stats.vertices) === exp.vertices && Number(s.stats.faces) === exp.faces,
      `counts ${s.stats.vertices}/${s.stats.faces}`,
    );
    const gl = await page.evaluate(() => !!document.querySelector('#viewport canvas')?.getContext('webgl2'));
    assert(gl, 'no WebGL2 context on the canvas');
  });

  // 3. Every gallery sample against its expected kernel.
  for (const sample of SAMPLES) {
    const exp = expectedKernel(sample);
    await test(`sample ${sample.id} → ${exp.status}${exp.volume != null ? `, volume ${exp.volume.toPrecision(10)}` : ''}`, async () => {
      const s = await loadSample(page, sample.id);
      assert(s.status === exp.status, `status ${s.status}: ${s.statusText} ${JSON.stringify(s.message)}`);
      if (exp.volume != null) assertClose(Number(s.stats.volume), exp.volume, 1e-9, 'kernel volume');
      for (const k of ['vertices', 'edges', 'faces']) {
        if (exp[k] != null) assert(Number(s.stats[k]) === exp[k], `${k}: ${s.stats[k]}, expected ${exp[k]}`);
      }
      if (exp.area != null) assertClose(Number(s.stats.area), exp.area, 1e-9, 'kernel area');
      if (exp.status === 'POLYGON') {
        assert(
          s.message?.kind === 'flat' && /flat/i.test(s.message.text),
          `flat-kernel message: ${JSON.stringify(s.message)}`,
        );
        assert(Number(s.stats.volume) === 0, `flat kernel volume ${s.stats.volume}`);
        await jumpToEnd(page);
        const px = await shoot(page, 'flat-kernel.png', { fullPage: true });
        assert(px.blue > 500, `flat kernel: ${px.blue} kernel-blue pixels`);
      } else if (exp.status === 'EMPTY') {
        assert(
          s.message?.kind === 'empty' && /not star-shaped/i.test(s.message.text),
          `empty-kernel message: ${JSON.stringify(s.message)}`,
        );
      } else {
        const ratio = Number(s.stats.ratio);
        assert(ratio > 0 && ratio <= 1 + 1e-12, `kernel/shape volume ratio ${ratio}`);
        assert(s.stats['kernel-point'].split(',').length === 3, `kernel point ${s.stats['kernel-point']}`);
      }
    });
  }

  // 4. Animation: plays on its own, scrubber shows growing prefixes, jump to end.
  await test('animation: plays, scrubber prefixes grow, jump to end, screenshot mid-animation', async () => {
    await page.evaluate(() => {
      // slow playback (1/8×) so that the first second shows a partial kernel
      const sp = document.getElementById('speed');
      sp.value = '-3';
      sp.dispatchEvent(new Event('input', { bubbles: true }));
    });
    const done = await loadSample(page, 'gear');
    const total = done.steps;
    const V = Number(done.stats.vertices),
      E = Number(done.stats.edges),
      F = Number(done.stats.faces);
    assert(total === V + E + F, `timeline has ${total} steps, result has ${V}+${E}+${F}`);
    await page.waitForTimeout(800);
    const playing = await readState(page);
    assert(
      playing.step > 0 && playing.step < total,
      `after 0.8 s playing at 1/8× (5 steps/s) the step is ${playing.step} of ${total}`,
    );
    const ks = [0, Math.floor(total * 0.15), Math.floor(total * 0.4), Math.floor(total * 0.75), total];
    const seen = [];
    for (const k of ks) seen.push((await scrubTo(page, k)).shown);
    assert(
      seen[0].vertices === 0 && seen[0].edges === 0 && seen[0].faces === 0,
      `step 0 shows ${JSON.stringify(seen[0])}`,
    );
    for (let i = 1; i < seen.length; i++) {
      const a = seen[i - 1],
        b = seen[i];
      assert(
        b.vertices >= a.vertices && b.edges >= a.edges && b.faces >= a.faces,
        `counts shrink: ${JSON.stringify(a)} → ${JSON.stringify(b)}`,
      );
      assert(b.vertices + b.edges + b.faces === ks[i], `step ${ks[i]} shows ${JSON.stringify(b)}`);
    }
    assert(seen[2].edges > seen[1].edges, `edges do not grow between steps ${ks[1]} and ${ks[2]}`);
    assert(seen[2].faces === 0, 'faces appear before the edges are traced');
    assert(
      seen[4].vertices === V && seen[4].edges === E && seen[4].faces === F,
      `end shows ${JSON.stringify(seen[4])}`,
    );
    await scrubTo(page, ks[2]);
    const px = await shoot(page, 'sample-mid-animation.png'); // edges traced so far, no faces yet
    await shoot(page, 'page-mid-animation.png', { fullPage: true });
    assert(px.amber > 1000, `input mesh hardly visible: ${px.amber} amber pixels`);
    assert(px.blue > 30, `partial kernel edges not visible: ${px.blue} kernel-blue pixels`);
    const late = await scrubTo(page, Math.floor((E + V + total) / 2)); // edges done, faces filling
    assert(late.shown.faces > 0 && late.shown.faces < F, `faces shown at step ${late.step}: ${late.shown.faces}`);
    const pxLate = await shoot(page, 'sample-faces-filling.png');
    assert(pxLate.blue > px.blue, `filling faces add no blue pixels (${px.blue} → ${pxLate.blue})`);
    await jumpToEnd(page);
    const end = await readState(page);
    assert(end.step === total, `jump to end: step ${end.step} of ${total}`);
    const px2 = await shoot(page, 'sample-gear-kernel.png');
    assert(px2.blue > 2000, `finished gear kernel: only ${px2.blue} kernel-blue pixels`);
  });
}

// Files through the picker, in every format the package reads.
export async function fileTests(page, tmp) {
  // 5. Files through the picker: the project's own samples written as OFF / STL / OBJ.
  const fileCases = [
    ['OFF (double precision)', 'dented-cube.off', 'dented-cube', writeOFF, 1e-9],
    ['binary STL (float32, welded)', 'plus-prism.stl', 'plus-prism', writeBinarySTL, 1e-6],
    ['ascii STL (double precision, welded)', 'star-prism.stl', 'star-prism', writeAsciiSTL, 1e-9],
    ['OBJ (double precision)', 'gear.obj', 'gear', writeOBJ, 1e-9],
  ];
  for (const [label, fname, id, writer, tol] of fileCases) {
    await test(`file picker: ${label} ${fname}`, async () => {
      const file = path.join(tmp, fname);
      writer(file, sampleById(id).build());
      const s = await loadFile(page, file);
      const exp = expectedKernel(sampleById(id));
      assert(s.status === 'POLYHEDRON', `status ${s.status}: ${JSON.stringify(s.message)}`);
      assertClose(Number(s.stats.volume), exp.volume, tol, 'kernel volume');
      assert(Number(s.stats.vertices) === exp.vertices, `vertices ${s.stats.vertices}, expected ${exp.vertices}`);
    });
  }

  // Polygon faces are computed as polygons: an L prism whose caps are single non-convex
  // hexagons has the unit cube for kernel (a fan of its caps would give a flat one).
  const lPrism = lPrismFiles();
  for (const [label, fname, text] of [
    ['OFF', 'l-prism.off', lPrism.off],
    ['OBJ', 'l-prism.obj', lPrism.obj],
  ]) {
    await test(`file picker: ${label} with non-convex polygon faces ${fname}`, async () => {
      const file = path.join(tmp, fname);
      fs.writeFileSync(file, text);
      const s = await loadFile(page, file);
      assert(s.status === 'POLYHEDRON', `status ${s.status}: ${JSON.stringify(s.message)}`);
      assertClose(Number(s.stats.volume), 1, 1e-12, 'kernel volume');
      assert(Number(s.stats.vertices) === 8, `vertices ${s.stats.vertices}, expected 8`);
      assert(Number(s.stats['input-faces']) === 8, `input faces ${s.stats['input-faces']}, expected 8 polygons`);
      // The caps are drawn (split by earcut for drawing only): the input's amber is on screen.
      const px = await shoot(page, `${fname}.png`);
      assert(px.amber > 2000, `L prism drawn with only ${px.amber} amber pixels`);
    });
  }

  // PLY (ascii, written here: vertex x y z, face vertex_indices); skipped with a package build
  // that does not read PLY.
  const plyFile = path.join(tmp, 'gear.ply');
  writePLY(plyFile, sampleById('gear').build());
  const plyProblem = await packageReadsFile(plyFile);
  if (plyProblem) skip('file picker: ascii PLY', `the package does not read it: ${plyProblem}`);
  else {
    await test('file picker: ascii PLY gear.ply', async () => {
      const s = await loadFile(page, plyFile);
      const exp = expectedKernel(sampleById('gear'));
      assert(s.status === 'POLYHEDRON', `status ${s.status}: ${JSON.stringify(s.message)}`);
      assertClose(Number(s.stats.volume), exp.volume, 1e-9, 'kernel volume');
    });
  }
}
