// Step events in batches of typed arrays: how the package's worker (kergen-worker.js) sends a
// trace's events to the page (worker.js). One object per event made a million-event trace cost
// seconds of structured cloning on the receiving thread; a batch is a handful of typed arrays,
// transferred (not copied), and decoded back into the same event objects, in order.
//
// A batch of `count` events:
//   kinds      Uint8Array(count)     0 vertex, 1 edge, 2 face (STEP_KINDS)
//   ids        Uint32Array(count)    each event's id
//   positions  Float64Array(3 V)     the V vertex events' positions (xyz), in event order
//   ends       Uint32Array(2 E)      the E edge events' vertex ids (a, b), in event order
//   loopStarts Uint32Array(F + 1)    face f's loop is loopIds[loopStarts[f] .. loopStarts[f + 1])
//   loopIds    Uint32Array           the F face events' vertex-id loops, concatenated

export const STEP_KINDS = ['vertex', 'edge', 'face'];
const VERTEX = 0,
  EDGE = 1,
  FACE = 2;

function grown(array, needed) {
  if (needed <= array.length) return array;
  const bigger = new array.constructor(Math.max(needed, 2 * array.length));
  bigger.set(array);
  return bigger;
}

/** Collects step events (the objects computeKernel's onStep receives) into a batch. */
export class StepBatchWriter {
  constructor(capacity = 4096) {
    this.kinds = new Uint8Array(capacity);
    this.ids = new Uint32Array(capacity);
    this.positions = new Float64Array(3 * capacity);
    this.ends = new Uint32Array(2 * capacity);
    this.loopStarts = new Uint32Array(capacity + 1);
    this.loopIds = new Uint32Array(4 * capacity);
    this.clear();
  }

  clear() {
    this.count = this.nv = this.ne = this.nf = this.nLoopIds = 0;
  }

  push(event) {
    const i = this.count;
    if (i === this.kinds.length) {
      this.kinds = grown(this.kinds, i + 1);
      this.ids = grown(this.ids, i + 1);
    }
    this.ids[i] = event.id;
    if (event.type === 'vertex') {
      this.kinds[i] = VERTEX;
      this.positions = grown(this.positions, 3 * this.nv + 3);
      this.positions.set(event.position, 3 * this.nv++);
    } else if (event.type === 'edge') {
      this.kinds[i] = EDGE;
      this.ends = grown(this.ends, 2 * this.ne + 2);
      this.ends[2 * this.ne] = event.a;
      this.ends[2 * this.ne++ + 1] = event.b;
    } else {
      this.kinds[i] = FACE;
      const loop = event.loop;
      this.loopIds = grown(this.loopIds, this.nLoopIds + loop.length);
      this.loopIds.set(loop, this.nLoopIds);
      this.loopStarts = grown(this.loopStarts, this.nf + 2);
      this.loopStarts[this.nf] = this.nLoopIds;
      this.nLoopIds += loop.length;
      this.loopStarts[++this.nf] = this.nLoopIds;
    }
    this.count++;
  }

  /** The events pushed since the last take() as a batch of fresh arrays (the writer is emptied). */
  take() {
    const batch = {
      count: this.count,
      kinds: this.kinds.slice(0, this.count),
      ids: this.ids.slice(0, this.count),
      positions: this.positions.slice(0, 3 * this.nv),
      ends: this.ends.slice(0, 2 * this.ne),
      loopStarts: this.loopStarts.slice(0, this.nf + 1),
      loopIds: this.loopIds.slice(0, this.nLoopIds),
    };
    this.clear();
    return batch;
  }
}

/** The buffers of a batch, for a postMessage transfer list. */
export function batchBuffers(batch) {
  return [batch.kinds, batch.ids, batch.positions, batch.ends, batch.loopStarts, batch.loopIds].map((a) => a.buffer);
}

/**
 * Calls `visit(event)` with each event of a batch, in order, as the objects computeKernel's onStep
 * receives ({ type: 'vertex', id, position }, { type: 'edge', id, a, b }, { type: 'face', id,
 * loop }). Stops at the first event for which `visit` returns false, and then returns false;
 * true when every event was visited.
 */
export function forEachStep(batch, visit) {
  const { kinds, ids, positions, ends, loopStarts, loopIds } = batch;
  let v = 0,
    e = 0,
    f = 0;
  for (let i = 0; i < kinds.length; i++) {
    let event;
    if (kinds[i] === VERTEX) {
      event = { type: 'vertex', id: ids[i], position: [positions[v], positions[v + 1], positions[v + 2]] };
      v += 3;
    } else if (kinds[i] === EDGE) {
      event = { type: 'edge', id: ids[i], a: ends[e], b: ends[e + 1] };
      e += 2;
    } else {
      const start = loopStarts[f],
        end = loopStarts[++f];
      const loop = new Array(end - start);
      for (let k = start; k < end; k++) loop[k - start] = loopIds[k];
      event = { type: 'face', id: ids[i], loop };
    }
    if (visit(event) === false) return false;
  }
  return true;
}
