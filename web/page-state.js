// The page's state, its controls (the DOM elements it reads and writes) and the view: shared by
// the page's modules (page-text, runs, sources, playback, controls).

import { Viewer } from './viewer.js';
import { viewFromParams } from './share.js';

// Above this many faces the input is prepared in the drawing worker, and its face edges are off
// by default (a dense wireframe hides the kernel and costs every frame).
export const INLINE_FACES = 20000;
export const EDGE_FACES = 50000;
// Above this many triangles the view draws a simplified copy of the input (draw-prep.js simplify).
export const DRAW_TRIANGLES = 10000;
// Above this many triangles a complete kernel is drawn from a simplified copy of about
// KERNEL_DRAW_TRIANGLES (the kernel's own faces for any shorter prefix of the replay).
export const KERNEL_SIMPLIFY_TRIANGLES = 50000;
export const KERNEL_DRAW_TRIANGLES = 20000;
// A full replay at speed 1× takes at most this long, whatever the kernel's size.
export const REPLAY_SECONDS = 10;
export const MIN_STEPS_PER_S = 40;
// ?stream=0: compute without step events (the replay is then built from the result); for
// measuring what streaming costs (bench/browser_bench.mjs).
export const PARAMS = new URLSearchParams(location.search);
export const STREAM = PARAMS.get('stream') !== '0';

export const $ = (id) => document.getElementById(id);
export const ui = {
  fileInput: $('file-input'),
  samples: $('samples'),
  viewport: $('viewport'),
  overlay: $('drop-overlay'),
  busy: $('busy'),
  busyText: $('busy-text'),
  play: $('play'),
  jumpEnd: $('jump-end'),
  cancel: $('cancel'),
  scrubber: $('scrubber'),
  stepLabel: $('step-label'),
  speed: $('speed'),
  speedLabel: $('speed-label'),
  animV: $('anim-vertices'),
  animE: $('anim-edges'),
  animF: $('anim-faces'),
  status: $('status'),
  message: $('message'),
  exportObj: $('export-obj'),
  exportStl: $('export-stl'),
  exportOff: $('export-off'),
  fit: $('fit-view'),
  fitKernel: $('fit-kernel'),
  opacity: $('opacity'),
  opacityLabel: $('opacity-label'),
  showEdges: $('show-edges'),
  edgesNote: $('edges-note'),
  openFile: $('open-file'),
  showInput: $('show-input'),
  showBall: $('show-ball'),
  sectionOn: $('section-on'),
  sectionAxis: $('section-axis'),
  sectionKernel: $('section-kernel'),
  sectionPos: $('section-pos'),
  sectionLabel: $('section-label'),
  shareUrl: $('share-url'),
  copyLink: $('copy-link'),
  shareNote: $('share-note'),
  actions: $('actions'),
  retryOpen: $('retry-open'),
  retryFlip: $('retry-flip'),
  retryWalls: $('retry-walls'),
  retryRepair: $('retry-repair'),
  retryWeld: $('retry-weld'),
  faceInfo: $('face-info'),
  faceHint: $('face-hint'),
  playbar: $('playbar'),
};

export const viewer = new Viewer(ui.viewport);

export const state = {
  token: 0, // identifies the current run; results of older runs are ignored
  worker: null,
  computing: false,
  name: '',
  result: null,
  t0: 0,
  timing: {},
  cursor: 0,
  playing: true,
  stickToEnd: false,
  speed: 1, // multiplier of the base replay rate (replayRate())
  seen: { vertex: new Set(), edge: new Set(), face: new Set() },
  inputShown: false, // step events wait in `pending` until the input (and its centre) is drawn
  pending: [],
  faces: 0,
  edgesReady: false,
  // What is open, kept so that it can be computed again with other options (see open()).
  source: null,
  runOptions: {
    allowOpen: PARAMS.get('allowOpen') === '1',
    repair: PARAMS.get('repair') === '1',
    walls: PARAMS.get('open') === 'perpendicular',
    weld: PARAMS.get('weld') === '1',
    flipFaces: PARAMS.get('flipFaces') === '1',
  },
  view: viewFromParams(PARAMS),
  mesh: null, // the parsed input when it is drawn on this thread (small); else the drawing worker has it
  drawing: null, // { center, maxAbs } of the drawn input
  openEdges: 0,
  // The input as computed (its mesh and the options its kind needs, e.g. weld for STL), kept to
  // try a refusal's alternatives (trials.js); null for meshes too big to try.
  input: null,
  // { source, trials: { [alternative]: outcome }, ranked, results: { [alternative]: result } }:
  // what was tried after a refusal of `source`; kept while the same source is computed again
  // (retry buttons). A retry button shows its alternative's result (once) instead of computing it again.
  trials: null,
  trying: false,
};
