// The demo's drawing worker: turns a parsed mesh into what the view draws (draw-prep.js), off
// the page's thread — for a million triangles that is a few hundred ms of work. It keeps the
// last mesh so that what depends on it can be asked for later: the faces' edges (the edge toggle
// on a big mesh), the open edges (an OPEN_MESH error) and some faces by input index (the faces
// that show a mesh is not star-shaped).
//
// main → worker: { type: 'prepare', id, mesh, edges, maxTriangles } | { type: 'edges', id } |
//                { type: 'open-edges', id } | { type: 'faces', id, faces } | { type: 'noop', id } |
//                { type: 'simplify', id, vertices, triangles, center, maxTriangles }
// worker → main: { id, drawing } | { id, edges } | { id, count, lines } | { id, triangles, lines, centers } | { id }
//                | { id, positions, triangles }   (simplify: a big kernel's display copy)
import {
  prepareDrawing,
  drawingBuffers,
  faceEdges,
  openEdgeLines,
  faceHighlight,
  simplifySurface,
} from './draw-prep.js';

let drawn = null; // the mesh whose edges can still be asked for: the drawn one (maybe simplified)
let input = null; // the input as parsed (open edges and faces are the input's, never a simplified copy's)
let center = [0, 0, 0];

self.onmessage = ({ data }) => {
  if (data.type === 'prepare') {
    const drawing = prepareDrawing(data.mesh, { edges: data.edges, maxTriangles: data.maxTriangles });
    input = data.mesh;
    center = drawing.center;
    drawn = drawing.simplified
      ? { positions: drawing.positions, indices: drawing.triangles, faceSizes: null }
      : data.mesh;
    // Keep what `drawn` refers to whole: send copies of the arrays shared with it.
    if (drawing.triangles === drawn.indices) drawing.triangles = drawn.indices.slice();
    if (drawing.positions === drawn.positions) drawing.positions = drawn.positions.slice();
    self.postMessage({ id: data.id, drawing }, drawingBuffers(drawing));
  } else if (data.type === 'simplify') {
    // A kernel is a convex polytope, drawn facet by facet (flat): its copy needs no normals.
    const { positions, triangles } = simplifySurface(data.vertices, data.triangles, data.center, data.maxTriangles);
    self.postMessage({ id: data.id, positions, triangles }, [positions.buffer, triangles.buffer]);
  } else if (data.type === 'noop') {
    self.postMessage({ id: data.id }); // started: nothing to do
  } else if (data.type === 'edges') {
    const edges = drawn ? faceEdges(drawn.indices, drawn.faceSizes, drawn.positions.length / 3) : new Uint32Array(0);
    self.postMessage({ id: data.id, edges }, [edges.buffer]);
  } else if (data.type === 'open-edges') {
    const open = input ? openEdgeLines(input, center) : { count: 0, lines: new Float32Array(0) };
    self.postMessage({ id: data.id, ...open }, [open.lines.buffer]);
  } else if (data.type === 'faces') {
    const none = { triangles: new Float32Array(0), lines: new Float32Array(0), centers: new Float32Array(0) };
    const faces = input ? faceHighlight(input, data.faces, center) : none;
    self.postMessage({ id: data.id, ...faces }, [faces.triangles.buffer, faces.lines.buffer, faces.centers.buffer]);
  }
};
