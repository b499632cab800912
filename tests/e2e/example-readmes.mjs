// Each example's README followed as a new user would: the first `sh` block of
// examples/<name>/README.md run line by line in a fresh `git clone` of this repository (its HEAD
// commit), then what the last line starts checked: the served page in Chromium (vite-three and
// vite-three-ts: an OFF file, a file that fails, then an STL and a GLB; no-bundler: an OFF file
// and a malformed one), the printed JSON (node), the printed kernel (cpp-consumer).
//
//   node tests/e2e/example-readmes.mjs [EXAMPLE...]   (npm run test:readmes; default: the four
//                                                      npm examples; cpp-consumer when named)
//
// `npm install` in an example fetches three and vite from the npm registry (the versions users get
// today). The clone's root commands `npm ci` and `npm run build:wasm` take minutes (the whole dev
// toolchain, an Emscripten build): by default they are replaced by linking this checkout's
// node_modules and copying its dist/ (the same files they would produce); KERGEN_README_FULL=1
// runs them as written. Every other line runs as written. Logs: tests/artifacts/readme-<name>.log.
import { execFileSync, spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { launch, chooseAndWait, canvasPixels } from './page-tools.mjs';
import { glbOf, lPrismFiles, plusPrismStl, scaledBoxScene } from '../node/lib/example-meshes.mjs';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const artifacts = path.join(repo, 'tests/artifacts');
const full = process.env.KERGEN_README_FULL === '1';
const SLOW_ROOT_LINES = {
  'npm ci': `ln -s ${JSON.stringify(path.join(repo, 'node_modules'))} node_modules`,
  'npm run build:wasm': `cp -r ${JSON.stringify(path.join(repo, 'dist'))} dist`,
};

function assert(cond, message) {
  if (!cond) throw new Error(message);
}

// The commands of a README: its first ```sh block, one per line.
function readmeCommands(name) {
  const text = fs.readFileSync(path.join(repo, 'examples', name, 'README.md'), 'utf8');
  const block = /```sh\n([\s\S]*?)```/.exec(text);
  assert(block, `examples/${name}/README.md has no sh block`);
  return block[1].split('\n').filter((l) => l.trim());
}

// The files the browser checks open.
async function meshFiles(dir) {
  fs.mkdirSync(dir, { recursive: true });
  const l = lPrismFiles();
  const files = {
    'l-prism.off': l.off,
    'open.obj': l.obj.split('\n').slice(0, -3).join('\n') + '\n', // two faces left out: open
    'plus.stl': plusPrismStl(),
    'box-scaled.glb': Buffer.from(await glbOf(scaledBoxScene().scene)),
    'broken.off': 'OFF\n3 1 0\n0 0 0\n1 0 0\n',
  };
  for (const [file, data] of Object.entries(files)) fs.writeFileSync(path.join(dir, file), data);
  return (file) => path.join(dir, file);
}

async function waitForServer(url, server, log) {
  for (let i = 0; i < 240; i++) {
    if (server.exitCode !== null) throw new Error(`the server exited (${server.exitCode}): see ${log}`);
    try {
      const res = await fetch(url);
      if (res.ok) return;
    } catch {
      // not up yet
    }
    await new Promise((r) => setTimeout(r, 250));
  }
  throw new Error(`${url} did not answer within 60 s`);
}

// The three.js app of vite-three and vite-three-ts, served at `url`.
async function checkThreeApp(context, url, mesh, name) {
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  const seen = [];
  try {
    await page.goto(url);
    const kernel = (text, volume, shapeVolume) => {
      const m = /^POLYHEDRON, volume (\S+) of (\S+)$/.exec(text);
      assert(m, `the output says a kernel: ${text}`);
      assert(Math.abs(Number(m[1]) - volume) <= 1e-12 * volume, `kernel volume ${m[1]}, expected ${volume}`);
      assert(
        Math.abs(Number(m[2]) - shapeVolume) <= 1e-12 * shapeVolume,
        `shape volume ${m[2]}, expected ${shapeVolume}`,
      );
    };
    // An OFF file: read by the package's readers (three.js has no OFF loader).
    kernel(await chooseAndWait(page, 'input', mesh('l-prism.off'), 'output'), 1, 3);
    const off = await canvasPixels(page);
    await page.screenshot({ path: path.join(artifacts, `readme-${name}-off.png`) });
    assert(off.orange > 1000, `the OFF file's kernel is drawn: ${JSON.stringify(off)}`);
    // A file that fails: its error, and nothing left of the last file's shape or kernel.
    const bad = await chooseAndWait(page, 'input', mesh('open.obj'), 'output');
    assert(/^OPEN_MESH: the mesh is open/.test(bad), `the error is shown with its code: ${bad}`);
    assert(!/weld: true/.test(bad), `the helpers weld already: no weld hint: ${bad}`);
    const failed = await canvasPixels(page);
    await page.screenshot({ path: path.join(artifacts, `readme-${name}-failed.png`) });
    assert(failed.drawn === 0, `the previous shape and kernel are cleared: ${JSON.stringify(failed)}`);
    // A good file after it, then a glTF scene.
    kernel(await chooseAndWait(page, 'input', mesh('plus.stl'), 'output'), 1, 5);
    const stl = await canvasPixels(page);
    assert(stl.orange > 500, `the STL's kernel is drawn after the failure: ${JSON.stringify(stl)}`);
    kernel(await chooseAndWait(page, 'input', mesh('box-scaled.glb'), 'output'), 12, 12);
    await page.screenshot({ path: path.join(artifacts, `readme-${name}-glb.png`) });
    assert(errors.length === 0, errors.join(' | '));
    seen.push(
      `OFF 1 of 3 (${off.orange} orange px)`,
      `${bad.split(':')[0]} (0 px drawn)`,
      'STL 1 of 5',
      'GLB 12 of 12',
    );
  } finally {
    await page.close();
  }
  return seen.join('; ');
}

async function checkNoBundler(context, url, mesh) {
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  try {
    await page.goto(url);
    const r = JSON.parse(await chooseAndWait(page, 'input', mesh('l-prism.off'), 'pre'));
    assert(r.status === 'POLYHEDRON' && r.volume === 1 && r.shapeVolume === 3, JSON.stringify(r));
    const bad = await chooseAndWait(page, 'input', mesh('broken.off'), 'pre');
    assert(/^PARSE_ERROR: .*broken\.off/.test(bad), `the error is shown with its code: ${bad}`);
    assert(errors.length === 0, errors.join(' | '));
    return `OFF: ${r.status} ${r.volume} of ${r.shapeVolume}; broken.off: PARSE_ERROR`;
  } finally {
    await page.close();
  }
}

// Runs `name`'s README in a fresh clone; returns what was checked.
async function followReadme(name, tmp, context, mesh) {
  const lines = readmeCommands(name);
  const clone = path.join(tmp, `clone-${name}`);
  const log = path.join(artifacts, `readme-${name}.log`);
  execFileSync('git', ['clone', '--quiet', repo, clone]);
  const last = lines.at(-1);
  const body = lines.slice(0, -1).map((l) => (!full && SLOW_ROOT_LINES[l]) || l);
  const cwdFile = path.join(tmp, `cwd-${name}`);
  const script = [
    'set -euo pipefail',
    ...body.map((l) => `echo "\\$ ${l.replace(/"/g, '\\"')}"; ${l}`),
    `pwd > ${cwdFile}`,
  ];
  fs.writeFileSync(
    log,
    `# examples/${name}/README.md in ${clone} (${full ? 'every line as written' : `replaced: ${Object.keys(SLOW_ROOT_LINES).join(', ')}`})\n`,
  );
  const out = fs.openSync(log, 'a');
  try {
    execFileSync('bash', ['-c', script.join('\n')], { cwd: clone, stdio: ['ignore', out, out], timeout: 1800000 });
  } catch (err) {
    throw new Error(`a README line failed (${err.status}): see ${log}`);
  }
  const cwd = fs.readFileSync(cwdFile, 'utf8').trim();
  fs.appendFileSync(log, `$ ${last}\n`);
  const server = /^(npx vite preview|python3 -m http\.server)/.test(last);
  if (!server) {
    const text = execFileSync('bash', ['-c', last], { cwd, encoding: 'utf8', timeout: 600000 });
    fs.appendFileSync(log, text);
    if (name === 'node') {
      const r = JSON.parse(text);
      assert(r.status === 'POLYHEDRON' && Math.abs(r.volume - 1 / 6) < 1e-15, text);
      assert(r.vertices === 4 && r.edges === 6 && r.faces === 4, text);
      return `${r.status}, volume ${r.volume}, ${r.vertices}/${r.edges}/${r.faces}`;
    }
    assert(text === 'type: POLYHEDRON\nvertices: 8\nvolume: 8\n', `kernel_info printed: ${text}`);
    return text.trim().replace(/\n/g, ', ');
  }
  const port = /--port (\d+)|http\.server (\d+)/.exec(last).slice(1).find(Boolean);
  const child = spawn('bash', ['-c', `exec ${last}`], { cwd, stdio: ['ignore', out, out], detached: true });
  try {
    const url = `http://localhost:${port}/`;
    await waitForServer(url, child, log);
    return name === 'no-bundler'
      ? await checkNoBundler(context, url, mesh)
      : await checkThreeApp(context, url, mesh, name);
  } finally {
    process.kill(-child.pid, 'SIGTERM');
    fs.closeSync(out);
  }
}

const names = process.argv.slice(2).length
  ? process.argv.slice(2)
  : ['vite-three', 'vite-three-ts', 'no-bundler', 'node'];
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-readmes-'));
fs.mkdirSync(artifacts, { recursive: true });
const mesh = await meshFiles(path.join(tmp, 'meshes'));
const { context, close } = await launch();
let failed = 0;
try {
  for (const name of names) {
    const t = Date.now();
    try {
      const what = await followReadme(name, tmp, context, mesh);
      console.log(`ok   examples/${name}/README.md followed (${Math.round((Date.now() - t) / 1000)} s): ${what}`);
    } catch (err) {
      failed++;
      console.log(`FAIL examples/${name}/README.md: ${err?.message ?? err}`);
    }
  }
} finally {
  await close();
  fs.rmSync(tmp, { recursive: true, force: true });
}
console.log(`readmes: ${names.length - failed} passed, ${failed} failed`);
process.exitCode = failed ? 1 : 0;
