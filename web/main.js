// kergen-wasm demo: load a mesh (file, drop, link or generated sample), compute its kernel in a
// worker (the package's KernelWorker), and animate the kernel's growth from the stream of step
// events. Nothing heavy runs on this thread: a file's bytes go to the worker untouched (it parses
// them with the package's reader; GLB/glTF, a scene format, is read by three.js's loader), the
// input is prepared for drawing in a second worker (draw-worker.js), and the replay only moves
// draw ranges.

import { viewer, state, PARAMS } from './page-state.js';
import { setStatus, showRows } from './page-text.js';
import { drawRequest } from './workers.js';
import { openSource, openUrl } from './sources.js';
import { viewToControls, updateShareUrl } from './controls.js';
import './playback.js';
import { installFaceInfo, kernelFaceAt } from './face-info.js';
import { sampleById } from './samples.js';

// For the browser tests: the view (camera, scene) and the page's state, read-only by convention.
window.kergenDemo = { viewer, state, kernelFaceAt };

const canvas = viewer.renderer.domElement;
canvas.setAttribute('role', 'img');
canvas.tabIndex = 0; // focusable: the view's label is read, and the keys work from there too
setStatus('idle', 'No mesh loaded.');
showRows(['name']);
viewToControls();
installFaceInfo();

// Start the drawing worker now, not when the first big file arrives.
drawRequest({ type: 'noop' });

if (PARAMS.has('url')) openUrl(PARAMS.get('url'), state.runOptions);
else {
  const initial = PARAMS.get('sample') ?? 'star-prism';
  if (sampleById(initial)) openSource({ kind: 'sample', id: initial }, state.runOptions);
  else updateShareUrl();
}
