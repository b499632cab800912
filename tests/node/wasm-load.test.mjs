// A wrong wasmUrl is reported with the URL and the HTTP status (or what was served instead of a
// WebAssembly module), not as a CompileError: in Node (http URLs) and on the browser path (where
// `window` exists, the .wasm is fetched and checked by index.js, then given to the glue).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import http from 'node:http';
import { assertBuilt, distWasm } from './lib/env.mjs';
import { freshWrapper } from './lib/fresh-wrapper.mjs';

let server;
let base;
before(async () => {
  assertBuilt();
  const wasm = fs.readFileSync(distWasm);
  server = http.createServer((req, res) => {
    if (req.url === '/kergen.wasm') {
      res.writeHead(200, { 'content-type': 'application/wasm' });
      res.end(wasm);
    } else if (req.url === '/spa.wasm') {
      // A dev server's single-page-app fallback: 200 with the app's HTML.
      res.writeHead(200, { 'content-type': 'text/html' });
      res.end('<!doctype html><html><body>app</body></html>');
    } else {
      res.writeHead(404, { 'content-type': 'text/html' });
      res.end('<!doctype html><h1>404 Not Found</h1>');
    }
  });
  await new Promise((r) => server.listen(0, '127.0.0.1', r));
  base = `http://127.0.0.1:${server.address().port}`;
});
after(() => server.close());

const failsWith = (pattern) => (err) => {
  assert.equal(err.code, 'WASM_LOAD_FAILED');
  assert.match(err.message, pattern);
  assert.doesNotMatch(err.message, /magic/i);
  return true;
};

test('Node: a 404 and an HTML page name the URL and the status; then the right URL loads', async () => {
  const K = await freshWrapper();
  await assert.rejects(
    K.init({ wasmUrl: `${base}/missing.wasm` }),
    failsWith(new RegExp(`${base}/missing\\.wasm: HTTP 404 Not Found$`)),
  );
  await assert.rejects(
    K.init({ wasmUrl: `${base}/spa.wasm` }),
    failsWith(
      /spa\.wasm: HTTP 200 OK but not a WebAssembly module \(content-type text\/html, starts with "<!doctype html><html><bo"\)/,
    ),
  );
  assert.equal(K.isInitialized(), false);
  await K.init({ wasmUrl: `${base}/kergen.wasm` });
  assert.equal(K.isInitialized(), true);
});

test('browser path (window defined): the same checks before the glue compiles anything', async () => {
  globalThis.window = globalThis; // what index.js and the glue look at to tell a page from Node
  try {
    const K = await freshWrapper();
    await assert.rejects(K.init({ wasmUrl: `${base}/missing.wasm` }), failsWith(/missing\.wasm: HTTP 404 Not Found$/));
    await assert.rejects(
      K.init({ wasmUrl: `${base}/spa.wasm` }),
      failsWith(/HTTP 200 OK but not a WebAssembly module \(content-type text\/html/),
    );
    await assert.rejects(
      K.init({ wasmUrl: 'http://127.0.0.1:1/kergen.wasm' }),
      failsWith(/could not load kergen\.wasm from http:\/\/127\.0\.0\.1:1\/kergen\.wasm: /),
    );
    await K.init({ wasmUrl: `${base}/kergen.wasm` });
    const cube = [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1];
    const idx = [
      0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5,
    ];
    assert.equal((await K.computeKernel(cube, idx)).volume, 1, 'the module fetched on the browser path works');
  } finally {
    delete globalThis.window;
  }
});
