// The demo page's modules (web/*.js) import each other in one direction: no module imports one
// that imports it back, directly or through others (a cycle makes the order in which modules run
// depend on which one the page loads first).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const web = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../web');

// Each module's relative imports (static `import ... from './x.js'` and `import './x.js'`).
function importGraph(dir) {
  const graph = new Map();
  for (const file of fs.readdirSync(dir).filter((f) => f.endsWith('.js'))) {
    const text = fs.readFileSync(path.join(dir, file), 'utf8');
    graph.set(
      file,
      [
        ...text.matchAll(/^import\s[^;]*?['"]\.\/([^'"]+)['"]/gm),
        ...text.matchAll(/^import\s+['"]\.\/([^'"]+)['"]/gm),
      ].map((m) => m[1]),
    );
  }
  return graph;
}

// The cycles of `graph`, each as a path that ends where it starts (depth-first search).
function cycles(graph) {
  const found = [];
  const done = new Set();
  const visit = (file, stack) => {
    const at = stack.indexOf(file);
    if (at >= 0) return void found.push([...stack.slice(at), file].join(' -> '));
    if (done.has(file)) return;
    for (const next of graph.get(file) ?? []) visit(next, [...stack, file]);
    done.add(file);
  };
  for (const file of graph.keys()) visit(file, []);
  return found;
}

test('the cycle finder finds a cycle of two modules and one of three', () => {
  const graph = new Map([
    ['a.js', ['b.js']],
    ['b.js', ['a.js', 'c.js']],
    ['c.js', ['d.js']],
    ['d.js', ['e.js']],
    ['e.js', ['c.js']],
  ]);
  const found = cycles(graph);
  assert.ok(found.includes('a.js -> b.js -> a.js'), found.join('; '));
  assert.ok(found.includes('c.js -> d.js -> e.js -> c.js'), found.join('; '));
});

test('web/: no import cycle among the page modules', () => {
  const graph = importGraph(web);
  assert.ok(graph.size > 20 && graph.get('runs.js').includes('trials.js'), 'the page modules were read');
  assert.deepEqual(cycles(graph), []);
});
