// Browser tests of a first visit: on a phone (390 × 844) the verdict and the first action under it
// are in view after every kind of load, wherever the page was scrolled to start it (a file
// through Choose…, a drop, a sample, ?url=, an offered action); and an open surface whose faces
// point inward is said to, with its faces turned over offered first (its kernel is the cube).
// Screenshots: tests/artifacts/visit-*.png. Called by run.mjs with its helpers (`h`).
import fs from 'node:fs';
import path from 'node:path';

const PHONE = { width: 390, height: 844 };

// Where the verdict and the first offered action are (CSS pixels from the top of the viewport).
const verdictBox = (page) =>
  page.evaluate(() => {
    const status = document.getElementById('status').getBoundingClientRect();
    const actions = document.getElementById('actions');
    const first = actions.hidden ? null : [...actions.children].find((b) => !b.hidden);
    const box = first?.getBoundingClientRect();
    return {
      statusTop: status.top,
      statusBottom: status.bottom,
      action: first ? { id: first.id, top: box.top, bottom: box.bottom, text: first.textContent } : null,
      height: window.innerHeight,
      scrollY: window.scrollY + document.getElementById('panel').scrollTop,
      panelScroll: document.getElementById('panel').scrollTop,
    };
  });

// The actions' trials finished (or none offered).
const actionsSettled = (page) =>
  page.waitForFunction(
    () => {
      const a = document.getElementById('actions');
      return a.hidden || ['ready', 'none', ''].includes(a.dataset.state);
    },
    null,
    { timeout: 60000 },
  );

// Waits (up to 60 s; the assertions after it say what is missing) for a visible action button:
// the actions' state is unset for a moment before the trials begin, so actionsSettled can pass
// before any button is shown.
const visibleAction = (page) =>
  page
    .waitForFunction(() => [...document.querySelectorAll('#actions button')].some((x) => !x.hidden), null, {
      timeout: 60000,
    })
    .catch(() => {});

// The panel (and the page, where it scrolls) scrolled to its end, as a phone user does to reach
// the samples or Choose… (under the 3D view, the panel scrolls by itself).
const scrollToEnd = (page) =>
  page.evaluate(() => {
    const panel = document.getElementById('panel');
    panel.scrollTop = panel.scrollHeight;
    window.scrollTo(0, document.documentElement.scrollHeight);
  });

