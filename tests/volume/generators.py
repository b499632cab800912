"""Volume meshes from real generators, for tests/volume/generated_meshes_test.py and
bench/volume_bench.sh: Voronoi cells (voro++), tetgen tetrahedra agglomerated into polyhedra, and a
cube grid agglomerated into L and U shapes (whose kernels are known in closed form).

Each generator returns (points, cells, extra): points a list of (x, y, z); cells a list of cells,
each a list of faces (vertex id lists into points), faces outward as the generator knows them;
extra per-cell facts (the grid's analytic kernels)."""
import os
import random
import subprocess


def voronoi(tmp, n, seed=1):
    """voro++'s Voronoi cells of n random points in the unit cube (convex cells). voro++ prints
    coordinates with 6 significant digits, so a face of more than 3 corners is planar only to that
    precision."""
    rng = random.Random(seed)
    path = os.path.join(tmp, "voro_points")
    with open(path, "w") as f:
        for i in range(n):
            f.write("%d %.17g %.17g %.17g\n" % (i, rng.random(), rng.random(), rng.random()))
    subprocess.run(["voro++", "-c", "%i|%P|%t", "0", "1", "0", "1", "0", "1", path], check=True)
    ids, points, cells = {}, [], []
    with open(path + ".vol") as f:
        for line in f:
            _, verts, faces = line.strip().split("|")
            local = []
            for v in verts.split(" "):
                key = tuple(float(c) for c in v.strip("()").split(","))
                if key not in ids:
                    ids[key] = len(points)
                    points.append(key)
                local.append(ids[key])
            cell = []
            for face in faces.split(" "):
                cell.append([local[int(k)] for k in face.strip("()").split(",")])
            cells.append(cell)
    return points, cells, None


def _orient3d(a, b, c, d):
    ax, ay, az = (b[i] - a[i] for i in range(3))
    bx, by, bz = (c[i] - a[i] for i in range(3))
    cx, cy, cz = (d[i] - a[i] for i in range(3))
    return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)


def tetgen_agglomerated(tmp, n_points, seed=2, sizes=(2, 12)):
    """tetgen's Delaunay tetrahedralization of random points, its tetrahedra grown into groups of
    `sizes` tetrahedra across shared faces (breadth-first from random seeds): non-convex cells, many
    not star-shaped. A cell's faces are the triangles of its tetrahedra that no other tetrahedron
    of the cell shares, outward as each tetrahedron's orientation says."""
    rng = random.Random(seed)
    node = os.path.join(tmp, "tet.node")
    with open(node, "w") as f:
        f.write("%d 3 0 0\n" % n_points)
        for i in range(n_points):
            f.write("%d %.17g %.17g %.17g\n" % (i, rng.random(), rng.random(), rng.random()))
    subprocess.run(["tetgen", "-Q", node], check=True)
    points = []
    with open(os.path.join(tmp, "tet.1.node")) as f:
        lines = [l.split() for l in f if l.strip() and not l.startswith("#")]
        for parts in lines[1:]:
            points.append(tuple(float(c) for c in parts[1:4]))
    tets = []
    with open(os.path.join(tmp, "tet.1.ele")) as f:
        lines = [l.split() for l in f if l.strip() and not l.startswith("#")]
        for parts in lines[1:]:
            t = [int(v) for v in parts[1:5]]
            if _orient3d(*(points[v] for v in t)) < 0:
                t[0], t[1] = t[1], t[0]
            tets.append(t)
    # Faces of a positively oriented tet (a, b, c, d), outward.
    def tet_faces(t):
        a, b, c, d = t
        return [(a, c, b), (a, b, d), (b, c, d), (a, d, c)]

    by_face = {}
    for i, t in enumerate(tets):
        for f in tet_faces(t):
            by_face.setdefault(tuple(sorted(f)), []).append(i)
    group = [-1] * len(tets)
    order = list(range(len(tets)))
    rng.shuffle(order)
    cells = []
    for seed_tet in order:
        if group[seed_tet] >= 0:
            continue
        target = rng.randint(*sizes)
        members, queue = [seed_tet], [seed_tet]
        group[seed_tet] = len(cells)
        while queue and len(members) < target:
            t = queue.pop(rng.randrange(len(queue)))
            for f in tet_faces(tets[t]):
                for o in by_face[tuple(sorted(f))]:
                    if group[o] < 0 and len(members) < target:
                        group[o] = len(cells)
                        members.append(o)
                        queue.append(o)
        inside = set(members)
        cell = []
        for t in members:
            for f in tet_faces(tets[t]):
                if sum(1 for o in by_face[tuple(sorted(f))] if o in inside) == 1:
                    cell.append(list(f))
        cells.append(cell)
    return points, cells, None


