// Browser tests of the demo page: export read back by dropping, drag & drop timing, and cancelling
// a long run while the page keeps animating. Called by run.mjs.
import fs from 'node:fs';
import path from 'node:path';
import { test, skip, assert, assertClose, sharedMeshes, artifacts } from './harness.mjs';
import { writeOFF, nativeKernel } from './mesh-files.mjs';
import { readState, markPending, waitFinished, loadSample, dropFile, jumpToEnd } from './page-state.mjs';

// Export through the package (read back by dropping), and drag & drop timing of 325.off.
export async function exportAndDrop(page, tmp) {
  // 8. Export.
  await test('export OBJ, STL and OFF of the plus-prism kernel (the package writer), each read back by the page', async () => {
    const s = await loadSample(page, 'plus-prism');
    assert(s.status === 'POLYHEDRON', s.status);
    const files = {};
    for (const format of ['obj', 'stl', 'off']) {
      const [dl] = await Promise.all([page.waitForEvent('download'), page.click(`#export-${format}`)]);
      assert(
        dl.suggestedFilename() === `Plus_prism-kernel.${format}` ||
          dl.suggestedFilename().endsWith(`-kernel.${format}`),
        dl.suggestedFilename(),
      );
      files[format] = path.join(tmp, `exported-kernel.${format}`);
      fs.copyFileSync(await dl.path(), files[format]);
    }
    const obj = fs.readFileSync(files.obj, 'utf8');
    const vs = obj
      .split('\n')
      .filter((l) => l.startsWith('v '))
      .map((l) => l.split(/\s+/).slice(1).map(Number));
    const fs_ = obj.split('\n').filter((l) => l.startsWith('f '));
    assert(vs.length === 8 && fs_.length === 6, `OBJ has ${vs.length} vertices, ${fs_.length} faces`);
    for (const v of vs)
      assert(
        Math.abs(Math.abs(v[0]) - 0.3) < 1e-12 && Math.abs(Math.abs(v[1]) - 0.3) < 1e-12,
        `vertex ${v} off the central column`,
      );
    const stl = fs.readFileSync(files.stl);
    assert(
      stl.length === 84 + 50 * 12 && stl.readUInt32LE(80) === 12,
      `STL: ${stl.length} bytes, ${stl.readUInt32LE(80)} triangles`,
    );
    const off = fs.readFileSync(files.off, 'utf8').split('\n');
    assert(
      /^OFF/.test(off[0]) && /^8 6 /.test(off.find((l, i) => i > 0 && !l.startsWith('#'))),
      `OFF header ${off.slice(0, 3).join(' | ')}`,
    );
    // Each file, dropped back on the page, is a cube-like kernel of itself with the same volume.
    for (const format of ['obj', 'stl', 'off']) {
      const back = await dropFile(page, files[format]);
      assert(back.status === 'POLYHEDRON', `${format} read back: ${back.status} ${JSON.stringify(back.message)}`);
      assertClose(
        Number(back.stats.volume),
        Number(s.stats.volume),
        format === 'stl' ? 1e-6 : 1e-12,
        `${format} kernel volume`,
      );
    }
  });

  // 9. Drag & drop and timing: princeton/325.off.
  const p325 = path.join(sharedMeshes, 'princeton/325.off');
  if (!fs.existsSync(p325)) skip('princeton/325.off drop timing', `${p325} not found`);
  else {
    await test('drag & drop princeton/325.off: kernel, drop → kernel time', async () => {
      const runs = [];
      for (let i = 0; i < 3; i++) {
        await jumpToEnd(page); // drop onto an idle page (no replay frames being rendered)
        await page.waitForTimeout(300);
        runs.push(await dropFile(page, p325));
      }
      const s = runs[runs.length - 1];
      assert(s.status === 'POLYHEDRON', `status ${s.status}: ${JSON.stringify(s.message)}`);
      const wall = runs.map((r) => Number(r.stats.wall));
      const detail = await page.textContent('#stat-wall');
      const worker = runs.map((r) => Number(r.stats.time));
      console.log(
        `     325.off (${s.stats['input-faces']} faces, kernel V ${s.stats.vertices} E ${s.stats.edges} F ${s.stats.faces}):` +
          ` drop → final kernel ${wall.map((x) => x.toFixed(0)).join(' / ')} ms in the page` +
          ` (worker msTotal ${worker.map((x) => x.toFixed(0)).join(' / ')} ms; test-side ${runs.map((r) => r.testMs).join(' / ')} ms incl. polling)`,
      );
      console.log(`     last run: ${detail}`);
      const native = nativeKernel(p325);
      if (native) assertClose(Number(s.stats.volume), native.volume, 1e-9, 'volume vs build/kergen --json');
    });
  }
}

