// What the demo suites read off the page: pixel classes of the 3D view, the visible controls, and
// setters for ranges and checkboxes (demo-states.mjs, demo-features.mjs, demo-refusals.mjs).
import fs from 'node:fs';
import path from 'node:path';

// Pixel classes of a screenshot of the 3D view above the play bar (the part a user sees), and
// the non-background pixels' extent and how many touch the band's border.
export async function viewPixels(page, artifacts, name) {
  // (A focused canvas has a focus ring, which would count as shape pixels.)
  await page.evaluate(
    () =>
      new Promise((r) => {
        document.activeElement?.blur();
        requestAnimationFrame(() => requestAnimationFrame(r));
      }),
  );
  const png = await page.locator('#viewport').screenshot({ path: path.join(artifacts, name) });
  const box = await page.locator('#viewport').boundingBox();
  const bar = await page.locator('#playbar').boundingBox();
  return page.evaluate(
    async ({ b64, width, height }) => {
      const bin = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
      const bmp = await createImageBitmap(new Blob([bin], { type: 'image/png' }));
      const ctx = new OffscreenCanvas(bmp.width, bmp.height).getContext('2d');
      ctx.drawImage(bmp, 0, 0);
      const W = Math.min(bmp.width, Math.round(width)),
        H = Math.min(bmp.height, Math.round(height));
      const { data } = ctx.getImageData(0, 0, W, H);
      const bg = [data[0], data[1], data[2]]; // the top-left corner: the scene's background
      const out = {
        blue: 0,
        amber: 0,
        green: 0,
        red: 0,
        magenta: 0,
        grey: 0,
        border: 0,
        lo: [W, H],
        hi: [-1, -1],
        width: W,
        height: H,
      };
      for (let y = 0; y < H; y++) {
        for (let x = 0; x < W; x++) {
          const i = 4 * (y * W + x),
            r = data[i],
            g = data[i + 1],
            b = data[i + 2];
          if (b >= 90 && b >= 1.8 * r && b >= 1.25 * g) out.blue++;
          if (r >= g + 25 && g >= b + 25) out.amber++;
          if (g >= r + 40 && g >= b + 10) out.green++;
          if (r >= 150 && g < 90 && b < 90) out.red++;
          if (r >= g + 60 && b >= g + 40) out.magenta++;
          if (Math.abs(r - g) < 12 && Math.abs(g - b) < 20 && r > 140 && r < 200) out.grey++;
          if (Math.abs(r - bg[0]) + Math.abs(g - bg[1]) + Math.abs(b - bg[2]) > 30) {
            if (x < 2 || y < 2 || x >= W - 2 || y >= H - 2) out.border++;
            out.lo = [Math.min(out.lo[0], x), Math.min(out.lo[1], y)];
            out.hi = [Math.max(out.hi[0], x), Math.max(out.hi[1], y)];
          }
        }
      }
      return out;
    },
    { b64: png.toString('base64'), width: box.width, height: bar.y - box.y },
  );
}

export const setRange = (page, id, v) =>
  page.evaluate(
    ({ id, v }) => {
      const el = document.getElementById(id);
      el.value = String(v);
      el.dispatchEvent(new Event('input', { bubbles: true }));
    },
    { id, v },
  );

export const setChecked = (page, id, on) =>
  page.evaluate(
    ({ id, on }) => {
      const el = document.getElementById(id);
      if (el.checked !== on) el.click();
    },
    { id, on },
  );

// What a user sees of the controls: visible rows, play button, message paragraphs.
export const controls = (page) =>
  page.evaluate(() => {
    const $ = (id) => document.getElementById(id);
    return {
      rows: [...document.querySelectorAll('#stats tr')].filter((r) => !r.hidden).map((r) => r.id.replace('row-', '')),
      play: { text: $('play').textContent, disabled: $('play').disabled },
      showResult: $('jump-end').disabled,
      cancel: $('cancel').disabled,
      stepLabel: $('step-label').textContent,
      outcome: $('status').dataset.outcome,
      paragraphs: [...$('message').querySelectorAll('p')].map((p) => p.textContent),
      actions: { open: !$('retry-open').hidden, repair: !$('retry-repair').hidden },
      canvasLabel: document.querySelector('#viewport canvas').getAttribute('aria-label'),
      canvasRole: document.querySelector('#viewport canvas').getAttribute('role'),
    };
  });

// The unit cube without its top face (an open mesh, 4 open edges) written as OFF to `file`.
export function writeOpenBox(file) {
  fs.writeFileSync(
    file,
    [
      'OFF',
      '8 5 0',
      '0 0 0',
      '1 0 0',
      '1 1 0',
      '0 1 0',
      '0 0 1',
      '1 0 1',
      '1 1 1',
      '0 1 1',
      '4 0 3 2 1',
      '4 0 1 5 4',
      '4 1 2 6 5',
      '4 2 3 7 6',
      '4 3 0 4 7',
    ].join('\n') + '\n',
  );
  return file;
}
