// Browser tests of the demo's views (issue 28): inside the shape (deepest point and inscribed ball,
// hiding the shape, section plane with caps, no z-fighting), fitting, ?url= and shareable links,
// GLB/glTF, keyboard and accessibility (axe-core). Called by run.mjs with its helpers (`h`) after
// demo-states.mjs; screenshots go to tests/artifacts/.
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { sampleById } from '../../web/samples.js';
import { serve } from './page-tools.mjs';
import { writeGlb, writeGltf } from './gltf-files.mjs';
import { bumpySphere } from '../../scripts/gen-big-mesh.mjs';
import { lPrismFiles } from '../node/lib/example-meshes.mjs';
const require = createRequire(import.meta.url);
import { viewPixels, setRange, setChecked, controls, writeOpenBox } from './demo-view-tools.mjs';

export async function demoFeatureTests(page, context, base, tmp, h) {
  const {
    test,
    skip,
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
  } = h;
  const px = (name) => viewPixels(page, artifacts, name);
  const openCube = writeOpenBox(path.join(tmp, 'open-box.off'));

  // ------------------------------------------------------------------------ inside the shape
  const resetView = () =>
    page.evaluate(() => {
      const set = (id, on) => document.getElementById(id).checked !== on && document.getElementById(id).click();
      set('section-on', false);
      set('show-input', true);
      set('show-ball', true);
      const o = document.getElementById('opacity');
      o.value = '0.22';
      o.dispatchEvent(new Event('input', { bubbles: true }));
    });
  await test('hide/show the shape (H), section plane with caps, clipping the kernel, no z-fighting', async () => {
    try {
      await insideTests();
    } finally {
      await resetView();
    }
  });
  async function insideTests() {
    await loadSample(page, 'vase');
    await jumpToEnd(page);
    await page.click('#fit-view');
    const shown = await px('inside-shape-shown.png');
    await page.focus('#viewport canvas'); // the keys work from the view too
    await page.keyboard.press('h');
    const hidden = await px('inside-shape-hidden.png');
    assert(shown.amber > 1000 && hidden.amber < 50, `H: ${shown.amber} → ${hidden.amber} amber pixels`);
    await page.keyboard.press('h');
    await setRange(page, 'opacity', 0);
    await setChecked(page, 'show-ball', false);
    const noSection = await px('section-off.png');
    await page.keyboard.press('s');
    await page.selectOption('#section-axis', 'z');
    // Through the deepest point, the plane cuts the kernel; below the kernel's lowest vertex it
    // leaves none of it (the vase stands on z = 0 and is 1.72 high).
    const { deep, low } = await page.evaluate(() => {
      const r = window.kergenDemo.state.result;
      return { deep: r.deepestPoint[2], low: Math.min(...r.vertices.filter((_, i) => i % 3 === 2)) };
    });
    await setRange(page, 'section-pos', (deep / 1.72).toFixed(2));
    const cut = await px('section-z-caps.png');
    await setRange(page, 'section-pos', ((low - 0.03) / 1.72).toFixed(2));
    const below = await px('section-below-kernel.png');
    await setChecked(page, 'section-kernel', false);
    const belowUnclipped = await px('section-below-kernel-unclipped.png');
    await setChecked(page, 'section-kernel', true);
    await setRange(page, 'section-pos', (deep / 1.72).toFixed(2));
    await setRange(page, 'opacity', 0.22);
    await setChecked(page, 'show-ball', true);
    const cutTranslucent = await px('section-z-translucent.png');
    await page.screenshot({ path: path.join(artifacts, 'section-page.png') });
    console.log(
      `     section z at the deepest point: amber ${noSection.amber} → ${cut.amber} (shape hidden: its cap); below the kernel: blue ${below.blue} clipped, ${belowUnclipped.blue} not`,
    );
    // Opacity 0: the face edges stay (a few hundred amber-brown pixels), the cap of the cut is solid.
    assert(cut.amber > 5 * noSection.amber && cut.amber > 1500, `cap: ${noSection.amber} → ${cut.amber} amber pixels`);
    assert(
      below.blue < 30 && belowUnclipped.blue > 1000,
      `kernel clipped below its lowest vertex: ${below.blue} blue pixels (${belowUnclipped.blue} unclipped)`,
    );
    assert(cutTranslucent.amber > cut.amber, `translucent shape over its cap: ${cutTranslucent.amber} amber pixels`);
    await page.keyboard.press('s');
    assert(!(await page.isChecked('#section-on')), 'S turns the section off');

    // The gear's kernel lies in the gear's top plane: seen from above, an opaque shape must not
    // stripe it (polygon offset: the kernel wins where they coincide).
    await loadSample(page, 'gear');
    await jumpToEnd(page);
    const fromAbove = () =>
      page.evaluate(() => {
        const v = window.kergenDemo.viewer;
        v.controls.target.set(0, 0, 0);
        v.camera.position.set(0, -1e-3, 4 * v.radius);
        v.camera.lookAt(0, 0, 0);
        v.controls.update();
        v.dirty = true;
      });
    await fromAbove();
    await setRange(page, 'opacity', 0);
    const alone = await px('zfight-kernel-alone.png');
    await setRange(page, 'opacity', 1);
    await fromAbove();
    const opaque = await px('zfight-opaque-shape.png');
    await setRange(page, 'opacity', 0.22);
    console.log(`     gear from above: ${alone.blue} blue pixels alone, ${opaque.blue} under the opaque shape`);
    assert(
      alone.blue > 2000 && opaque.blue >= 0.97 * alone.blue,
      `kernel top face: ${alone.blue} → ${opaque.blue} blue pixels`,
    );
    await page.click('#fit-view');
  }

  // ------------------------------------------------------------------------------------ fit
  const fitCases = [
    ['the dented cube', { sample: 'dented-cube' }],
    ['refinements/vase4.off', { file: path.join(sharedMeshes, 'refinements/vase4.off') }],
    ['princeton/350.off', { file: path.join(sharedMeshes, 'princeton/350.off') }],
  ];
  for (const [label, what] of fitCases) {
    if (what.file && !fs.existsSync(what.file)) {
      skip(`fit view: ${label}`, `${what.file} not found`);
      continue;
    }
    await test(`fit view (F) fits ${label} entirely above the play bar, wide and narrow windows`, async () => {
      const sizes = [
        [1280, 800],
        [390, 844],
      ];
      try {
        for (const [w, hgt] of sizes) {
          await page.setViewportSize({ width: w, height: hgt });
          await page.waitForTimeout(200);
          if (what.sample) await loadSample(page, what.sample);
          else await loadFile(page, what.file);
          await jumpToEnd(page);
          await page.evaluate(() => document.activeElement?.blur());
          await page.keyboard.press('f');
          const p = await px(`fit-${path.basename(label).replace(/\W+/g, '-')}-${w}.png`);
          const fill = Math.max((p.hi[0] - p.lo[0] + 1) / p.width, (p.hi[1] - p.lo[1] + 1) / p.height);
          console.log(
            `     ${label} ${w}×${hgt}: shape spans ${p.lo}–${p.hi} of ${p.width}×${p.height} (fills ${(100 * fill).toFixed(0)} %), ${p.border} pixels on the border`,
          );
          assert(p.border === 0, `${p.border} shape pixels touch the visible area's border at ${w}×${hgt}`);
          assert(fill > 0.6, `the shape fills only ${(100 * fill).toFixed(0)} % of the visible area at ${w}×${hgt}`);
        }
      } finally {
        await page.setViewportSize({ width: 1280, height: 800 });
        await page.waitForTimeout(200);
      }
    });
  }

  // ----------------------------------------------------------------------- links and sharing
  await test('?url= opens a mesh by link; a link to this view reopens sample, options and section', async () => {
    const off = path.join(tmp, 'linked-l-prism.off');
    fs.writeFileSync(off, lPrismFiles().off);
    served.set('/__files/linked-l-prism.off', off);
    const second = await context.newPage();
    try {
      await second.goto(`${base}?url=${encodeURIComponent(`${base}__files/linked-l-prism.off`)}&opacity=0.5`);
      const s = await waitFinished(second);
      assert(s.status === 'POLYHEDRON', JSON.stringify(s));
      assertClose(Number(s.stats.volume), 1, 1e-12, 'linked L prism kernel volume');
      assert((await second.inputValue('#opacity')) === '0.5', 'opacity from the link');
      assert((await second.inputValue('#share-url')).includes('url='), 'the link of a ?url= mesh');

      await markPending(page);
      await page.click('[data-sample="dented-cube"]');
      await waitFinished(page);
      await setRange(page, 'opacity', 0.4);
      await setChecked(page, 'section-on', true);
      await page.selectOption('#section-axis', 'x');
      await setRange(page, 'section-pos', 0.3);
      await setChecked(page, 'show-ball', false);
      const link = await page.inputValue('#share-url');
      assert(link === page.url(), `the address bar is the link: ${page.url()} vs ${link}`);
      await second.goto(link);
      const r = await waitFinished(second);
      const got = await second.evaluate(() => ({
        sample: document.querySelector('#samples button.active')?.dataset.sample,
        opacity: document.getElementById('opacity').value,
        section: document.getElementById('section-on').checked,
        axis: document.getElementById('section-axis').value,
        pos: document.getElementById('section-pos').value,
        ball: document.getElementById('show-ball').checked,
      }));
      assert(
        JSON.stringify(got) ===
          JSON.stringify({ sample: 'dented-cube', opacity: '0.4', section: true, axis: 'x', pos: '0.3', ball: false }),
        `reopened ${JSON.stringify(got)} from ${link}`,
      );
      assertClose(Number(r.stats.volume), 1 / 3, 1e-12, 'reopened kernel volume');
      await setChecked(page, 'section-on', false);
      await setChecked(page, 'show-ball', true);
      await setRange(page, 'opacity', 0.22);
    } finally {
      await second.close();
    }
  });

  await test('?url=: a server without CORS, an HTTP 404 and a non-http address each get a clear error', async () => {
    const other = await serve(path.dirname(openCube));
    const cors = await serve(path.dirname(openCube), new Map(), { cors: true });
    const p2 = await context.newPage();
    try {
      const otherBase = `http://127.0.0.1:${other.address().port}/`;
      const cases = [
        [`${otherBase}open-box.off`, /does not allow this page to read it \(no CORS header/],
        [`${base}__files/missing.off`, /HTTP 404/],
        ['ftp://example.invalid/x.off', /must be an http or https address/],
      ];
      for (const [url, re] of cases) {
        await p2.goto(`${base}?url=${encodeURIComponent(url)}`);
        const s = await waitFinished(p2);
        assert(
          s.state === 'error' && s.message?.code === 'URL_ERROR' && re.test(s.message.text),
          `${url}: ${JSON.stringify(s.message)}`,
        );
        const c = await controls(p2);
        assert(c.play.disabled && c.play.text === 'Play', `${url}: play ${JSON.stringify(c.play)}`);
      }
      await p2.screenshot({ path: path.join(artifacts, 'state-error-url.png') });
      // The same file from a server that allows any origin: read, OPEN_MESH with its open edges.
      await p2.goto(`${base}?url=${encodeURIComponent(`http://127.0.0.1:${cors.address().port}/open-box.off`)}`);
      const s = await waitFinished(p2);
      assert(s.message?.code === 'OPEN_MESH', `cross-origin with CORS: ${JSON.stringify(s.message)}`);
    } finally {
      await p2.close();
      other.close();
      cors.close();
    }
  });

  // ----------------------------------------------------------------------------------- glTF
  const dented = sampleById('dented-cube').build();
  const gltfCases = [
    ['GLB', 'dented-two-nodes.glb', (f) => writeGlb(f, dented, 5)],
    ['glTF (embedded buffer)', 'dented-two-nodes.gltf', (f) => writeGltf(f, dented, 9)],
  ];
  for (const [label, fname, make] of gltfCases) {
    await test(`file picker: ${label}, two meshes merged in world space and welded → the dented cube's kernel`, async () => {
      const file = path.join(tmp, fname);
      make(file);
      const s = await loadFile(page, file);
      assert(s.status === 'POLYHEDRON', JSON.stringify(s));
      assertClose(Number(s.stats.volume), 1 / 3, 1e-6, 'kernel volume (float32 positions)');
      assert(Number(s.stats['input-faces']) === 14, `input faces ${s.stats['input-faces']}`);
      assert(/vertices .*were merged/i.test(s.message?.text ?? ''), `weld noted: ${JSON.stringify(s.message)}`);
    });
  }
  // Above 20,000 faces the page draws the input in its drawing worker, which then keeps the
  // mesh: a big GLB (its arrays copied for that worker) and the open edges of a big open mesh.
  await test('big inputs (drawn by the drawing worker): a 40k-triangle GLB; the open edges of a 40k-triangle open mesh', async () => {
    const big = bumpySphere(200, 101); // 40,000 triangles
    const glb = path.join(tmp, 'bumpy-40k.glb');
    writeGlb(glb, big, 15000, { shift: 0 });
    const s = await loadFile(page, glb);
    const direct = await page.evaluate(() => window.kergenDemo.state.result.status);
    assert(
      s.status === 'POLYHEDRON' && direct === 'POLYHEDRON' && Number(s.stats['input-faces']) === 40000,
      `big GLB: ${JSON.stringify(s)}`,
    );
    // The same sphere with the 200 triangles around its north pole removed: 200 open edges.
    const open = path.join(tmp, 'bumpy-40k-open.off');
    const lines = ['OFF', `${big.positions.length / 3} ${big.indices.length / 3 - 200} 0`];
    for (let i = 0; i < big.positions.length; i += 3)
      lines.push(`${big.positions[i]} ${big.positions[i + 1]} ${big.positions[i + 2]}`);
    for (let t = 0; t < big.indices.length; t += 3) {
      const tri = big.indices.subarray(t, t + 3);
      if (!tri.includes(0)) lines.push(`3 ${tri.join(' ')}`);
    }
    fs.writeFileSync(open, lines.join('\n') + '\n');
    const o = await loadFile(page, open);
    assert(o.message?.code === 'OPEN_MESH', JSON.stringify(o.message));
    const count = Number(await page.getAttribute('#stat-open-edges', 'data-value'));
    assert(count === 200, `open edges of the big mesh: ${count}`);
  });

  await test('file picker: a .gltf whose buffer is a separate file says so', async () => {
    const file = path.join(tmp, 'external.gltf');
    writeGltf(file, dented, 5, { external: true });
    const s = await loadFile(page, file);
    assert(
      s.state === 'error' &&
        s.message?.code === 'PARSE_ERROR' &&
        /refers to files beside it \(buffer\.bin\)/.test(s.message.text),
      JSON.stringify(s.message),
    );
  });

  // ------------------------------------------------------------------------ keyboard and a11y
  await test('keyboard: F/K/Space work with a sample button focused; the file picker by Tab and Enter', async () => {
    await loadSample(page, 'gear');
    await jumpToEnd(page);
    await page.focus('[data-sample="gear"]');
    const distance = () =>
      page.evaluate(() => {
        const v = window.kergenDemo.viewer;
        return v.camera.position.distanceTo(v.controls.target);
      });
    await page.evaluate(() => {
      const v = window.kergenDemo.viewer;
      v.camera.position.multiplyScalar(3);
      v.controls.update();
    });
    const far = await distance();
    await page.keyboard.press('f');
    const fitted = await distance();
    await page.keyboard.press('k');
    const kernel = await distance();
    assert(fitted < far / 2 && kernel < fitted, `distances: moved away ${far}, F ${fitted}, K ${kernel}`);
    const token = await page.evaluate(() => window.kergenDemo.state.token);
    await page.keyboard.press(' ');
    const after = await page.evaluate(() => ({
      token: window.kergenDemo.state.token,
      playing: window.kergenDemo.state.playing,
      text: document.getElementById('play').textContent,
    }));
    assert(
      after.token === token && after.playing && after.text === 'Pause',
      `Space on a focused sample button: ${JSON.stringify(after)} (run ${token})`,
    );
    await page.click('#jump-end');

    await page.evaluate(() => document.activeElement?.blur());
    let focused = '';
    for (let i = 0; i < 6 && focused !== 'open-file'; i++) {
      await page.keyboard.press('Tab');
      focused = await page.evaluate(() => document.activeElement?.id ?? '');
    }
    assert(focused === 'open-file', `Tab reached "${focused}", not the file picker`);
    const file = path.join(tmp, 'tab-enter.off');
    fs.copyFileSync(openCube, file);
    await markPending(page);
    const chooserPromise = page.waitForEvent('filechooser', { timeout: 10000 });
    await page.waitForTimeout(300); // playwright turns on file-chooser interception asynchronously
    await page.keyboard.press('Enter');
    const chooser = await chooserPromise;
    await chooser.setFiles(file);
    const s = await waitFinished(page);
    assert(s.message?.code === 'OPEN_MESH', `the file chosen by keyboard was opened: ${JSON.stringify(s.message)}`);
  });

  await test('accessibility: axe-core finds no serious or critical violation (done, error, empty; light and dark)', async () => {
    await page.addScriptTag({ path: require.resolve('axe-core/axe.min.js') });
    const runs = [];
    const check = async (label) => {
      const v = await page.evaluate(async () =>
        (await window.axe.run(document, { resultTypes: ['violations'] })).violations.map((x) => ({
          id: x.id,
          impact: x.impact,
          nodes: x.nodes.length,
          target: x.nodes[0]?.target?.join(' '),
        })),
      );
      runs.push({ label, v });
    };
    await check('error (open box, retry buttons)');
    await loadSample(page, 'u-prism');
    await check('empty');
    await loadSample(page, 'gear');
    await jumpToEnd(page);
    await setChecked(page, 'section-on', true);
    await check('done, section on');
    await page.emulateMedia({ colorScheme: 'dark' });
    await page.waitForTimeout(200);
    await check('done, dark');
    await page.screenshot({ path: path.join(artifacts, 'page-dark-section.png') });
    await page.emulateMedia({ colorScheme: 'light' });
    await setChecked(page, 'section-on', false);
    for (const r of runs)
      console.log(
        `     axe ${r.label}: ${r.v.length ? r.v.map((x) => `${x.id} (${x.impact}, ${x.nodes})`).join(', ') : 'no violations'}`,
      );
    const bad = runs.flatMap((r) =>
      r.v
        .filter((x) => x.impact === 'serious' || x.impact === 'critical')
        .map((x) => `${r.label}: ${x.id} ${x.impact} at ${x.target}`),
    );
    assert(bad.length === 0, bad.join(' | '));
    const unnamed = await page.evaluate(() =>
      [...document.querySelectorAll('button, input:not([type=hidden]), select')]
        .filter(
          (el) =>
            !el.hidden &&
            el.type !== 'file' &&
            !(el.labels?.length || el.getAttribute('aria-label') || el.textContent.trim()),
        )
        .map((el) => el.id),
    );
    assert(unnamed.length === 0, `controls without a name: ${unnamed}`);
  });
}