def grid_lu(nx, ny, nz):
    """A grid of unit cubes (nx by ny by nz blocks of 3 x 2 x 1 cubes), each block split into two
    cells: an L tromino and its 180-degree turn (kernel: the corner cube, volume 1 of 3), or a U
    pentomino (not star-shaped: its two arms' inner walls face each other) and the cube between
    its arms. Faces are the unit squares on each cell's boundary, outward."""
    ids, points = {}, []

    def pid(p):
        if p not in ids:
            ids[p] = len(points)
            points.append(p)
        return ids[p]

    # Outward unit squares of the cube at (x, y, z): (axis, side) -> corner loop.
    def cube_faces(x, y, z):
        c = lambda dx, dy, dz: pid((float(x + dx), float(y + dy), float(z + dz)))
        return {
            (0, 0): [c(0, 0, 0), c(0, 0, 1), c(0, 1, 1), c(0, 1, 0)],
            (0, 1): [c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1)],
            (1, 0): [c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)],
            (1, 1): [c(0, 1, 0), c(0, 1, 1), c(1, 1, 1), c(1, 1, 0)],
            (2, 0): [c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)],
            (2, 1): [c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)],
        }

    def cell_of(cubes):
        faces, keys = [], []
        members = set(cubes)
        for (x, y, z) in cubes:
            for (axis, side), loop in cube_faces(x, y, z).items():
                nb = [x, y, z]
                nb[axis] += 1 if side else -1
                if tuple(nb) not in members:
                    faces.append(loop)
                    keys.append(((x, y, z), axis, side))
        return faces, keys

    cells, extra = [], []
    for bz in range(nz):
        for by in range(ny):
            for bx in range(nx):
                x0, y0, z = 3 * bx, 2 * by, bz
                if (bx + by + bz) % 2 == 0:
                    l1 = [(x0, y0, z), (x0 + 1, y0, z), (x0, y0 + 1, z)]
                    l2 = [(x0 + 2, y0 + 1, z), (x0 + 1, y0 + 1, z), (x0 + 2, y0, z)]
                    for cubes in (l1, l2):
                        faces, _ = cell_of(cubes)
                        cells.append(faces)
                        extra.append({"shape": "L", "kernel_volume": 1.0, "cell_volume": 3.0, "diameter": 3.0})
                else:
                    u = [(x0, y0, z), (x0 + 1, y0, z), (x0 + 2, y0, z), (x0, y0 + 1, z), (x0 + 2, y0 + 1, z)]
                    faces, keys = cell_of(u)
                    # The witness: the left arm's inner wall (x = x0 + 1, facing +x) and the right
                    # arm's (x = x0 + 2, facing -x).
                    walls = [keys.index(((x0, y0 + 1, z), 0, 1)), keys.index(((x0 + 2, y0 + 1, z), 0, 0))]
                    cells.append(faces)
                    extra.append({"shape": "U", "status": "EMPTY", "walls": sorted(walls)})
                    faces, _ = cell_of([(x0 + 1, y0 + 1, z)])
                    cells.append(faces)
                    extra.append({"shape": "cube", "kernel_volume": 1.0, "cell_volume": 1.0, "diameter": 3 ** 0.5})
    return points, cells, extra


def write_vtu(path, points, cells):
    """The mesh as VTU polyhedra, written by meshio (an independent writer)."""
    import meshio
    import numpy as np

    mesh = meshio.Mesh(np.array(points, dtype=float), [("polyhedron", [[np.array(f) for f in c] for c in cells])])
    mesh.write(path, binary=True, compression=None)


def write_node_ele(stem, points, cells):
    """The face-based .node/.ele pair (ids from 0), written here."""
    with open(stem + ".node", "w") as f:
        f.write("# vertices\n%d 3 0 0\n" % len(points))
        for i, p in enumerate(points):
            f.write("%d %.17g %.17g %.17g\n" % (i, *p))
    with open(stem + ".ele", "w") as f:
        f.write("%d 0\n" % len(cells))
        face_id = 0
        for c, cell in enumerate(cells):
            f.write("%d %d\n" % (c, len(cell)))
            for face in cell:
                f.write("%d %d %s\n" % (face_id, len(face), " ".join(map(str, face))))
                face_id += 1


def _six_volume(points, cell):
    o = points[cell[0][0]]
    total = 0.0
    for face in cell:
        for k in range(1, len(face) - 1):
            total += _orient3d(o, points[face[0]], points[face[k]], points[face[k + 1]])
    return total


def write_cell_off(path, points, cell, numbering="first_use", outward=False):
    """One cell alone as an OFF surface, its faces in the cell's order. numbering "first_use":
    vertices in order of first use; "sorted": in increasing id (as kergen's cell_surface numbers
    them). outward: every loop reversed when the cell's signed volume is negative."""
    if numbering == "sorted":
        order = sorted({v for face in cell for v in face})
    else:
        order = list(dict.fromkeys(v for face in cell for v in face))
    local = {v: i for i, v in enumerate(order)}
    if outward and _six_volume(points, cell) < 0:
        cell = [face[::-1] for face in cell]
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(order), len(cell)))
        for v in order:
            f.write("%.17g %.17g %.17g\n" % points[v])
        for face in cell:
            f.write("%d %s\n" % (len(face), " ".join(str(local[v]) for v in face)))
