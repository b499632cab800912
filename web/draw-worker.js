// The demo's drawing worker: turns a parsed mesh into what the view draws (draw-prep.js), off
// the page's thread — for a million triangles that is a few hundred ms of work. It keeps the
// last mesh so the faces' edges can be asked for later (the edge toggle on a big mesh).
//
// main → worker: { type: 'prepare', id, mesh, edges, maxTriangles }  |  { type: 'edges', id }  |  { type: 'noop', id }
// worker → main: { id, drawing }                                      |  { id, edges }            |  { id }
import { prepareDrawing, drawingBuffers, faceEdges } from './draw-prep.js';

let last = null; // the mesh whose edges can still be asked for: the drawn one


self.onmessage = ({ data }) => {
  if (data.type === 'prepare') {
    const drawing = prepareDrawing(data.mesh, { edges: data.edges, maxTriangles: data.maxTriangles });
    last = drawing.simplified ? { positions: drawing.positions, indices: drawing.triangles, faceSizes: null } : data.mesh;
    // Keep what `last` refers to whole: send copies of the arrays shared with it.
    if (drawing.triangles === last.indices) drawing.triangles = last.indices.slice();
    if (drawing.positions === last.positions) drawing.positions = last.positions.slice();
    self.postMessage({ id: data.id, drawing }, drawingBuffers(drawing));
  } else if (data.type === 'noop') {
    self.postMessage({ id: data.id }); // started: nothing to do
  } else if (data.type === 'edges') {
    const edges = last ? faceEdges(last.indices, last.faceSizes, last.positions.length / 3) : new Uint32Array(0);
    self.postMessage({ id: data.id, edges }, [edges.buffer]);
  }
};