export async function firstVisitTests(page, context, base, h) {
  const { test, assert, assertClose, waitFinished, markPending, artifacts, sharedMeshes, served } = h;
  const fixture = (name) => path.join(sharedMeshes, 'fixtures', name);

  await test('phone 390×844: the verdict and the first action are in view after each kind of load, from wherever the page was scrolled', async () => {
    if (!fs.existsSync(fixture('cube-ouvert.off'))) throw new Error(`missing ${fixture('cube-ouvert.off')}`);
    served.set('/__files/cube-ouvert.off', fixture('cube-ouvert.off'));
    await page.setViewportSize(PHONE);
    const rows = [];
    let from = 0; // the page's scroll when the load began
    const started = async () => {
      from = await page.evaluate(() => window.scrollY + document.getElementById('panel').scrollTop);
    };
    const check = async (name, { action = true } = {}) => {
      await waitFinished(page);
      await actionsSettled(page);
      if (action) await visibleAction(page);
      const b = await verdictBox(page);
      rows.push({ name, from, ...b });
      await page.screenshot({ path: path.join(artifacts, `visit-${name}-390.png`) });
      assert(
        b.statusTop >= 0 && b.statusBottom <= b.height,
        `${name}: the verdict is at ${Math.round(b.statusTop)}–${Math.round(b.statusBottom)} px, outside 0–${b.height}`,
      );
      if (action) {
        assert(b.action, `${name}: an action is offered`);
        assert(
          b.action.top >= 0 && b.action.bottom <= b.height,
          `${name}: the first action (${b.action.id}) is at ${Math.round(b.action.top)}–${Math.round(b.action.bottom)} px, outside 0–${b.height}`,
        );
      }
    };
    try {
      await page.goto(`${base}?sample=none`);
      // 1. A sample, reached by scrolling: the U prism (empty kernel, no action).
      await scrollToEnd(page);
      await page.locator('[data-sample="u-prism"]').scrollIntoViewIfNeeded();
      await markPending(page);
      await started();
      await page.click('[data-sample="u-prism"]');
      await check('sample-u-prism', { action: false });
      // 2. A file through Choose…, reached by scrolling: an open cube, refused, actions offered.
      await scrollToEnd(page);
      await page.locator('#open-file').scrollIntoViewIfNeeded();
      await markPending(page);
      await started();
      const [chooser] = await Promise.all([page.waitForEvent('filechooser'), page.click('#open-file')]);
      await chooser.setFiles(fixture('cube-ouvert.off'));
      await check('choose-file');
      // 3. A drop with the page scrolled to its end.
      await scrollToEnd(page);
      await markPending(page);
      await started();
      const bytes = fs.readFileSync(fixture('cube-ouvert.off')).toString('base64');
      await page.evaluate((b64) => {
        const bin = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
        const dt = new DataTransfer();
        dt.items.add(new File([bin], 'cube-ouvert.off'));
        document
          .getElementById('viewport')
          .dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
      }, bytes);
      await check('drop');
      // 4. The first action, clicked with the page scrolled so that it sits at the top edge (the
      // verdict above it out of view).
      await page.evaluate(() => {
        const first = [...document.getElementById('actions').children].find((b) => !b.hidden);
        const panel = document.getElementById('panel');
        panel.scrollTop += first.getBoundingClientRect().top - panel.getBoundingClientRect().top - 2;
      });
      const before = await verdictBox(page);
      await markPending(page);
      await started();
      await page.click(`#${before.action.id}`);
      await check('retried-action', { action: false });
      // 5. ?url= (the page loads at its top).
      await markPending(page);
      await page.goto(`${base}?url=${encodeURIComponent(`${base}__files/cube-ouvert.off`)}`);
      await check('url');
    } finally {
      await page.setViewportSize({ width: 1280, height: 800 });
      for (const r of rows)
        console.log(
          `     390: ${r.name}: verdict ${Math.round(r.statusTop)}–${Math.round(r.statusBottom)} px, first action ${r.action ? `${r.action.id} ${Math.round(r.action.top)}–${Math.round(r.action.bottom)}` : 'none'} (scrolled ${Math.round(r.from)} px when the load began, ${Math.round(r.scrollY)} after; height ${r.height})`,
        );
    }
  });

  await test('an open surface whose faces point inward: said so, turning them over offered first, its kernel the cube', async () => {
    const file = fixture('open_cube.off');
    if (!fs.existsSync(file)) throw new Error(`missing ${file}`);
    for (const size of [PHONE, { width: 1280, height: 800 }]) {
      await page.setViewportSize(size);
      await page.goto(`${base}?sample=none`);
      await markPending(page);
      await page.setInputFiles('#file-input', file);
      const s = await waitFinished(page);
      await actionsSettled(page);
      await visibleAction(page);
      assert(s.state === 'error' && s.message?.code === 'OPEN_MESH', `refused as open: ${JSON.stringify(s.message)}`);
      const b = await verdictBox(page);
      const offered = await page.evaluate(() =>
        [...document.querySelectorAll('#actions button')]
          .filter((x) => !x.hidden)
          .map((x) => ({ id: x.id, alt: x.dataset.alt, outcome: x.dataset.outcome, text: x.textContent })),
      );
      const text = (await page.textContent('#message')) ?? '';
      await page.screenshot({ path: path.join(artifacts, `visit-inward-offered-${size.width}.png`) });
      console.log(`     ${size.width}: offered ${offered.map((o) => `${o.alt} (${o.outcome})`).join(', ')}`);
      assert(/faces point inward/.test(text), `the message says the faces point inward: ${text}`);
      assert(/never turned over by itself/.test(text), `and that an open surface is not turned over silently: ${text}`);
      assert(
        /kernel is empty: no point is behind every face, walls or not/.test(text),
        `walls are not blamed for the emptiness of the faces alone: ${text}`,
      );
      assert(!/flipFaces|Options::/.test(text), `no option names in the page's words: ${text}`);
      assert(
        offered[0]?.alt === 'flipWalls' &&
          offered[0].outcome === 'POLYHEDRON' &&
          /Turn the faces outward/.test(offered[0].text),
        `turning the faces over is offered first: ${JSON.stringify(offered)}`,
      );
      assert(
        b.action?.id === 'retry-flip' && b.action.top >= 0 && b.action.bottom <= b.height,
        `the first action in view: ${JSON.stringify(b)}`,
      );
      await markPending(page);
      await page.click('#retry-flip');
      const r = await waitFinished(page);
      await page.screenshot({ path: path.join(artifacts, `visit-inward-flipped-${size.width}.png`) });
      assert(r.status === 'POLYHEDRON', `flipped: ${JSON.stringify(r)}`);
      // The cube of side 100 the five faces and the walls at the missing side's edges enclose.
      assertClose(Number(r.stats.volume), 1e6, 1e-12, 'the flipped open cube kernel volume');
      assert(!(await page.isVisible('#row-ratio')), 'no kernel / shape volume row for an open surface');
    }
    await page.setViewportSize({ width: 1280, height: 800 });
  });
}
