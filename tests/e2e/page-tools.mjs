// Shared by the browser tests (run.mjs) and the browser benchmark (bench/browser_bench.mjs):
// serving web/dist (plus test files) on 127.0.0.1, launching Debian's Chromium, writing binary
// STL, and dropping a file on the demo page while its main-thread long tasks are recorded.
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';

const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript',
  '.mjs': 'text/javascript',
  '.css': 'text/css',
  '.wasm': 'application/wasm',
  '.json': 'application/json',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
};

/**
 * Serves `root` on a free port of 127.0.0.1. `files` maps URL paths ('/__files/x.stl') to local
 * files served from disk as they are (big test meshes never go through the page's code). With
 * `cors`, every answer allows any origin to read it (Access-Control-Allow-Origin: *).
 */
export function serve(root, files = new Map(), { cors = false } = {}) {
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://127.0.0.1');
    const pathname = decodeURIComponent(url.pathname);
    let file = files.get(pathname) ?? path.normalize(path.join(root, pathname));
    if (!files.has(pathname) && !file.startsWith(root)) {
      res.writeHead(403).end();
      return;
    }
    if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
    if (!fs.existsSync(file)) {
      res.writeHead(404).end('not found');
      return;
    }
    res.writeHead(200, {
      'Content-Type': MIME[path.extname(file)] ?? 'application/octet-stream',
      'Cache-Control': 'no-store',
      ...(cors ? { 'Access-Control-Allow-Origin': '*' } : {}),
    });
    fs.createReadStream(file).pipe(res);
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

/** Chromium (SwiftShader WebGL) with a fresh profile; returns { context, page, close }. */
export async function launch({ headful = false, executablePath = '/usr/bin/chromium' } = {}) {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath,
    headless: !headful,
    args: [
      '--no-sandbox',
      '--disable-gpu',
      '--disable-quic',
      '--no-first-run',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
      '--use-angle=swiftshader',
      '--enable-unsafe-swiftshader',
    ],
    viewport: { width: 1280, height: 800 },
    acceptDownloads: true,
    colorScheme: 'light',
  });
  const page = context.pages()[0] ?? (await context.newPage());
  const close = async () => {
    await context.close();
    fs.rmSync(profile, { recursive: true, force: true });
  };
  return { context, page, close };
}

/** Binary STL of a triangle mesh (float32 corners, zero normals), written in 1 MB chunks. */
export function writeBinarySTL(file, { positions, indices }) {
  const n = indices.length / 3;
  const fd = fs.openSync(file, 'w');
  const header = Buffer.alloc(84);
  header.write('binary STL written by the kergen-wasm browser tests', 0);
  header.writeUInt32LE(n, 80);
  fs.writeSync(fd, header);
  const perChunk = 20000;
  const chunk = Buffer.alloc(50 * perChunk);
  for (let t0 = 0; t0 < n; t0 += perChunk) {
    const m = Math.min(perChunk, n - t0);
    chunk.fill(0);
    for (let t = 0; t < m; t++) {
      const o = 50 * t;
      for (let k = 0; k < 3; k++) {
        const v = indices[3 * (t0 + t) + k];
        for (let c = 0; c < 3; c++) chunk.writeFloatLE(positions[3 * v + c], o + 12 + 12 * k + 4 * c);
      }
    }
    fs.writeSync(fd, chunk, 0, 50 * m);
  }
  fs.closeSync(fd);
}

/**
 * Fetches `url` into a File in the page (before any measurement: the test's own copying must not
 * count), then drops it on the view with a PerformanceObserver for 'longtask' running, waits for
 * the final state, shows the whole kernel at once (Show result) and waits two frames. Returns the page's
 * numbers: drop → shown (ms), the page's own stats, and the long tasks seen (longest, count, sum).
 */
