// Browser tests of issue 35's page flows: a refused mesh leads to the action that works (its
// alternatives computed before they are offered, best first, explained in the page's words); walls
// that empty an open surface's kernel are said to be the walls; what bounds a kernel face (hover);
// the inscribed ball drawn once the kernel is complete, outlined when it would hide the kernel;
// opacity 0 hides the face edges; a ?url= that returns a web page; the phone layout (the verdict
// and its actions above the fold at 390 × 844); axe-core on the new states; screenshots of each
// state at 1280 × 800 and 390 × 844 (tests/artifacts/flow-*.png). Called by run.mjs with its
// helpers (`h`).
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { viewPixels, setRange, controls } from './demo-view-tools.mjs';
import { bumpySphere } from '../../scripts/gen-big-mesh.mjs';
import { CUBE_V, CUBE_Q } from './mesh-files.mjs';

const require = createRequire(import.meta.url);

function writeOFF(file, positions, faces) {
  const lines = ['OFF', `${positions.length / 3} ${faces.length} 0`];
  for (let i = 0; i < positions.length; i += 3) lines.push(positions.slice(i, i + 3).join(' '));
  for (const f of faces) lines.push(`${f.length} ${f.join(' ')}`);
  fs.writeFileSync(file, lines.join('\n') + '\n');
}

// A polygon mesh built from points by value (a shared point is one vertex).
function polygonMesh(faces) {
  const positions = [],
    ids = new Map();
  const v = (p) => {
    const key = p.join(',');
    if (!ids.has(key)) {
      ids.set(key, positions.length / 3);
      positions.push(...p);
    }
    return ids.get(key);
  };
  return { positions, faces: faces.map((f) => f.map(v)) };
}

// A 10 × 10 × 10 box whose top is four squares around its centre, while the four sides keep
// their whole top edge: the top's edge midpoints are T-junctions (closed geometrically, open as
// indexed), as in a modelled part whose faces were split on one side only. Kernel: the box, 1000.
function tJunctionBox() {
  const c = (x, y, z) => [10 * x, 10 * y, 10 * z];
  return polygonMesh([
    [c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)],
    [c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)],
    [c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1)],
    [c(1, 1, 0), c(0, 1, 0), c(0, 1, 1), c(1, 1, 1)],
    [c(0, 1, 0), c(0, 0, 0), c(0, 0, 1), c(0, 1, 1)],
    [c(0, 0, 1), c(0.5, 0, 1), c(0.5, 0.5, 1), c(0, 0.5, 1)],
    [c(0.5, 0, 1), c(1, 0, 1), c(1, 0.5, 1), c(0.5, 0.5, 1)],
    [c(0.5, 0.5, 1), c(1, 0.5, 1), c(1, 1, 1), c(0.5, 1, 1)],
    [c(0, 0.5, 1), c(0.5, 0.5, 1), c(0.5, 1, 1), c(0, 1, 1)],
  ]);
}

// A stepped block (a 10 × 10 × 5 slab with a 10 × 5 × 5 step on its front half) whose two side
// walls are each two rectangles: the corners where they meet lie inside the other rectangle's
// edge, and inside the front's and the step's edges (T-junctions). Kernel: the slab's front
// half, [0,10] × [0,5] × [0,5], volume 250 (the step's riser and top bound it).
function steppedBlock() {
  return polygonMesh([
    [
      [0, 0, 0],
      [0, 10, 0],
      [10, 10, 0],
      [10, 0, 0],
    ],
    [
      [0, 0, 0],
      [10, 0, 0],
      [10, 0, 10],
      [0, 0, 10],
    ],
    [
      [10, 10, 0],
      [0, 10, 0],
      [0, 10, 5],
      [10, 10, 5],
    ],
    [
      [10, 5, 5],
      [10, 10, 5],
      [0, 10, 5],
      [0, 5, 5],
    ],
    [
      [0, 5, 10],
      [10, 5, 10],
      [10, 5, 5],
      [0, 5, 5],
    ],
    [
      [0, 0, 10],
      [10, 0, 10],
      [10, 5, 10],
      [0, 5, 10],
    ],
    [
      [0, 0, 0],
      [0, 0, 5],
      [0, 10, 5],
      [0, 10, 0],
    ],
    [
      [0, 0, 5],
      [0, 0, 10],
      [0, 5, 10],
      [0, 5, 5],
    ],
    [
      [10, 0, 0],
      [10, 10, 0],
      [10, 10, 5],
      [10, 0, 5],
    ],
    [
      [10, 0, 5],
      [10, 5, 5],
      [10, 5, 10],
      [10, 0, 10],
    ],
  ]);
}