// Cancel a long run while the page keeps animating.
export async function cancelTest(page, tmp) {
  // 10. Cancel on a large input; the page stays responsive while the worker computes. Convex
  // spheres (kernel = the whole shape, the most work per face); bigger ones if a run ends first.
  await test('cancel a long run; the page keeps animating meanwhile', async () => {
    const { radialSphere } = await import('../../web/samples.js');
    let cancelled = false;
    for (const [nlat, nlon] of [
      [100, 200],
      [200, 400],
      [400, 800],
    ]) {
      const big = path.join(tmp, `sphere-${nlat}x${nlon}.off`);
      writeOFF(
        big,
        radialSphere(nlat, nlon, () => 1),
      );
      await markPending(page);
      await page.setInputFiles('#file-input', big);
      await page.waitForFunction(
        () =>
          document.getElementById('status').dataset.state !== 'test-pending' &&
          document.getElementById('status').dataset.state !== 'reading',
        null,
        { timeout: 60000, polling: 10 },
      );
      // Event-loop latency (a blocked main thread shows as one long gap) and frame gaps.
      const { maxGap, maxFrameGap, ticks } = await page.evaluate(
        () =>
          new Promise((resolve) => {
            const t0 = performance.now();
            let last = t0,
              gap = 0,
              lastFrame = t0,
              frameGap = 0,
              done = false,
              n = 0;
            const tick = () => {
              const now = performance.now();
              n++;
              gap = Math.max(gap, now - last);
              last = now;
              if (now - t0 < 1500) setTimeout(tick, 5);
              else {
                done = true;
                resolve({ maxGap: gap, maxFrameGap: frameGap, ticks: n });
              }
            };
            const frame = (now) => {
              frameGap = Math.max(frameGap, now - lastFrame);
              lastFrame = now;
              if (!done) requestAnimationFrame(frame);
            };
            setTimeout(tick, 5);
            requestAnimationFrame(frame);
          }),
      );
      const before = await readState(page);
      if (before.state === 'computing') await page.screenshot({ path: path.join(artifacts, 'state-computing.png') });
      if (before.state !== 'computing') {
        console.log(
          `     ${2 * nlat * nlon} triangles finished before cancel (${before.state} ${before.status}); trying a bigger sphere`,
        );
        continue;
      }
      // The run can end between the check above and the click: then try a bigger sphere.
      const clicked = await page.evaluate(() => {
        const b = document.getElementById('cancel');
        if (b.disabled) return false;
        b.click();
        return true;
      });
      if (!clicked) {
        console.log(`     ${2 * nlat * nlon} triangles finished just before cancel; trying a bigger sphere`);
        await waitFinished(page);
        continue;
      }
      const s = await waitFinished(page, 10000);
      assert(
        s.state === 'cancelled' && s.message?.code === 'CANCELLED',
        `after cancel: ${s.state} ${JSON.stringify(s.message)}`,
      );
      // The controls and the message say what is shown: the steps that had arrived, or none.
      const play = await page.evaluate(() => ({
        text: document.getElementById('play').textContent,
        disabled: document.getElementById('play').disabled,
      }));
      assert(play.text === 'Play', `after cancel the play button reads "${play.text}"`);
      assert(
        s.steps > 0
          ? s.message.text.includes(`the ${s.steps.toLocaleString('en-US')} steps that had arrived`) && !play.disabled
          : /nothing of it is shown/.test(s.message.text) && play.disabled,
        `cancel with ${s.steps} steps shown: "${s.message.text}", play ${JSON.stringify(play)}`,
      );
      await page.screenshot({ path: path.join(artifacts, 'state-cancelled.png') });
      // A computation on the main thread would block the whole 1.5 s window. With software GL
      // the first frame of the new mesh alone can take ~0.3 s, so: the event loop must run
      // freely (≥ 50 of ~250 possible 5 ms timer ticks) and never stall for 1 s.
      assert(
        ticks >= 50 && maxGap < 1000,
        `main thread blocked while the worker computed: ${ticks} timer ticks in 1.5 s, longest gap ${maxGap.toFixed(0)} ms`,
      );
      console.log(
        `     ${2 * nlat * nlon}-triangle sphere: ${before.steps} steps streamed in the first 1.5 s, ${ticks} timer ticks in 1.5 s, longest event-loop gap ${maxGap.toFixed(0)} ms, longest frame gap ${maxFrameGap.toFixed(0)} ms (software GL), cancelled`,
      );
      cancelled = true;
      break;
    }
    assert(cancelled, 'every run finished before it could be cancelled');
    const again = await loadSample(page, 'l-prism'); // the worker is usable after a cancel
    assert(again.status === 'POLYHEDRON', `after cancel, L prism: ${again.status}`);
  });
}
