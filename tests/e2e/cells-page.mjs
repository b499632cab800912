// Browser tests of the volume-mesh page (web/cells.html), called by run.mjs: the generated sample
// read by the package's reader in the worker and every cell's kernel checked against its analytic
// value (web/cells-sample.js), the legend and the marked non-star cells, a clicked cell shown
// with its kernel or its witness faces, colouring by ρ/h, the filter, the .node + .ele pair,
// errors, the progress bar and cancel, and screenshots at 1280×800 and 390×844 (tests/artifacts/).
import fs from 'node:fs';
import path from 'node:path';
import { agglomeratedGrid, sampleVolumeMesh, volumeMeshToVtu } from '../../web/cells-sample.js';

const sample = sampleVolumeMesh();

async function waitDone(page, timeout = 120000) {
  await page.waitForFunction(
    () => ['done', 'error', 'cancelled'].includes(document.getElementById('cells-status').dataset.state),
    null,
    { timeout },
  );
  return page.evaluate(() => ({
    state: document.getElementById('cells-status').dataset.state,
    message: document.getElementById('cells-message').textContent,
    code: document.getElementById('cells-message').dataset.code,
  }));
}

// The next load's end is a state change from here (the previous load's end does not count).
const markPending = (page) =>
  page.evaluate(() => (document.getElementById('cells-status').dataset.state = 'test-pending'));

async function openPage(context, base, viewport, query = '') {
  const page = await context.newPage();
  await page.setViewportSize(viewport);
  const errors = [];
  page.on('pageerror', (e) => errors.push(`pageerror: ${e.message}`));
  page.on('console', (m) => m.type() === 'error' && errors.push(`console.error: ${m.text()}`));
  await page.goto(`${base}cells.html${query}`, { waitUntil: 'load' });
  return { page, errors };
}

// Pixels of the 3D view by colour: the non-star magenta, the kernel blue, and anything that is
// not the scene's background.
async function shootView(page, file, artifacts) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  await page.screenshot({ path: path.join(artifacts, file) });
  const png = await page.locator('#viewport').screenshot();
  return page.evaluate(async (b64) => {
    const bin = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
    const bmp = await createImageBitmap(new Blob([bin], { type: 'image/png' }));
    const canvas = new OffscreenCanvas(bmp.width, bmp.height);
    const ctx = canvas.getContext('2d');
    ctx.drawImage(bmp, 0, 0);
    const { data } = ctx.getImageData(0, 0, bmp.width, bmp.height);
    const bg = [data[0], data[1], data[2]];
    let magenta = 0,
      blue = 0,
      drawn = 0;
    for (let i = 0; i < data.length; i += 4) {
      const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
      if (r >= 150 && g <= 110 && b >= 100 && r >= g + 80) magenta++;
      if (b >= 90 && b >= 1.8 * r && b >= 1.25 * g) blue++;
      if (Math.abs(r - bg[0]) + Math.abs(g - bg[1]) + Math.abs(b - bg[2]) > 30) drawn++;
    }
    return { magenta, blue, drawn, total: bmp.width * bmp.height };
  }, png.toString('base64'));
}

// The first cell of `kind` in the sample that the view draws, and where it is on the screen.
async function visibleCell(page, kind) {
  const candidates = sample.kinds.map((k, c) => (k === kind ? c : -1)).filter((c) => c >= 0);
  return page.evaluate((candidates) => {
    const { view } = window.kergenCells;
    for (const c of candidates) {
      const at = view.screenPointOf(c);
      if (at && view.pick(at.x, at.y) === c) return { cell: c, ...at };
    }
    return null;
  }, candidates);
}

async function clickCell(page, at) {
  await page.mouse.click(at.x, at.y);
  await page.waitForFunction(
    (c) => {
      const p = document.getElementById('cells-selected');
      return p.dataset.cell === String(c) && p.dataset.shown;
    },
    at.cell,
    { timeout: 30000 },
  );
  return page.evaluate(() => {
    const p = document.getElementById('cells-selected');
    const v = (id) => document.getElementById(id).dataset.value;
    return {
      shown: p.dataset.shown,
      kernelVolume: Number(p.dataset.kernelVolume),
      witnessFaces: Number(p.dataset.witnessFaces),
      status: v('sel-status'),
      rho: Number(v('sel-rho')),
      h: Number(v('sel-h')),
      witnessText: document.getElementById('sel-witness').textContent,
    };
  });
}

