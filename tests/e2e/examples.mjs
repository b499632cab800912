// The browser examples from the packed tarball, in Chromium: a temporary copy of each with the
// tarball installed (extracted into node_modules: offline), then
//   examples/vite-three: built with the repository's Vite (three and vite linked from its
//     node_modules) and served; given a GLB (a 1×2×3 box scaled ×2 by its node: volume 12), an
//     STL (plus prism: kernel volume 1 of 5), an OBJ (L prism: 1 of 3) and an open mesh through
//     its file input: the page's output says each kernel, and the kernel drawn shrinks from the
//     box to the cube (the next file replaces the shape and its kernel); the open mesh's error
//     code is shown;
//   examples/no-bundler: served as it is (an import map to node_modules), given an OFF L prism and
//     a malformed file.
// Run by run.mjs (npm run test:e2e), or alone: node tests/e2e/examples.mjs
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve, launch, chooseAndWait, canvasPixels } from './page-tools.mjs';
import { extractTarball, packTarball } from '../node/lib/pack.mjs';
import { glbOf, lPrismFiles, plusPrismStl, scaledBoxScene } from '../node/lib/example-meshes.mjs';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

function copyExample(name, tmp, tarball) {
  const app = path.join(tmp, name);
  fs.cpSync(path.join(repo, 'examples', name), app, {
    recursive: true,
    filter: (src) => !/node_modules|[/\\]dist$/.test(src),
  });
  extractTarball(tarball, app);
  return app;
}

async function writeMeshFiles(dir) {
  fs.mkdirSync(dir, { recursive: true });
  const l = lPrismFiles();
  const files = {
    'box-scaled.glb': Buffer.from(await glbOf(scaledBoxScene().scene)),
    'plus.stl': plusPrismStl(),
    'l-prism.obj': l.obj,
    'l-prism.off': l.off,
    'open.obj': l.obj.split('\n').slice(0, -3).join('\n') + '\n', // the last two faces left out
    'broken.off': 'OFF\n3 1 0\n0 0 0\n1 0 0\n',
  };
  for (const [name, data] of Object.entries(files)) fs.writeFileSync(path.join(dir, name), data);
  return (name) => path.join(dir, name);
}

export async function examplesTests(context, tmp, { test, assert, artifacts }) {
  let tarball;
  const ready = async () => {
    if (!tarball) tarball = packTarball(tmp).tarball;
    return tarball;
  };
  const mesh = await writeMeshFiles(path.join(tmp, 'example-meshes'));

  await test('examples/vite-three from the tarball: GLB (scaled box: 12), STL (1 of 5), OBJ (1 of 3), each replacing the last; an open mesh shows OPEN_MESH', async () => {
    const app = copyExample('vite-three', tmp, await ready());
    for (const dep of ['three', 'vite'])
      fs.symlinkSync(path.join(repo, 'node_modules', dep), path.join(app, 'node_modules', dep), 'dir');
    const vite = await import('vite');
    await vite.build({ root: app, logLevel: 'warn', build: { chunkSizeWarningLimit: 4000 } });
    const server = await serve(path.join(app, 'dist'));
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
    try {
      await page.goto(`http://127.0.0.1:${server.address().port}/`);
      const parse = (text) => {
        const m = /^(\w+), volume (\S+) of (\S+)$/.exec(text);
        assert(m, `the output says a kernel: ${text}`);
        return { status: m[1], volume: Number(m[2]), shapeVolume: Number(m[3]) };
      };
      const expectations = [
        ['box-scaled.glb', 12, 12],
        ['plus.stl', 1, 5],
        ['l-prism.obj', 1, 3],
      ];
      const orange = [];
      for (const [name, volume, shapeVolume] of expectations) {
        const r = parse(await chooseAndWait(page, 'input', mesh(name), 'output'));
        assert(r.status === 'POLYHEDRON', `${name}: ${r.status}`);
        assert(Math.abs(r.volume - volume) <= 1e-12 * volume, `${name}: kernel volume ${r.volume}, expected ${volume}`);
        assert(
          Math.abs(r.shapeVolume - shapeVolume) <= 1e-12 * shapeVolume,
          `${name}: shape volume ${r.shapeVolume}, expected ${shapeVolume}`,
        );
        await page.waitForTimeout(300);
        orange.push((await canvasPixels(page)).orange);
        await page.screenshot({ path: path.join(artifacts, `example-vite-three-${name}.png`) });
      }
      // The box's kernel is the whole box; the plus prism's only its central cube, seen from the
      // same distance relative to the shape: far fewer kernel pixels once the box is replaced.
      assert(orange[0] > 20000, `the box kernel is drawn: ${orange[0]} orange pixels`);
      assert(orange[1] > 1000 && orange[1] < orange[0] / 3, `the plus kernel replaced the box's: ${orange}`);
      const bad = await chooseAndWait(page, 'input', mesh('open.obj'), 'output');
      assert(/^OPEN_MESH: /.test(bad), `the error is shown with its code: ${bad}`);
      assert(errors.length === 0, errors.join(' | '));
      console.log(`     vite-three: kernel volumes 12, 1, 1; orange pixels ${orange.join(', ')}`);
    } finally {
      await page.close();
      server.close();
    }
  });

  await test('examples/no-bundler from the tarball (import map, module worker): OFF L prism → volume 1 of 3; a malformed file → PARSE_ERROR', async () => {
    const app = copyExample('no-bundler', tmp, await ready());
    const server = await serve(app);
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
    try {
      await page.goto(`http://127.0.0.1:${server.address().port}/`);
      const text = await chooseAndWait(page, 'input', mesh('l-prism.off'), 'pre');
      const r = JSON.parse(text);
      assert(r.status === 'POLYHEDRON' && r.file === 'l-prism.off', text);
      assert(
        Math.abs(r.volume - 1) <= 1e-12 && Math.abs(r.shapeVolume - 3) <= 1e-12,
        `volumes ${r.volume} of ${r.shapeVolume}`,
      );
      assert(r.vertices === 8 && r.edges === 12 && r.faces === 6, `counts ${r.vertices}/${r.edges}/${r.faces}`);
      assert(await page.isVisible('a[download]'), 'the kernel can be downloaded');
      const [download] = await Promise.all([page.waitForEvent('download'), page.click('a[download]')]);
      const stl = fs.readFileSync(await download.path());
      assert(
        stl.length === 84 + 50 * stl.readUInt32LE(80) && stl.readUInt32LE(80) === 12,
        `the kernel as STL: ${stl.length} B`,
      );
      const bad = await chooseAndWait(page, 'input', mesh('broken.off'), 'pre');
      assert(/^PARSE_ERROR: .*broken\.off/.test(bad), `the error is shown with its code: ${bad}`);
      assert(errors.length === 0, errors.join(' | '));
    } finally {
      await page.close();
      server.close();
    }
  });
}

// Alone: node tests/e2e/examples.mjs
if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-e2e-examples-'));
  const artifacts = path.join(repo, 'tests/artifacts');
  fs.mkdirSync(artifacts, { recursive: true });
  const { context, close } = await launch();
  let failed = 0;
  const test = async (name, fn) => {
    try {
      await fn();
      console.log(`ok   ${name}`);
    } catch (err) {
      failed++;
      console.log(`FAIL ${name}: ${err?.stack ?? err}`);
    }
  };
  const assert = (cond, message) => {
    if (!cond) throw new Error(message);
  };
  try {
    await examplesTests(context, tmp, { test, assert, artifacts });
  } finally {
    await close();
    fs.rmSync(tmp, { recursive: true, force: true });
  }
  process.exitCode = failed ? 1 : 0;
}
