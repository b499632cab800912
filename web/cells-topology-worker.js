// A module worker of the cells page: the topology of a volume mesh (cells-geometry.js's
// cellTopology: the cell across each face, the cells' centres), a loop over every face incidence
// that takes a second or more for 100k cells, so that it never blocks the page's thread.
// Message in: { id, mesh }; out: { id, topology } with its arrays transferred.
import { cellTopology } from './cells-geometry.js';

self.onmessage = (e) => {
  const { id, mesh } = e.data;
  const topology = cellTopology(mesh);
  self.postMessage({ id, topology }, [topology.cellOf.buffer, topology.other.buffer, topology.centres.buffer]);
};
