// Controls: export, the view options (each written to state.view, which the shareable URL
// carries), the link to this view, fitting, and the keyboard shortcuts.

import { state, ui, viewer } from './page-state.js';
import { showError } from './page-text.js';
import { drawRequest, worker } from './workers.js';
import { shareUrl } from './share.js';

function download(blob, filename) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = filename;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 10000);
}

const baseName = () => (state.name || 'mesh').replace(/\.[a-z0-9]+$/i, '').replace(/[^\w.-]+/g, '_');

// The kernel's file is written by the package (the same writer as the CLI's -o), in the worker.
async function exportKernel(format, mime) {
  const r = state.result;
  if (!r) return;
  try {
    const bytes = await worker().writeMesh(r, format);
    download(new Blob([bytes], { type: mime }), `${baseName()}-kernel.${format}`);
  } catch (err) {
    showError(err);
  }
}
ui.exportObj.addEventListener('click', () => exportKernel('obj', 'text/plain'));
ui.exportStl.addEventListener('click', () => exportKernel('stl', 'model/stl'));
ui.exportOff.addEventListener('click', () => exportKernel('off', 'text/plain'));

// ------------------------------------------------------------------------------------------
// View controls. Each writes state.view, which the shareable URL carries.

function opacityFromSlider() {
  const x = Number(ui.opacity.value);
  state.view.opacity = x;
  viewer.setOpacity(x);
  ui.opacityLabel.textContent = `${Math.round(100 * x)} %`;
}
ui.opacity.addEventListener('input', () => {
  opacityFromSlider();
  updateShareUrl();
});

ui.showInput.addEventListener('change', () => {
  state.view.shape = ui.showInput.checked;
  viewer.setInputVisible(ui.showInput.checked);
  updateShareUrl();
});

ui.showBall.addEventListener('change', () => {
  state.view.ball = ui.showBall.checked;
  viewer.setBallVisible(ui.showBall.checked);
  updateShareUrl();
});

ui.showEdges.addEventListener('change', async () => {
  const on = ui.showEdges.checked;
  viewer.setEdgesVisible(on);
  if (on && !state.edgesReady && state.inputShown) {
    // A big file's edges were not computed up front: the drawing worker still has the mesh.
    state.edgesReady = true;
    const token = state.token;
    const { edges } = await drawRequest({ type: 'edges' });
    if (token === state.token && edges) viewer.setInputEdges(edges);
  }
});
ui.showEdges.addEventListener('input', () => {
  state.view.edges = ui.showEdges.checked;
  updateShareUrl();
});

export function applySection() {
  const v = state.view;
  viewer.setSection({ on: v.section, axis: 'xyz'.indexOf(v.axis), at: v.pos, clipKernel: v.clipKernel });
  ui.sectionLabel.textContent = `${Math.round(100 * v.pos)} %`;
  for (const el of [ui.sectionAxis, ui.sectionPos, ui.sectionKernel]) el.disabled = !v.section;
}
function sectionFromControls() {
  Object.assign(state.view, {
    section: ui.sectionOn.checked,
    axis: ui.sectionAxis.value,
    pos: Number(ui.sectionPos.value),
    clipKernel: ui.sectionKernel.checked,
  });
  applySection();
  updateShareUrl();
}
for (const el of [ui.sectionOn, ui.sectionAxis, ui.sectionKernel]) el.addEventListener('change', sectionFromControls);
ui.sectionPos.addEventListener('input', sectionFromControls);

// The controls as state.view says (from the URL at start).
export function viewToControls() {
  const v = state.view;
  ui.opacity.value = String(v.opacity);
  ui.showInput.checked = v.shape;
  ui.showBall.checked = v.ball;
  ui.sectionOn.checked = v.section;
  ui.sectionAxis.value = v.axis;
  ui.sectionPos.value = String(v.pos);
  ui.sectionKernel.checked = v.clipKernel;
  opacityFromSlider();
  viewer.setInputVisible(v.shape);
  viewer.setBallVisible(v.ball);
  applySection();
}

// The page's URL always reopens what is shown (a sample or a link, with the view options); a
// file from this computer cannot be reopened by a link.
export function updateShareUrl() {
  const url = shareUrl(location.href, state.source, state.runOptions, state.view);
  if (url) history.replaceState(null, '', url);
  else if (location.search) history.replaceState(null, '', location.pathname);
  ui.shareUrl.value = url ?? '';
  ui.copyLink.disabled = !url;
  ui.shareNote.textContent = url
    ? ''
    : 'A file opened from this computer cannot be reopened by a link; samples and meshes opened with ?url= can.';
}

ui.copyLink.addEventListener('click', async () => {
  try {
    await navigator.clipboard.writeText(ui.shareUrl.value);
    ui.shareNote.textContent = 'Link copied.';
  } catch {
    // No clipboard permission: select the link for the user to copy.
    ui.shareUrl.focus();
    ui.shareUrl.select();
    ui.shareNote.textContent = 'The clipboard is not available here: the link is selected, copy it with Ctrl+C.';
  }
});

// The play bar covers the bottom of the view: fitting uses the area above it.
new ResizeObserver(() => {
  const view = ui.viewport.getBoundingClientRect(),
    bar = ui.playbar.getBoundingClientRect();
  viewer.setInsetBottom(Math.max(0, view.bottom - bar.top));
}).observe(ui.playbar);

ui.fit.addEventListener('click', () => viewer.fit());
ui.fitKernel.addEventListener('click', () => viewer.fit(true));

// Shortcuts work wherever the focus is, except where a key types text or picks an option.
const typesText = (el) =>
  el instanceof HTMLTextAreaElement ||
  el instanceof HTMLSelectElement ||
  el?.isContentEditable ||
  (el instanceof HTMLInputElement &&
    !['checkbox', 'radio', 'range', 'button', 'submit', 'reset', 'file', 'color'].includes(el.type));
const SHORTCUTS = {
  f: () => viewer.fit(),
  k: () => viewer.fit(true),
  h: () => ui.showInput.click(),
  s: () => ui.sectionOn.click(),
  ' ': () => ui.play.click(),
};
window.addEventListener('keydown', (e) => {
  if (e.ctrlKey || e.metaKey || e.altKey || typesText(e.target)) return;
  const action = SHORTCUTS[e.key.toLowerCase()];
  if (!action) return;
  // Space would also press the focused button or tick the focused box: play/pause instead.
  e.preventDefault();
  if (!e.repeat) action();
});
window.addEventListener('keyup', (e) => {
  if (e.key === ' ' && !typesText(e.target)) e.preventDefault();
});
