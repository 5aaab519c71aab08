"""Regions of space cut out by a triangle surface, found independently of the library: a grid of
points is flooded along grid edges that cross no triangle, and each flooded component is one
region, its volume the points' count times a grid cell's. Used to check the meshed regions'
volumes against the input."""
import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components


def read_triangles(path):
    """Vertices (n x 3) and triangles (m x 3) of an OFF or OBJ file (polygons fanned)."""
    vertices, triangles = [], []
    if path.endswith(".off"):
        with open(path) as f:
            tokens = " ".join(line.split("#")[0] for line in f).split()
        assert tokens[0].endswith("OFF")
        nv, nf = int(tokens[1]), int(tokens[2])
        p = 4
        vertices = np.array(tokens[p:p + 3 * nv], float).reshape(-1, 3)
        p += 3 * nv
        for _ in range(nf):
            n = int(tokens[p])
            face = [int(x) for x in tokens[p + 1:p + 1 + n]]
            triangles += [(face[0], face[k], face[k + 1]) for k in range(1, n - 1)]
            p += n + 1
        return vertices, np.array(triangles)
    with open(path) as f:
        lines = f.readlines()
    for line in lines:
        parts = line.split()
        if parts and parts[0] == "v":
            vertices.append([float(x) for x in parts[1:4]])
        elif parts and parts[0] == "f":
            face = [int(x.split("/")[0]) - 1 for x in parts[1:]]
            triangles += [(face[0], face[k], face[k + 1]) for k in range(1, len(face) - 1)]
    return np.array(vertices), np.array(triangles)


class VoxelRegions:
    """Flood fill of a grid of `n` points along the longest side over the surface's bounding box
    grown by two grid steps; the grid is offset by irrational fractions of a step so that no
    grid line runs through a vertex or along a face of axis-aligned models."""

    def __init__(self, vertices, triangles, n=120):
        lo, hi = vertices.min(0), vertices.max(0)
        self.h = (hi - lo).max() / n
        self.lo = lo - 2 * self.h + np.array([0.3183, 0.2718, 0.1414]) * self.h
        self.shape = tuple(int(np.ceil((hi[k] - self.lo[k]) / self.h)) + 3 for k in range(3))
        blocked = [np.zeros(self.shape, bool) for _ in range(3)]  # edge from point i to i + 1 along axis
        for tri in vertices[triangles]:
            for axis in range(3):
                self._block(tri, axis, blocked[axis])
        index = np.arange(np.prod(self.shape)).reshape(self.shape)
        rows, cols = [], []
        for axis in range(3):
            a = [slice(None)] * 3
            b = [slice(None)] * 3
            a[axis] = slice(0, -1)
            b[axis] = slice(1, None)
            free = ~blocked[axis][tuple(a)]
            rows.append(index[tuple(a)][free])
            cols.append(index[tuple(b)][free])
        rows, cols = np.concatenate(rows), np.concatenate(cols)
        graph = coo_matrix((np.ones(len(rows), np.int8), (rows, cols)), shape=(index.size, index.size))
        count, labels = connected_components(graph, directed=False)
        self.labels = labels.reshape(self.shape)
        self.outside = self.labels[0, 0, 0]
        self.counts = np.bincount(labels, minlength=count)

    def _block(self, tri, axis, blocked):
        """Marks the edges along `axis` that cross triangle `tri`."""
        u, v = (axis + 1) % 3, (axis + 2) % 3
        # Grid lines along `axis` through points with indices (j, k) on axes (u, v).
        jmin = int(np.ceil((tri[:, u].min() - self.lo[u]) / self.h))
        jmax = int(np.floor((tri[:, u].max() - self.lo[u]) / self.h))
        kmin = int(np.ceil((tri[:, v].min() - self.lo[v]) / self.h))
        kmax = int(np.floor((tri[:, v].max() - self.lo[v]) / self.h))
        if jmin > jmax or kmin > kmax:
            return
        j, k = np.meshgrid(np.arange(jmin, jmax + 1), np.arange(kmin, kmax + 1), indexing="ij")
        pu, pv = self.lo[u] + j * self.h, self.lo[v] + k * self.h
        a, b, c = tri
        det = (b[u] - a[u]) * (c[v] - a[v]) - (c[u] - a[u]) * (b[v] - a[v])
        if det == 0:
            return  # the triangle is edge-on to these lines
        s = ((pu - a[u]) * (c[v] - a[v]) - (c[u] - a[u]) * (pv - a[v])) / det
        t = ((b[u] - a[u]) * (pv - a[v]) - (pu - a[u]) * (b[v] - a[v])) / det
        inside = (s >= 0) & (t >= 0) & (s + t <= 1)
        if not inside.any():
            return
        height = a[axis] + s * (b[axis] - a[axis]) + t * (c[axis] - a[axis])
        i = np.floor((height - self.lo[axis]) / self.h).astype(int)
        ok = inside & (i >= 0) & (i < self.shape[axis] - 1)
        where = [None, None, None]
        where[axis], where[u], where[v] = i[ok], j[ok], k[ok]
        blocked[tuple(where)] = True

    def region_at(self, point):
        """The component of the grid point nearest to `point`."""
        ijk = np.clip(np.rint((np.asarray(point) - self.lo) / self.h).astype(int), 0, np.array(self.shape) - 1)
        return self.labels[tuple(ijk)]

    def volume(self, region):
        return self.counts[region] * self.h ** 3

    def bounded_regions(self):
        return [r for r in range(len(self.counts)) if r != self.outside]
