// Playback of the kernel's step events: play/pause, the step scrubber, Show result, speed, and
// the frame loop that shows the replay's prefix and renders.

import { MIN_STEPS_PER_S, REPLAY_SECONDS, state, ui, viewer } from './page-state.js';
import { fmt, fmtCount } from './page-text.js';

// "Pause" only while something plays: not at step 0 of nothing (computing, error, cancel).
export function setPlayButton() {
  const playing = state.playing && viewer.kernel.length > 0;
  ui.play.textContent = playing ? 'Pause' : 'Play';
  ui.play.setAttribute('aria-pressed', String(playing));
}

// Steps per second at speed 1×: a full replay takes at most REPLAY_SECONDS whatever the
// kernel's size (a million-step kernel moves tens of thousands of steps per frame; a frame's work
// does not depend on it: show(k) only sets draw ranges).
const replayRate = () => Math.max(MIN_STEPS_PER_S, viewer.kernel.length / REPLAY_SECONDS);

function speedFromSlider() {
  state.speed = 2 ** Number(ui.speed.value);
  updateSpeedLabel();
}

let speedLabel = '';
function updateSpeedLabel() {
  const mult = state.speed >= 1 ? `${fmt(state.speed, 3)}×` : `1/${fmt(1 / state.speed, 3)}×`;
  const text = `${mult} (${fmtCount(Math.round(state.speed * replayRate()))} steps/s)`;
  if (text !== speedLabel) ui.speedLabel.textContent = speedLabel = text;
}
ui.speed.addEventListener('input', speedFromSlider);
speedFromSlider();

ui.play.addEventListener('click', () => {
  const total = viewer.kernel.length;
  if (!state.playing && state.result && Math.floor(state.cursor) >= total) state.cursor = 0; // replay
  state.playing = !state.playing;
  state.stickToEnd = false;
  setPlayButton();
});
ui.jumpEnd.addEventListener('click', () => {
  state.stickToEnd = true;
  state.playing = false;
  state.cursor = viewer.kernel.length;
  setPlayButton();
});
ui.scrubber.addEventListener('input', () => {
  state.playing = false;
  state.stickToEnd = false;
  state.cursor = Number(ui.scrubber.value);
  setPlayButton();
});

let lastFrame = performance.now();
let lastUi = '';
function frame(now) {
  const dt = Math.min(0.25, (now - lastFrame) / 1000);
  lastFrame = now;
  const total = viewer.kernel.length;
  if (state.stickToEnd) state.cursor = total;
  else if (state.playing) {
    state.cursor = Math.min(total, state.cursor + state.speed * replayRate() * dt);
    if (state.result && state.cursor >= total) {
      state.playing = false;
      setPlayButton();
    }
  }
  const k = Math.floor(state.cursor);
  const c = viewer.kernel.show(k);
  const key = `${k}/${total}/${c.vertices}/${c.edges}/${c.faces}/${state.computing}`;
  if (key !== lastUi) {
    lastUi = key;
    // Nothing to play (before the first step, after an error, an empty kernel): no controls that do nothing.
    ui.play.disabled = ui.jumpEnd.disabled = ui.scrubber.disabled = total === 0;
    setPlayButton();
    ui.scrubber.max = String(total);
    ui.scrubber.value = String(k);
    ui.stepLabel.textContent = `${k} / ${total}${state.computing ? '+' : ''}`;
    updateSpeedLabel();
    for (const [el, v] of [
      [ui.animV, c.vertices],
      [ui.animE, c.edges],
      [ui.animF, c.faces],
    ]) {
      el.textContent = String(v);
      el.dataset.value = String(v);
    }
  }
  viewer.render(state.computing);
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);
