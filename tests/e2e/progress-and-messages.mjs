// Browser tests of the demo page: phases, Show result, replay speed, opacity and face edges;
// princeton/350.off against the native CLI, the empty-kernel message and broken files. Called by run.mjs.
import fs from 'node:fs';
import path from 'node:path';
import { sampleById } from '../../web/samples.js';
import { test, skip, assert, assertClose, sharedMeshes, nativeCli } from './harness.mjs';
import { writeOFF, CUBE_V, CUBE_Q, writeQuadOFF, writeEdgeSharingCubes, nativeKernel } from './mesh-files.mjs';
import {
  readState,
  markPending,
  waitFinished,
  loadSample,
  loadFile,
  scrubTo,
  jumpToEnd,
  shoot,
} from './page-state.mjs';

// Phases while a file is read and computed, Show result and replay speed, opacity, face edges.
export async function progressAndControls(page, tmp) {
  // The file is read in the worker: the page shows each phase as it comes.
  await test('file load shows the phases: reading (bytes), validating, planes, lp, tracing, assembling', async () => {
    const file = path.join(tmp, 'vase.off');
    writeOFF(file, sampleById('vase').build());
    const s = await loadFile(page, file);
    assert(s.status === 'POLYHEDRON', `status ${s.status}`);
    const phases = (await page.getAttribute('#busy', 'data-phases')).split(',');
    const want = ['loading', 'reading', 'validating', 'planes', 'lp', 'tracing', 'assembling', 'done'];
    const missing = want.filter((p) => !phases.includes(p));
    assert(missing.length === 0, `phases shown: ${phases.join(',')}; missing ${missing.join(',')}`);
    const order = want.filter((p) => p !== 'loading').map((p) => phases.indexOf(p));
    assert(
      order.every((x, i) => i === 0 || x > order[i - 1]),
      `phase order ${phases.join(',')}`,
    );
    const wall = await page.textContent('#stat-wall');
    assert(/^\d+ ms \(|^\d+(\.\d)? s \(/.test(wall), `load → kernel text "${wall}"`);
  });

  await test('the busy line names the phase while a big file is computed', async () => {
    const big = path.join(tmp, 'sphere-busy.off');
    const { radialSphere } = await import('../../web/samples.js');
    writeOFF(
      big,
      radialSphere(100, 200, () => 1),
    );
    await markPending(page);
    await page.setInputFiles('#file-input', big);
    const texts = new Set();
    const t = Date.now();
    while (Date.now() - t < 60000) {
      const st = await page.getAttribute('#status', 'data-state');
      if (!(await page.isHidden('#busy'))) texts.add((await page.textContent('#busy-text')).replace(/[\d,]+/g, 'N'));
      if (['done', 'error', 'cancelled'].includes(st)) break;
      await page.waitForTimeout(20);
    }
    const s = await waitFinished(page);
    assert(s.status === 'POLYHEDRON', `status ${s.status}`);
    console.log(`     busy texts seen: ${[...texts].join(' | ')}`);
    assert(
      [...texts].some((x) => /^Tracing the kernel · N steps/.test(x)),
      `no tracing progress seen: ${[...texts].join(' | ')}`,
    );
  });

  await test('Show result skips the replay; replay speed 1× fits the kernel in ≤ 10 s', async () => {
    await page.evaluate(() => {
      // speed 1× (an earlier test slowed it down)
      const sp = document.getElementById('speed');
      sp.value = '0';
      sp.dispatchEvent(new Event('input', { bubbles: true }));
    });
    const done = await loadSample(page, 'bumpy-sphere');
    const total = done.steps;
    assert(total > 400, `bumpy sphere kernel has ${total} steps`);
    await scrubTo(page, 0);
    await page.click('#play');
    await page.waitForTimeout(1000);
    const mid = await readState(page);
    // 1×: max(40, total / 10) steps per second, so about a tenth per second (frames allow slack).
    assert(mid.step > total * 0.04 && mid.step < total * 0.3, `after 1 s at 1×: step ${mid.step} of ${total}`);
    const label = await page.textContent('#speed-label');
    assert(label.includes(`${Math.round(total / 10)} steps/s`), `speed label "${label}"`);
    await page.click('#jump-end');
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const end = await readState(page);
    assert(
      end.step === total && end.shown.faces === Number(done.stats.faces),
      `after Show result: step ${end.step} of ${total}, ${JSON.stringify(end.shown)}`,
    );
  });

  await test('shape opacity: 0 hides the shape, 1 makes it opaque; face-edges toggle', async () => {
    await loadSample(page, 'gear');
    await jumpToEnd(page);
    const setRange = (id, v) =>
      page.evaluate(
        ({ id, v }) => {
          const el = document.getElementById(id);
          el.value = String(v);
          el.dispatchEvent(new Event('input', { bubbles: true }));
        },
        { id, v },
      );
    await page.click('#fit-view');
    const normal = await shoot(page, 'opacity-default.png');
    await setRange('opacity', 0);
    const hidden = await shoot(page, 'opacity-0.png');
    await setRange('opacity', 1);
    const opaque = await shoot(page, 'opacity-1.png');
    await setRange('opacity', 0.22);
    assert(
      hidden.amber < 50 && hidden.blue > normal.blue,
      `opacity 0: ${hidden.amber} amber, ${hidden.blue} blue (default ${normal.blue})`,
    );
    // Opaque, the shape hides the kernel's sides; its top face stays (it lies in the gear's top
    // plane, where the kernel is drawn over the shape).
    assert(
      opaque.amber > 3 * normal.amber && opaque.blue < 0.8 * normal.blue,
      `opacity 1: ${opaque.amber} amber (default ${normal.amber}), ${opaque.blue} blue (default ${normal.blue})`,
    );
    assert(await page.isChecked('#show-edges'), 'face edges on by default for a small mesh');
    await page.click('#show-edges');
    const noEdges = await shoot(page, 'edges-off.png');
    await page.click('#show-edges');
    const withEdges = await shoot(page, 'edges-on.png');
    assert(
      noEdges.meanLuminance > withEdges.meanLuminance,
      `edges off should be lighter: ${noEdges.meanLuminance} vs ${withEdges.meanLuminance}`,
    );
  });
}

// princeton/350.off against the CLI, the empty-kernel message and broken files.
export async function realMeshesAndMessages(page, tmp) {
  // 6. A real mesh: princeton/350.off via the file picker, against the native CLI.
  const p350 = path.join(sharedMeshes, 'princeton/350.off');
  if (!fs.existsSync(p350)) skip('princeton/350.off', `${p350} not found (shared meshes absent)`);
  else {
    await test('princeton/350.off via the file picker: POLYHEDRON, volume vs native CLI, kernel on screen', async () => {
      const s = await loadFile(page, p350);
      assert(s.status === 'POLYHEDRON', `status ${s.status}: ${s.statusText} ${JSON.stringify(s.message)}`);
      assert(Number(s.stats['input-faces']) === 17514, `input faces ${s.stats['input-faces']}`);
      const vol = Number(s.stats.volume);
      assert(vol > 0, `volume ${vol}`);
      console.log(
        `     350.off: V ${s.stats.vertices}, E ${s.stats.edges}, F ${s.stats.faces}, volume ${vol}, ratio ${s.stats.ratio}, planes ${s.stats.planes}, worker ${Number(s.stats.time).toFixed(1)} ms`,
      );
      const native = nativeKernel(p350);
      if (native) {
        assert(native.status === 'POLYHEDRON', `native status ${native.status}`);
        assertClose(vol, native.volume, 1e-9, 'volume vs build/kergen --json');
        console.log(`     native CLI volume ${native.volume} (match)`);
      } else {
        skip('princeton/350.off volume vs native CLI', `${nativeCli} not built (npm run build:native)`);
      }
      await jumpToEnd(page);
      // The kernel is tiny next to the shape (0.02 % of its volume): without the inscribed ball
      // drawn over it, and with the whole shape fitted above the play bar.
      await page.click('#show-ball');
      const px = await shoot(page, 'princeton-350-kernel.png');
      await page.click('#show-ball');
      assert(px.blue > 10, `only ${px.blue} kernel-blue pixels in the view`);
      await page.click('#fit-kernel');
      await page.waitForTimeout(300);
      const zoomed = await shoot(page, 'princeton-350-kernel-zoom.png');
      assert(
        zoomed.blue > 20 * px.blue && zoomed.blue > 20000,
        `zoom to kernel: ${px.blue} → ${zoomed.blue} kernel-blue pixels`,
      );
      await page.click('#fit-view');
    });
  }

  // 7. Messages: empty kernel, broken files.
  await test('U prism shows the empty-kernel message (screenshot)', async () => {
    const s = await loadSample(page, 'u-prism');
    assert(s.status === 'EMPTY' && s.message?.kind === 'empty', JSON.stringify(s));
    const shown = await page.isVisible('#message');
    assert(shown, '#message not visible');
    const px = await shoot(page, 'empty-kernel.png', { fullPage: true });
    assert(px.blue < 50, `${px.blue} kernel-blue pixels drawn for an empty kernel`);
    assert(px.amber > 1000, 'the input mesh is not drawn');
  });

  const broken = [
    // (refused by the package's reader, the CLI's, with the file's name and line)
    [
      'OFF with an out-of-range index',
      'bad-index.off',
      (f) => writeQuadOFF(f, CUBE_V, [...CUBE_Q.slice(0, 5), [3, 0, 4, 99]]),
      'PARSE_ERROR',
      /bad-index\.off:16: vertex index 99 out of range \(the file has 8 vertices\)/,
    ],
    [
      'open cube (one face missing)',
      'open-cube.off',
      (f) => writeQuadOFF(f, CUBE_V, CUBE_Q.slice(0, 5)),
      'OPEN_MESH',
      /open/i,
    ],
    ['two cubes sharing an edge', 'edge-cubes.off', writeEdgeSharingCubes, 'NON_MANIFOLD_EDGE', /manifold/i],
    [
      'unparseable OFF',
      'garbage.off',
      (f) => fs.writeFileSync(f, 'OFF\n3 1 0\n0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n'),
      'PARSE_ERROR',
      /garbage\.off:4: invalid number 'zero'/,
    ],
    [
      'OBJ face with a bad index',
      'bad-face.obj',
      (f) => fs.writeFileSync(f, 'v 0 0 0\nv 1 0 0\nv 0 1 0\n# a comment\nf 1 2 x\n'),
      'PARSE_ERROR',
      /bad-face\.obj:5: /,
    ],
    [
      'truncated binary STL',
      'short.stl',
      (f) => fs.writeFileSync(f, Buffer.alloc(20)),
      'PARSE_ERROR',
      /short\.stl: .*STL/,
    ],
    [
      'unsupported file type',
      'mesh.xyz',
      (f) => fs.writeFileSync(f, 'hello\n'),
      'PARSE_ERROR',
      /mesh\.xyz: unknown mesh format/,
    ],
  ];
  for (const [label, fname, make, code, re] of broken) {
    await test(`error message: ${label} → ${code}`, async () => {
      const file = path.join(tmp, fname);
      make(file);
      const s = await loadFile(page, file);
      assert(s.state === 'error', `state ${s.state} (${s.statusText})`);
      assert(s.message?.kind === 'error' && s.message.code === code, `message ${JSON.stringify(s.message)}`);
      assert(re.test(s.message.text), `message text "${s.message.text}" does not match ${re}`);
      assert(await page.isVisible('#message'), '#message not visible');
    });
  }
}