export async function dropAndMeasure(page, url, name, { timeout = 300000 } = {}) {
  await page.evaluate(
    async ({ url, name }) => {
      const blob = await (await fetch(url)).blob();
      window.__dropFile = new File([blob], name);
      document.getElementById('status').dataset.state = 'test-pending';
    },
    { url, name },
  );
  await page.waitForTimeout(300); // let the fetch's own tasks settle
  await page.evaluate(() => {
    window.__longTasks = [];
    window.__observer = new PerformanceObserver((list) => {
      for (const e of list.getEntries()) window.__longTasks.push({ start: e.startTime, duration: e.duration });
    });
    window.__observer.observe({ type: 'longtask' });
    const dt = new DataTransfer();
    dt.items.add(window.__dropFile);
    // The final state is caught in the page (no polling latency): then Show result at once,
    // and the kernel is on screen two frames later.
    window.__doneAt = window.__shownAt = null;
    const status = document.getElementById('status');
    const watch = new MutationObserver(() => {
      if (window.__doneAt != null || !['done', 'error', 'cancelled'].includes(status.dataset.state)) return;
      window.__doneAt = performance.now();
      watch.disconnect();
      document.getElementById('jump-end').click();
      requestAnimationFrame(() =>
        requestAnimationFrame(() => {
          window.__shownAt = performance.now();
        }),
      );
    });
    watch.observe(status, { attributes: true });
    window.__dropT0 = performance.now();
    document
      .getElementById('viewport')
      .dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  });
  await page.waitForFunction(() => window.__shownAt != null, null, { timeout, polling: 50 });
  return page.evaluate(async () => {
    const doneMs = window.__doneAt - window.__dropT0,
      shownMs = window.__shownAt - window.__dropT0;
    await new Promise((r) => setTimeout(r, 200)); // long tasks are reported after they end
    window.__observer.disconnect();
    const tasks = window.__longTasks;
    const $ = (id) => document.getElementById(id);
    return {
      doneMs,
      shownMs,
      dropT0: window.__dropT0,
      state: $('status').dataset.state,
      status: $('status').dataset.value,
      statusText: $('status').textContent,
      message: $('message').hidden ? null : $('message').textContent,
      workerMs: Number($('stat-time').dataset.value),
      wallMs: Number($('stat-wall').dataset.value),
      wallText: $('stat-wall').textContent,
      timeText: $('stat-time').textContent,
      vertices: Number($('stat-vertices').dataset.value),
      edges: Number($('stat-edges').dataset.value),
      faces: Number($('stat-faces').dataset.value),
      inputFaces: Number($('stat-input-faces').dataset.value),
      volume: Number($('stat-volume').dataset.value),
      phases: $('busy').dataset.phases,
      steps: Number($('scrubber').max),
      step: Number($('scrubber').value),
      longest: tasks.reduce((m, t) => Math.max(m, t.duration), 0),
      longTasks: tasks.length,
      longTaskMs: tasks.reduce((s, t) => s + t.duration, 0),
      tasks,
    };
  });
}

// Drags the view in a slow figure for `ms` milliseconds and returns the requestAnimationFrame
// deltas seen meanwhile (ms, in order; the first two, which straddle the start, dropped).
export async function dragFrameDeltas(page, { ms = 1000 } = {}) {
  const box = await page.locator('#viewport').boundingBox();
  await page.evaluate(() => {
    window.__frames = [];
    let last = performance.now();
    const tick = (t) => {
      window.__frames.push(t - last);
      last = t;
      if (!window.__stopFrames) requestAnimationFrame(tick);
    };
    window.__stopFrames = false;
    requestAnimationFrame(tick);
  });
  const cx = box.x + box.width / 2,
    cy = box.y + box.height / 3;
  await page.mouse.move(cx, cy);
  await page.mouse.down();
  const t0 = Date.now();
  for (let i = 1; Date.now() - t0 < ms; i++) {
    await page.mouse.move(cx + 150 * Math.sin(i / 8), cy + 40 * Math.cos(i / 11));
    await page.waitForTimeout(16);
  }
  await page.mouse.up();
  return (await page.evaluate(() => ((window.__stopFrames = true), window.__frames))).slice(2);
}

// Sets `file` on the file input at `selector` and waits until the text at `outSelector` changes
// and no longer starts with "Reading"; returns that text.
export async function chooseAndWait(page, selector, file, outSelector) {
  const before = await page.textContent(outSelector);
  await page.setInputFiles(selector, file);
  await page.waitForFunction(
    ([sel, old]) => {
      const t = document.querySelector(sel).textContent;
      return t !== old && !/^Reading/.test(t);
    },
    [outSelector, before],
    { timeout: 60000 },
  );
  return page.textContent(outSelector);
}

// Pixels of the canvas that are not the renderer's black background, and the orange (kernel) ones,
// read two frames after the call (three.js has drawn the latest scene).
export const canvasPixels = (page) =>
  page.evaluate(
    () =>
      new Promise((resolve) =>
        requestAnimationFrame(() =>
          requestAnimationFrame(() => {
            const c = document.querySelector('canvas');
            const copy = document.createElement('canvas');
            copy.width = c.width;
            copy.height = c.height;
            const ctx = copy.getContext('2d');
            ctx.drawImage(c, 0, 0);
            const d = ctx.getImageData(0, 0, c.width, c.height).data;
            let drawn = 0,
              orange = 0;
            for (let i = 0; i < d.length; i += 4) {
              if (d[i] > 12 || d[i + 1] > 12 || d[i + 2] > 12) drawn++;
              if (d[i] > 120 && d[i] - d[i + 2] > 80) orange++;
            }
            resolve({ drawn, orange });
          }),
        ),
      ),
  );