// A UV ball (6 bands × 8 sectors, unit radius) with 4 triangles removed: as an open surface its
// kernel is a polyhedron, but the walls at its 12 boundary edges have no common point with its
// faces' inner sides (the walls empty it).
function openBall(n = 6, m = 8, removed = [5, 7, 12, 29]) {
  const P = [0, 0, 1];
  for (let i = 1; i < n; i++) {
    const th = (Math.PI * i) / n;
    for (let j = 0; j < m; j++) {
      const ph = (2 * Math.PI * j) / m;
      P.push(Math.sin(th) * Math.cos(ph), Math.sin(th) * Math.sin(ph), Math.cos(th));
    }
  }
  P.push(0, 0, -1);
  const S = P.length / 3 - 1;
  const id = (i, j) => 1 + (i - 1) * m + (((j % m) + m) % m);
  const T = [];
  for (let j = 0; j < m; j++) T.push([0, id(1, j), id(1, j + 1)]);
  for (let i = 1; i < n - 1; i++)
    for (let j = 0; j < m; j++) {
      T.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
      T.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
    }
  for (let j = 0; j < m; j++) T.push([S, id(n - 1, j + 1), id(n - 1, j)]);
  return { positions: P, faces: T.filter((_, k) => !removed.includes(k)) };
}

// The package's own answer in Node (an independent call of the same core) for meshes whose kernel
// has no closed form here.
async function nodeKernel(mesh, options) {
  const K = await import('../../wasm/index.js');
  await K.init();
  return K.computeKernelSync(Float64Array.from(mesh.positions), Uint32Array.from(mesh.faces.flat()), {
    faceSizes: Uint32Array.from(mesh.faces.map((f) => f.length)),
    ...options,
  });
}

// The refusal's alternatives, once tried and offered: the visible retry buttons in page order.
async function offered(page) {
  await page.waitForFunction(() => ['ready', 'none'].includes(document.getElementById('actions').dataset.state), null, {
    timeout: 60000,
  });
  return page.evaluate(() =>
    [...document.querySelectorAll('#actions button')]
      .filter((b) => !b.hidden)
      .map((b) => ({ id: b.id, alt: b.dataset.alt, outcome: b.dataset.outcome, text: b.textContent })),
  );
}

const OPTION_NAMES = /weld: true|allowOpen|repair: true|open: 'perpendicular'|Options::|within 0\b/;

// Where the verdict and its actions end on the page (CSS pixels from the top of the viewport).
const fold = (page) =>
  page.evaluate(() => {
    const bottom = (id) => {
      const el = document.getElementById(id);
      return el.hidden ? 0 : el.getBoundingClientRect().bottom;
    };
    return {
      statusTop: document.getElementById('status').getBoundingClientRect().top,
      status: bottom('status'),
      actions: bottom('actions'),
      title: document.querySelector('#message b')?.getBoundingClientRect().bottom ?? 0,
      height: window.innerHeight,
    };
  });