export async function cellsPageTests(context, base, tmp, { test, assert, assertClose, artifacts }) {
  const { page, errors } = await openPage(context, base, { width: 1280, height: 800 });

  await test('cells page: the generated sample, every cell against its analytic kernel', async () => {
    const end = await waitDone(page);
    assert(end.state === 'done', `the sample ended in ${end.state}: ${end.message}`);
    const r = await page.evaluate(() => {
      const res = window.kergenCells.state.result;
      return {
        status: [...res.status].map((s) => res.statusNames[s]),
        kernelVolume: [...res.kernelVolume],
        cellVolume: [...res.cellVolume],
        inscribedRadius: [...res.inscribedRadius],
        summary: res.summary,
      };
    });
    assert(
      r.status.length === sample.cells.length,
      `${r.status.length} cells, the generator made ${sample.cells.length}`,
    );
    sample.expected.forEach((e, c) => {
      assert(r.status[c] === (e.starShaped ? 'POLYHEDRON' : 'EMPTY'), `cell ${c} (${sample.kinds[c]}): ${r.status[c]}`);
      assertClose(r.cellVolume[c], e.cellVolume, 1e-12, `cell ${c} volume`);
      if (e.starShaped) {
        assertClose(r.kernelVolume[c], e.kernelVolume, 1e-12, `cell ${c} kernel volume`);
        assertClose(r.inscribedRadius[c], e.inscribedRadius, 1e-9, `cell ${c} inscribed radius`);
      } else assert(r.kernelVolume[c] === 0, `cell ${c} kernel volume ${r.kernelVolume[c]}`);
    });
    const nonStar = sample.kinds.filter((k) => k === 'U').length;
    const text = (id) => page.evaluate((id) => document.getElementById(id).textContent, id);
    assert(Number(await text('legend-nonstar')) === nonStar, `legend: ${await text('legend-nonstar')} non-star cells`);
    assert((await text('sum-nonstar')) === String(nonStar), `summary: ${await text('sum-nonstar')}`);
    assert(
      (await text('cells-progress-text')) === `${sample.cells.length} / ${sample.cells.length} cells`,
      'progress at its end',
    );
  });

  await test('cells page: the legend, and the non-star cells marked in the view (1280×800 screenshot)', async () => {
    const legend = await page.evaluate(() => {
      const l = document.getElementById('cells-legend');
      return {
        hidden: l.hidden,
        by: l.dataset.by,
        bar: getComputedStyle(document.getElementById('legend-bar')).backgroundImage,
        min: document.getElementById('legend-min').textContent,
        max: document.getElementById('legend-max').textContent,
      };
    });
    assert(!legend.hidden && legend.by === 'ratio', `legend ${JSON.stringify(legend)}`);
    assert(
      legend.bar.startsWith('linear-gradient') && legend.min === '0' && legend.max === '1',
      `legend ${JSON.stringify(legend)}`,
    );
    const px = await shootView(page, 'cells-sample-1280.png', artifacts);
    console.log(`     cells sample 1280×800: ${px.drawn} drawn pixels, ${px.magenta} non-star magenta`);
    assert(px.drawn > 0.15 * px.total, `the scene is hardly drawn: ${px.drawn} of ${px.total} pixels`);
    assert(px.magenta > 500, `non-star cells hardly visible: ${px.magenta} magenta pixels`);
  });

  await test('cells page: a click on a non-star cell shows it with its witness faces', async () => {
    const at = await visibleCell(page, 'U');
    assert(at, 'a U cell is drawn');
    const sel = await clickCell(page, at);
    assert(sel.shown === 'kernel' && sel.status === 'EMPTY', `selected ${JSON.stringify(sel)}`);
    assert(sel.witnessFaces >= 2 && sel.witnessFaces <= 4, `${sel.witnessFaces} witness faces`);
    assert(/^faces \d+(, \d+)+$/.test(sel.witnessText), `witness: ${sel.witnessText}`);
    assertClose(sel.h, sample.expected[at.cell].diameter, 1e-9, 'diameter');
    const px = await shootView(page, 'cells-nonstar-cell.png', artifacts);
    assert(px.magenta > 300, `witness faces hardly visible: ${px.magenta} magenta pixels`);
  });

  await test('cells page: a click on an L cell shows its kernel, the elbow box, and its inscribed ball', async () => {
    const at = await visibleCell(page, 'L');
    assert(at, 'an L cell is drawn');
    const sel = await clickCell(page, at);
    const e = sample.expected[at.cell];
    assert(sel.shown === 'kernel' && sel.status === 'POLYHEDRON', `selected ${JSON.stringify(sel)}`);
    assertClose(sel.kernelVolume, e.kernelVolume, 1e-12, 'kernel volume');
    assertClose(sel.rho, e.inscribedRadius, 1e-9, 'inscribed radius');
    const px = await shootView(page, 'cells-l-cell.png', artifacts);
    console.log(`     L cell ${at.cell}: ${px.blue} kernel-blue pixels`);
    assert(px.blue > 1000, `the kernel is hardly visible: ${px.blue} blue pixels`);
    await page.keyboard.press('Escape');
    assert(await page.evaluate(() => document.getElementById('cells-selected').hidden), 'Escape shows all cells again');
  });

  await test('cells page: colour by ρ/h, the cut and the non-star filter', async () => {
    await page.selectOption('#cells-colour-by', 'rho');
    const legend = await page.evaluate(() => ({
      by: document.getElementById('cells-legend').dataset.by,
      max: Number(document.getElementById('legend-max').textContent),
      summaryMax: window.kergenCells.state.result.summary.maxRhoOverH,
    }));
    assert(
      legend.by === 'rho' && Math.abs(legend.max - legend.summaryMax) < 1e-3 * legend.summaryMax,
      JSON.stringify(legend),
    );
    const shown = await page.evaluate(() => {
      const el = document.getElementById('cells-only-nonstar');
      el.checked = true;
      el.dispatchEvent(new Event('input', { bubbles: true }));
      const { view, state } = window.kergenCells;
      const names = new Set([...new Set(view.triCell)].map((c) => state.result.statusNames[state.result.status[c]]));
      return { names: [...names], cells: new Set(view.triCell).size };
    });
    assert(
      shown.names.length === 1 && shown.names[0] === 'EMPTY',
      `only non-star cells drawn: ${JSON.stringify(shown)}`,
    );
    assert(shown.cells === sample.kinds.filter((k) => k === 'U').length, `${shown.cells} cells drawn`);
    const cut = await page.evaluate(() => {
      document.getElementById('cells-only-nonstar').checked = false;
      const el = document.getElementById('cells-cut');
      el.value = '0.4';
      el.dispatchEvent(new Event('input', { bubbles: true }));
      return new Set(window.kergenCells.view.triCell).size;
    });
    assert(cut > 0 && cut < sample.cells.length, `the cut shows ${cut} cells`);
    await page.evaluate(() => {
      const el = document.getElementById('cells-cut');
      el.value = '1';
      el.dispatchEvent(new Event('input', { bubbles: true }));
    });
    await page.selectOption('#cells-colour-by', 'ratio');
  });

  await test('cells page: a .node + .ele pair chosen together; one alone, and a truncated .vtu, are refused', async () => {
    const grid = agglomeratedGrid(6, 4, 2);
    const node = [`${grid.positions.length / 3} 3 0 0`];
    for (let v = 0; v < grid.positions.length / 3; v++)
      node.push(`${v} ${grid.positions[3 * v]} ${grid.positions[3 * v + 1]} ${grid.positions[3 * v + 2]}`);
    const ele = [`${grid.cells.length} 0`];
    let id = 0;
    grid.cells.forEach((faces, c) => {
      ele.push(`${c} ${faces.length}`);
      for (const f of faces) ele.push(`${id++} ${f.length} ${f.join(' ')}`);
    });
    const nodeFile = path.join(tmp, 'grid.node');
    const eleFile = path.join(tmp, 'grid.ele');
    fs.writeFileSync(nodeFile, node.join('\n') + '\n');
    fs.writeFileSync(eleFile, ele.join('\n') + '\n');
    await markPending(page);
    await page.setInputFiles('#cells-file', [nodeFile, eleFile]);
    let end = await waitDone(page);
    assert(end.state === 'done', `the pair ended in ${end.state}: ${end.message}`);
    const summary = await page.evaluate(() => window.kergenCells.state.result.summary);
    assert(summary.cells === grid.cells.length, `${summary.cells} cells`);
    assert(summary.byType.EMPTY === grid.kinds.filter((k) => k === 'U').length, `${summary.byType.EMPTY} non-star`);
    await page.setInputFiles('#cells-file', [nodeFile]);
    await page.waitForFunction(() => document.getElementById('cells-message').dataset.code === 'INVALID_ARGUMENT');
    const cutFile = path.join(tmp, 'cut.vtu');
    const text = volumeMeshToVtu(grid);
    fs.writeFileSync(cutFile, text.slice(0, Math.floor(text.length * 0.6)));
    await markPending(page);
    await page.setInputFiles('#cells-file', [cutFile]);
    end = await waitDone(page);
    assert(end.state === 'error' && end.code === 'PARSE_ERROR', `truncated: ${JSON.stringify(end)}`);
    assert(end.message.includes('cut.vtu'), `the message names the file: ${end.message}`);
  });

  await test('cells page: the progress bar advances range by range, and Cancel stops the run', async () => {
    const file = path.join(tmp, 'grid-3k.vtu');
    fs.writeFileSync(file, volumeMeshToVtu(agglomeratedGrid(24, 24, 9)));
    await page.evaluate(() => {
      document.getElementById('cells-deepest').value = 'never';
      window.__progress = new Set();
      new MutationObserver(() => window.__progress.add(document.getElementById('cells-progress').value)).observe(
        document.getElementById('cells-progress-text'),
        { childList: true, characterData: true, subtree: true },
      );
    });
    await markPending(page);
    await page.setInputFiles('#cells-file', [file]);
    const end = await waitDone(page, 300000);
    assert(end.state === 'done', `ended in ${end.state}: ${end.message}`);
    const values = await page.evaluate(() => [...window.__progress].filter((v) => v > 0));
    const workers = await page.evaluate(() => document.getElementById('sum-workers').dataset.value);
    console.log(`     ${values.length} progress values over ${workers} worker(s)`);
    assert(values.length >= 3, `progress values seen: ${values.join(', ')}`);
    // Cancel: with inscribed balls the same mesh takes seconds.
    await page.evaluate(() => (document.getElementById('cells-deepest').value = 'always'));
    await markPending(page);
    await page.setInputFiles('#cells-file', [file]);
    await page.waitForFunction(() => document.getElementById('cells-progress').value > 0, null, { timeout: 120000 });
    await page.click('#cells-cancel');
    const stopped = await waitDone(page);
    assert(stopped.state === 'cancelled', `after Cancel: ${stopped.state}`);
    await markPending(page);
    await page.click('#cells-sample');
    const again = await waitDone(page);
    assert(again.state === 'done', `the sample after a cancel: ${again.state} ${again.message}`);
  });

  await test('cells page: no errors in the page', async () => {
    assert(errors.length === 0, errors.slice(0, 5).join(' | '));
  });
  await page.close();

  await test('cells page on a phone (390×844): the sample drawn, the legend and a selected cell (screenshot)', async () => {
    const phone = await openPage(context, base, { width: 390, height: 844 });
    try {
      const end = await waitDone(phone.page);
      assert(end.state === 'done', `ended in ${end.state}`);
      const at = await visibleCell(phone.page, 'U');
      assert(at, 'a U cell is drawn');
      await clickCell(phone.page, at);
      const px = await shootView(phone.page, 'cells-sample-390.png', artifacts);
      console.log(`     cells sample 390×844: ${px.drawn} drawn pixels, ${px.magenta} magenta`);
      assert(px.drawn > 0.1 * px.total && px.magenta > 100, `the phone view: ${JSON.stringify(px)}`);
      assert(!(await phone.page.evaluate(() => document.getElementById('cells-legend').hidden)), 'legend shown');
      assert(phone.errors.length === 0, phone.errors.slice(0, 5).join(' | '));
    } finally {
      await phone.page.close();
    }
  });
}
