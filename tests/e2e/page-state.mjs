// The e2e tests' page helpers: the demo page's state as its data attributes say it, loading
// samples and files, the scrubber, and screenshots of the 3D view with their pixels counted.
import fs from 'node:fs';
import path from 'node:path';
import { artifacts } from './harness.mjs';

export const STATS = [
  'stat-input-faces',
  'stat-planes',
  'stat-status',
  'stat-vertices',
  'stat-edges',
  'stat-faces',
  'stat-volume',
  'stat-area',
  'stat-ratio',
  'stat-kernel-point',
  'stat-time',
  'stat-wall',
];

export async function readState(page) {
  return page.evaluate((ids) => {
    const $ = (id) => document.getElementById(id);
    const stats = {};
    for (const id of ids) stats[id.replace('stat-', '')] = $(id).dataset.value;
    const m = $('message');
    return {
      state: $('status').dataset.state,
      status: $('status').dataset.value,
      statusText: $('status').textContent,
      message: m.hidden ? null : { kind: m.dataset.kind, code: m.dataset.code, text: m.textContent },
      stats,
      step: Number($('scrubber').value),
      steps: Number($('scrubber').max),
      shown: {
        vertices: Number($('anim-vertices').dataset.value),
        edges: Number($('anim-edges').dataset.value),
        faces: Number($('anim-faces').dataset.value),
      },
    };
  }, STATS);
}

export async function markPending(page) {
  await page.evaluate(() => {
    document.getElementById('status').dataset.state = 'test-pending';
  });
}

export async function waitFinished(page, timeout = 60000) {
  await page.waitForFunction(
    () => ['done', 'error', 'cancelled'].includes(document.getElementById('status').dataset.state),
    null,
    { timeout, polling: 20 },
  );
  // The timeline (scrubber, step label, counts) is redrawn by the page's animation frame, which
  // can come after the status: wait for one (the page's frame callback runs before this one).
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => resolve())));
  return readState(page);
}

export async function loadSample(page, id) {
  await markPending(page);
  await page.click(`[data-sample="${id}"]`);
  return waitFinished(page);
}

export async function loadFile(page, file) {
  await markPending(page);
  await page.setInputFiles('#file-input', file);
  return waitFinished(page, 120000);
}

export async function dropFile(page, file) {
  await markPending(page);
  const b64 = fs.readFileSync(file).toString('base64');
  const t = Date.now();
  await page.evaluate(
    ({ b64, name }) => {
      const bin = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
      const dt = new DataTransfer();
      dt.items.add(new File([bin], name));
      document
        .getElementById('viewport')
        .dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
    },
    { b64, name: path.basename(file) },
  );
  const s = await waitFinished(page, 120000);
  return { ...s, testMs: Date.now() - t };
}

export async function scrubTo(page, k) {
  await page.evaluate((k) => {
    const s = document.getElementById('scrubber');
    s.value = String(k);
    s.dispatchEvent(new Event('input', { bubbles: true }));
  }, k);
  await page.waitForFunction((k) => document.getElementById('step-label').textContent.startsWith(`${k} /`), k, {
    timeout: 5000,
  });
  return readState(page);
}

export async function jumpToEnd(page) {
  await page.click('#jump-end');
  await page.waitForFunction(
    () => {
      const s = document.getElementById('scrubber');
      return s.value === s.max;
    },
    null,
    { timeout: 5000 },
  );
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

// Screenshot of the 3D view (or the whole page) saved to tests/artifacts; returns pixel counts
// measured by decoding the PNG in the page (createImageBitmap + canvas getImageData).
export async function shoot(page, name, { fullPage = false } = {}) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const png = fullPage
    ? await page.screenshot({ path: path.join(artifacts, name) })
    : await page.locator('#viewport').screenshot({ path: path.join(artifacts, name) });
  // Count pixels only inside the 3D view, above the playback bar (its sliders are blue too).
  const box = await page.locator('#viewport').boundingBox();
  const bar = await page.locator('#playbar').boundingBox();
  const height = bar.y - box.y;
  const clip = fullPage ? { ...box, height } : { x: 0, y: 0, width: box.width, height };
  return page.evaluate(
    async ({ b64, clip }) => {
      const bin = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
      const bmp = await createImageBitmap(new Blob([bin], { type: 'image/png' }));
      const canvas = new OffscreenCanvas(bmp.width, bmp.height);
      const ctx = canvas.getContext('2d');
      ctx.drawImage(bmp, 0, 0);
      const x0 = Math.round(clip.x),
        y0 = Math.round(clip.y);
      const { data, width, height } = ctx.getImageData(x0, y0, Math.round(clip.width), Math.round(clip.height));
      let blue = 0,
        amber = 0,
        tinted = 0,
        lum = 0;
      for (let i = 0; i < data.length; i += 4) {
        const r = data[i],
          g = data[i + 1],
          b = data[i + 2];
        if (b >= 90 && b >= 1.8 * r && b >= 1.25 * g) blue++; // kernel blue #1e6fff, lit or shaded
        if (r >= g + 25 && g >= b + 25) amber++; // the input's amber
        if (r >= b + 20 && r >= g && g >= b) tinted++; // amber at any opacity and shade, pale too
        lum += 0.2126 * r + 0.7152 * g + 0.0722 * b;
      }
      const n = width * height;
      return { blue, amber, tinted, total: n, blueFraction: blue / n, meanLuminance: lum / n };
    },
    { b64: png.toString('base64'), clip },
  );
}