export async function demoRefusalTests(page, context, base, tmp, h) {
  const { test, skipTest, assert, assertClose, loadFile, waitFinished, markPending, jumpToEnd, artifacts } = h;
  const px = (name) => viewPixels(page, artifacts, name);
  const files = {};
  for (const [name, mesh] of Object.entries({
    'tjunction-box.off': tJunctionBox(),
    'stepped-block.off': steppedBlock(),
    'open-ball.off': openBall(),
  })) {
    files[name] = { file: path.join(tmp, name), mesh };
    writeOFF(files[name].file, mesh.positions, mesh.faces);
  }
  await setRange(page, 'opacity', 0.22); // earlier tests may have left the shape hidden
  const click = async (id) => {
    await markPending(page);
    await page.click(`#${id}`);
    const s = await waitFinished(page);
    if (s.steps > 0) await jumpToEnd(page);
    return s;
  };

  await test('refusal: T-junction box: repair is tried first and offered first, in words; it gives the box (volume 1000)', async () => {
    const s = await loadFile(page, files['tjunction-box.off'].file);
    assert(s.state === 'error' && s.message?.code === 'OPEN_MESH', JSON.stringify(s));
    const o = await offered(page);
    assert(o.length >= 1 && o[0].id === 'retry-repair' && o[0].outcome === 'POLYHEDRON', JSON.stringify(o));
    const text = await page.textContent('#message');
    assert(!OPTION_NAMES.test(text), `option names in the message: "${text}"`);
    assert(
      /4 vertices lie inside another face's edge \(T-junctions\)/.test(text) && /repair splits the edges/.test(text),
      text,
    );
    assert(/polyhedron \(volume 1000\)/.test(text), text);
    await page.screenshot({ path: path.join(artifacts, 'flow-tjunction-refused-1280.png') });
    const r = await click(o[0].id);
    assert(r.status === 'POLYHEDRON', JSON.stringify(r));
    assertClose(Number(r.stats.volume), 1000, 1e-12, 'repaired T-junction box kernel volume (the box)');
    // The tried result is shown as it was computed, not computed a second time.
    const wall = await page.textContent('#stat-wall');
    assert(/computed while trying the ways offered/.test(wall) && !/worker round trip/.test(wall), wall);
    const note = await page.textContent('#message');
    assert(/T-junctions/.test(note) && !OPTION_NAMES.test(note), `repair note "${note}"`);
    await page.screenshot({ path: path.join(artifacts, 'flow-tjunction-repaired-1280.png') });
  });

  await test('refusal: stepped block with split side walls: the first offered action gives the analytic kernel (250)', async () => {
    const s = await loadFile(page, files['stepped-block.off'].file);
    assert(s.state === 'error', JSON.stringify(s));
    const o = await offered(page);
    assert(o.length >= 1, 'nothing offered');
    const r = await click(o[0].id);
    assert(r.status === 'POLYHEDRON', `first offered ${o[0].id}: ${JSON.stringify(r)}`);
    assertClose(Number(r.stats.volume), 250, 1e-12, `kernel volume after "${o[0].text}"`);
  });

  await test('refusal: open ball: the open surface first (a polyhedron), walls second and said to empty it; walls drawn', async () => {
    const ball = files['open-ball.off'];
    const s = await loadFile(page, ball.file);
    assert(s.state === 'error' && s.message?.code === 'OPEN_MESH', JSON.stringify(s));
    const o = await offered(page);
    assert(
      o[0]?.id === 'retry-open' &&
        o[0].outcome === 'POLYHEDRON' &&
        o.some((b) => b.id === 'retry-walls' && b.outcome === 'EMPTY'),
      JSON.stringify(o),
    );
    const text = await page.textContent('#message');
    assert(/the walls make the kernel empty/.test(text) && !OPTION_NAMES.test(text), text);
    assert(/Repair was tried: refused too/.test(text), text);
    await page.screenshot({ path: path.join(artifacts, 'flow-open-ball-refused-1280.png') });
    // Walls: empty, and said to be the walls' doing (the open surface's kernel named).
    const w = await click('retry-walls');
    assert(w.status === 'EMPTY', JSON.stringify(w));
    const c = await controls(page);
    const wtext = await page.textContent('#message');
    assert(c.outcome === 'empty' && !/not star-shaped/i.test(wtext + w.statusText), `${w.statusText} / ${wtext}`);
    assert(/walls/.test(w.statusText) && /Without the walls .* polyhedron/.test(wtext), wtext);
    const edges = await page.evaluate(() => window.kergenDemo.state.result.witnessBoundaryEdges?.length ?? null);
    await setRange(page, 'opacity', 0.1);
    const p = await px('flow-open-ball-walls-empty-view.png');
    await page.screenshot({ path: path.join(artifacts, 'flow-open-ball-walls-empty-1280.png') });
    await setRange(page, 'opacity', 0.22);
    console.log(
      `     open ball with walls: EMPTY; witness boundary edges ${edges ?? 'not in this package'}; ${p.magenta} magenta pixels`,
    );
    if (edges) {
      assert(/The walls at the \d+ boundary edges? and the/.test(wtext), wtext);
      assert(p.magenta > 30, `${p.magenta} magenta pixels for the witness's boundary edges`);
    }
    // The first offered: the package in Node gives the same kernel (volume) for allowOpen.
    await loadFile(page, ball.file);
    await offered(page);
    const r = await click('retry-open');
    const truth = await nodeKernel(ball.mesh, { allowOpen: true });
    assert(r.status === 'POLYHEDRON' && truth.status === 'POLYHEDRON', JSON.stringify(r));
    assertClose(Number(r.stats.volume), truth.volume, 1e-12, 'open ball kernel volume (allowOpen)');
  });

  await test('refusal: open box: walls first (the unit cube), the open surface second, repair tried and refused', async () => {
    const file = path.join(tmp, 'open-box.off');
    const cube = polygonMesh([
      [
        [0, 0, 0],
        [0, 1, 0],
        [1, 1, 0],
        [1, 0, 0],
      ],
      [
        [0, 0, 0],
        [1, 0, 0],
        [1, 0, 1],
        [0, 0, 1],
      ],
      [
        [1, 0, 0],
        [1, 1, 0],
        [1, 1, 1],
        [1, 0, 1],
      ],
      [
        [1, 1, 0],
        [0, 1, 0],
        [0, 1, 1],
        [1, 1, 1],
      ],
      [
        [0, 1, 0],
        [0, 0, 0],
        [0, 0, 1],
        [0, 1, 1],
      ],
    ]);
    writeOFF(file, cube.positions, cube.faces);
    await loadFile(page, file);
    const o = await offered(page);
    assert(
      JSON.stringify(o.map((b) => [b.id, b.outcome])) === '[["retry-walls","POLYHEDRON"],["retry-open","UNBOUNDED"]]',
      JSON.stringify(o),
    );
    const r = await click('retry-walls');
    assertClose(Number(r.stats.volume), 1, 1e-12, 'open box with walls');
  });

  await test('refusal: a cube of 6 separate quads (24 vertices): repair merges equal positions, said without "within 0"', async () => {
    const file = path.join(tmp, 'quad-soup.off');
    const q = CUBE_Q,
      V = CUBE_V;
    const positions = q.flatMap((f) => f.flatMap((v) => V.slice(3 * v, 3 * v + 3)));
    writeOFF(
      file,
      positions,
      q.map((_, i) => [4 * i, 4 * i + 1, 4 * i + 2, 4 * i + 3]),
    );
    const s = await loadFile(page, file);
    assert(s.state === 'error', JSON.stringify(s));
    const o = await offered(page);
    assert(o[0]?.id === 'retry-repair' && o[0].outcome === 'POLYHEDRON', JSON.stringify(o));
    const r = await click('retry-repair');
    assertClose(Number(r.stats.volume), 1, 1e-12, 'welded quad soup');
    const note = await page.textContent('#message');
    assert(
      /16 vertices at the same position as another vertex were merged/.test(note) && !OPTION_NAMES.test(note),
      note,
    );
  });

  await test('refusal: the trials of a 40k-triangle open mesh can be cancelled: the actions are then offered untried', async () => {
    const big = bumpySphere(200, 101); // 40,000 triangles; the 200 around the north pole removed
    const faces = [];
    for (let t = 0; t < big.indices.length; t += 3) {
      const tri = Array.from(big.indices.subarray(t, t + 3));
      if (!tri.includes(0)) faces.push(tri);
    }
    const file = path.join(tmp, 'bumpy-40k-open-trials.off');
    writeOFF(file, Array.from(big.positions), faces);
    await loadFile(page, file);
    const t0 = Date.now();
    await page.waitForFunction(() => document.getElementById('actions').dataset.state !== '', null, { timeout: 30000 });
    const during = await page.evaluate(() => ({
      state: document.getElementById('actions').dataset.state,
      cancel: document.getElementById('cancel').disabled,
      busy: document.getElementById('busy-text').textContent,
    }));
    assert(during.state === 'trying' && !during.cancel && /^Trying first/.test(during.busy), JSON.stringify(during));
    await page.click('#cancel');
    const o = await offered(page);
    const text = await page.textContent('#message');
    console.log(
      `     40k open mesh: cancelled the trials after ${Date.now() - t0} ms; offered ${o.map((b) => b.id).join(', ')}`,
    );
    assert(/Trying these first was cancelled/.test(text), text);
    assert(
      JSON.stringify(o.map((b) => b.id)) === '["retry-repair","retry-walls","retry-open"]' &&
        o.every((b) => !b.outcome),
      JSON.stringify(o),
    );
  });

  await test('ball: hidden while the kernel grows, drawn at the end; outlined (not filled) in the vase, filled in the gear', async () => {
    const ball = () =>
      page.evaluate(() => {
        const o = window.kergenDemo.viewer.overlays;
        return { group: o.insideGroup.visible, filled: o.ball.visible, ring: o.ring.visible };
      });
    await markPending(page);
    await page.click('[data-sample="vase"]');
    await waitFinished(page);
    await page.evaluate(() => {
      const s = document.getElementById('scrubber');
      s.value = String(Math.floor(Number(s.max) / 2));
      s.dispatchEvent(new Event('input', { bubbles: true }));
    });
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const mid = await ball();
    assert(!mid.group, `ball drawn halfway through the replay: ${JSON.stringify(mid)}`);
    await jumpToEnd(page);
    const end = await ball();
    assert(end.group && end.ring && !end.filled, `vase ball at the end: ${JSON.stringify(end)}`);
    const p = await px('flow-vase-ball-outline.png');
    assert(p.blue > 1500 && p.green > 20, `vase: ${p.blue} blue, ${p.green} green pixels`);
    await markPending(page);
    await page.click('[data-sample="gear"]');
    await waitFinished(page);
    await jumpToEnd(page);
    const gear = await ball();
    assert(gear.group && gear.filled, `gear ball: ${JSON.stringify(gear)}`);
  });

  await test('opacity 0 hides the shape and its face edges', async () => {
    await page.evaluate(() => {
      const e = document.getElementById('show-edges');
      if (!e.checked) e.click();
    });
    await setRange(page, 'opacity', 0);
    const hidden = await page.evaluate(() => {
      const v = window.kergenDemo.viewer;
      return { mesh: v.inputMesh?.visible, wire: v.inputWire?.visible };
    });
    const p = await px('flow-opacity-0.png');
    await setRange(page, 'opacity', 0.22);
    const shown = await page.evaluate(() => window.kergenDemo.viewer.inputWire?.visible);
    assert(hidden.mesh === false && hidden.wire === false && shown === true, JSON.stringify({ hidden, shown }));
    assert(p.amber < 50, `${p.amber} amber pixels at opacity 0`);
  });

  await test('?url=ball.off (relative) answered with the site page: this URL returned a web page', async () => {
    // The test server answers unknown paths with 404; a site (vite preview) answers with its page.
    h.served.set('/ball.off', path.join(h.webDist, 'index.html'));
    await markPending(page);
    await page.goto(`${base}?url=ball.off`);
    const s = await waitFinished(page);
    const text = await page.textContent('#message');
    assert(s.state === 'error' && s.message?.code === 'URL_ERROR', JSON.stringify(s));
    assert(/this URL returned a web page, not a mesh/i.test(text) && !/OFF header|header/i.test(text), text);
  });

  await test('what bounds a kernel face: hover names its input face (or box / wall) and highlights it', async () => {
    await page.goto(`${base}?sample=dented-cube`);
    await waitFinished(page);
    await jumpToEnd(page);
    const fromPackage = await page.evaluate(() => !!window.kergenDemo.state.result.faceSources);
    if (!fromPackage) {
      // The package predates faceSources: the test gives the page the map it would (the lowest
      // input face in each kernel face's plane, found here by exact plane match of the corners).
      await page.evaluate(async () => {
        const { state } = window.kergenDemo;
        const r = state.result;
        const m = state.mesh;
        const P = (arr, i) => [arr[3 * i], arr[3 * i + 1], arr[3 * i + 2]];
        const sub = (a, b) => a.map((x, i) => x - b[i]);
        const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
        const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        const sizes = m.faceSizes ?? new Uint32Array(m.indices.length / 3).fill(3);
        const starts = [];
        let o = 0;
        for (const k of sizes) starts.push((o += k) - k);
        const src = new Int32Array(r.faces.length).fill(-9);
        r.faces.forEach((loop, f) => {
          const a = P(r.vertices, loop[0]),
            b = P(r.vertices, loop[1]),
            c = P(r.vertices, loop[2]);
          const n = cross(sub(b, a), sub(c, a));
          const len = Math.hypot(...n);
          for (let i = 0; i < sizes.length && src[f] < 0; i++) {
            const q0 = P(m.positions, m.indices[starts[i]]),
              q1 = P(m.positions, m.indices[starts[i] + 1]),
              q2 = P(m.positions, m.indices[starts[i] + 2]);
            const nq = cross(sub(q1, q0), sub(q2, q0));
            const on = [q0, q1, q2].every((q) => Math.abs(dot(n, sub(q, a))) <= 1e-9 * len);
            if (on && dot(n, nq) > 0) src[f] = i;
          }
        });
        r.faceSources = src;
      });
    }
    // Hover the centroid of the kernel face that faces the camera most (its screen position from
    // the page's camera): the raycast must find that face.
    const target = await page.evaluate(() => {
      const { state, viewer } = window.kergenDemo;
      const r = state.result,
        o = viewer.kernel.offset,
        cam = viewer.camera;
      const rect = viewer.renderer.domElement.getBoundingClientRect();
      const P = (i) => [r.vertices[3 * i] - o.x, r.vertices[3 * i + 1] - o.y, r.vertices[3 * i + 2] - o.z];
      let best = null;
      r.faces.forEach((loop, f) => {
        const pts = Array.from(loop, P);
        const c = [0, 1, 2].map((k) => pts.reduce((a, p) => a + p[k], 0) / pts.length);
        const [a, b, d] = pts;
        const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
          v = [d[0] - a[0], d[1] - a[1], d[2] - a[2]];
        const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
        const e = [cam.position.x - c[0], cam.position.y - c[1], cam.position.z - c[2]];
        const facing = (n[0] * e[0] + n[1] * e[1] + n[2] * e[2]) / Math.hypot(...n) / Math.hypot(...e);
        if (!best || facing > best.facing) best = { f, c, facing };
      });
      const p = cam.position
        .clone()
        .set(...best.c)
        .project(cam);
      return { face: best.f, x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
    });
    await page.mouse.move(target.x - 3, target.y - 3);
    await page.mouse.move(target.x, target.y);
    await page
      .waitForFunction(() => !document.getElementById('face-info').hidden, null, { timeout: 5000 })
      .catch(() => {});
    const info = await page.evaluate(() => {
      const el = document.getElementById('face-info');
      return el.hidden ? null : { text: el.textContent, face: el.dataset.face, source: el.dataset.source };
    });
    const direct = await page.evaluate(({ x, y }) => {
      const { viewer, kernelFaceAt } = window.kergenDemo;
      const g = viewer.kernel.facesGeo;
      return {
        face: kernelFaceAt(x, y),
        sphere: g.boundingSphere?.radius,
        range: g.drawRange.count,
        n: g.getAttribute('position').count,
      };
    }, target);
    assert(
      info,
      `no face info on hover over the kernel: target ${JSON.stringify(target)}, direct pick ${JSON.stringify(direct)}`,
    );
    const check = await page.evaluate(({ face, source }) => {
      const { state, viewer } = window.kergenDemo;
      return {
        expected: state.result.faceSources[Number(face)],
        cyan: viewer.overlays.sourceFill.visible,
        outline: viewer.overlays.faceOutline.visible,
        source: Number(source),
      };
    }, info);
    assert(check.expected === check.source, JSON.stringify({ info, check }));
    assert(
      check.source >= 0 ? new RegExp(`bounded by input face ${check.source}\\b`).test(info.text) && check.cyan : true,
      JSON.stringify({ info, check }),
    );
    assert(check.outline, 'kernel face not outlined');
    assert(Number(info.face) === target.face, `hovered face ${info.face}, expected ${target.face}`);
    await page.screenshot({ path: path.join(artifacts, 'flow-face-source-hover-1280.png') });
    console.log(`     hover: "${info.text}" (faceSources ${fromPackage ? 'from the package' : 'given by the test'})`);
    await page.mouse.move(1, 1);
  });

  await test('phone 390×844: the verdict and its actions above the fold, in each state; screenshots at both sizes', async () => {
    const states = [
      ['done-gear', () => page.goto(`${base}?sample=gear`)],
      ['flat-z-prism', () => page.goto(`${base}?sample=z-prism`)],
      ['empty-u-prism', () => page.goto(`${base}?sample=u-prism`)],
      ['error-tjunction', () => page.setInputFiles('#file-input', files['tjunction-box.off'].file)],
      ['error-open-ball', () => page.setInputFiles('#file-input', files['open-ball.off'].file)],
      // A file, refused, then the offered action clicked (the test waits for it to be offered).
      ...[
        ['repaired-tjunction', 'tjunction-box.off', 'retry-repair'],
        ['open-unbounded', 'open-box.off', 'retry-open'],
        ['empty-with-walls', 'open-ball.off', 'retry-walls'],
      ].map(([name, file, action]) => [
        name,
        async () => {
          await page.setInputFiles('#file-input', path.join(tmp, file));
          await waitFinished(page);
          await offered(page);
          await markPending(page);
          await page.click(`#${action}`);
        },
      ]),
      ['idle', () => page.goto(`${base}?sample=none`)],
    ];
    const rows = [];
    for (const [w, hgt] of [
      [390, 844],
      [1280, 800],
    ]) {
      await page.setViewportSize({ width: w, height: hgt });
      for (const [name, open] of states) {
        await markPending(page);
        await open();
        const s =
          name === 'idle'
            ? await page
                .waitForFunction(() => document.getElementById('status').dataset.state === 'idle')
                .then(() => ({}))
            : await waitFinished(page);
        if (s.state === 'error') await offered(page);
        else if (s.steps > 0) await jumpToEnd(page);
        const f = await fold(page);
        rows.push({ name, w, ...f });
        await page.screenshot({ path: path.join(artifacts, `flow-${name}-${w}.png`) });
        const last = Math.max(f.status, f.actions, f.title);
        assert(
          last <= f.height,
          `${name} at ${w}×${hgt}: the verdict ends at ${last} px, below the fold (${f.height})`,
        );
      }
    }
    await page.setViewportSize({ width: 1280, height: 800 });
    for (const r of rows)
      console.log(
        `     ${r.w}: ${r.name}: status ${Math.round(r.statusTop)}–${Math.round(r.status)} px, title ${Math.round(r.title)}, actions end ${Math.round(r.actions)} (fold ${r.height})`,
      );
  });

  await test('accessibility: axe-core on the new states (alternatives offered, empty with walls, phone layout)', async () => {
    const runs = [];
    const check = async (label) => {
      if (!(await page.evaluate(() => !!window.axe)))
        await page.addScriptTag({ path: require.resolve('axe-core/axe.min.js') });
      const v = await page.evaluate(async () =>
        (await window.axe.run(document, { resultTypes: ['violations'] })).violations.map((x) => ({
          id: x.id,
          impact: x.impact,
          target: x.nodes[0]?.target?.join(' '),
        })),
      );
      runs.push({ label, v });
    };
    await markPending(page);
    await page.setInputFiles('#file-input', files['open-ball.off'].file);
    await waitFinished(page);
    await offered(page);
    await check('alternatives offered (open ball)');
    await click('retry-walls');
    await check('empty with walls');
    await page.setViewportSize({ width: 390, height: 844 });
    await check('phone, empty with walls');
    await page.setViewportSize({ width: 1280, height: 800 });
    for (const r of runs)
      console.log(
        `     axe ${r.label}: ${r.v.length ? r.v.map((x) => `${x.id} (${x.impact})`).join(', ') : 'no violations'}`,
      );
    const bad = runs.flatMap((r) =>
      r.v
        .filter((x) => x.impact === 'serious' || x.impact === 'critical')
        .map((x) => `${r.label}: ${x.id} at ${x.target}`),
    );
    assert(bad.length === 0, bad.join(' | '));
    if (!bad.length && runs.length !== 3) skipTest('not every state was checked');
  });
}
