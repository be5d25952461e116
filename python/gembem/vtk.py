"""The VTK XML files gembem writes (ASCII .vtu/.vtp, .pvd collections) as numpy arrays.

gembem writes every VTK file in ASCII (`format="ascii"`), so the standard library's XML parser
is enough: no VTK or ParaView is needed to read a host field or a snapshot from Python.
"""
import os
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

import numpy as np

_TYPES = {"Float64": np.float64, "Float32": np.float32, "Int64": np.int64, "Int32": np.int32,
          "UInt8": np.uint8, "Int8": np.int8, "UInt32": np.uint32, "UInt64": np.uint64}


@dataclass
class Mesh:
    """One piece of a .vtu/.vtp file: points (n x 3), the cells' connectivity and offsets (VTK's
    own layout: cell k is connectivity[offsets[k-1]:offsets[k]]), and the data arrays by name
    (vectors and tensors as n x components)."""
    path: str
    points: np.ndarray
    connectivity: np.ndarray
    offsets: np.ndarray
    point_data: dict = field(default_factory=dict)
    cell_data: dict = field(default_factory=dict)

    def __repr__(self):
        def arrays(data):
            return ", ".join(f"{k} {'x'.join(map(str, v.shape))}" for k, v in data.items()) or "none"
        return (f"Mesh({self.path!r}: {len(self.points)} points, {len(self.offsets)} cells; "
                f"point data: {arrays(self.point_data)}; cell data: {arrays(self.cell_data)})")

    def cells(self):
        """The cells as a list of point-index arrays."""
        starts = np.concatenate([[0], self.offsets[:-1]])
        return [self.connectivity[a:b] for a, b in zip(starts, self.offsets)]

    def triangles(self):
        """The cells as an m x 3 array of point indices, polygons (the host field's quadrilaterals)
        fanned into triangles from their first point: what matplotlib's tri* functions draw.
        A cell's triangles are consecutive, in cell order: cell data goes with
        ``np.repeat(values, sizes - 2)`` (sizes: points per cell)."""
        starts = np.concatenate([[0], self.offsets[:-1]]).astype(np.int64)
        sizes = self.offsets - starts
        if np.any(sizes < 3):
            raise ValueError(f"{self.path}: cells of fewer than 3 points (lines or vertices) have no triangles")
        tris = [np.stack([self.connectivity[starts[sizes > k]],
                          self.connectivity[starts[sizes > k] + k - 1],
                          self.connectivity[starts[sizes > k] + k]], axis=1)
                for k in range(2, int(sizes.max(initial=2)))]
        if not tris:
            return np.empty((0, 3), dtype=np.int64)
        cell = np.concatenate([np.nonzero(sizes > k)[0] for k in range(2, int(sizes.max()))])
        return np.concatenate(tris)[np.argsort(cell, kind="stable")]


def _array(node, path):
    if node.get("format", "ascii") != "ascii":
        raise ValueError(f"{path}: DataArray '{node.get('Name')}' is {node.get('format')}, expected ascii")
    kind = node.get("type")
    if kind not in _TYPES:
        raise ValueError(f"{path}: DataArray '{node.get('Name')}' of type {kind}, expected one of {', '.join(_TYPES)}")
    values = np.array((node.text or "").split(), dtype=_TYPES[kind])
    ncomp = int(node.get("NumberOfComponents", "1"))
    return values.reshape(-1, ncomp) if ncomp > 1 else values


def _arrays(parent, path):
    return {} if parent is None else {a.get("Name"): _array(a, path) for a in parent.findall("DataArray")}


def read_vtk(path):
    """Reads an ASCII .vtu (UnstructuredGrid) or .vtp (PolyData) file written by gembem."""
    path = os.fspath(path)
    root = ET.parse(path).getroot()
    piece = root.find("./*/Piece")
    if piece is None:
        raise ValueError(f"{path}: no <Piece>, expected a VTK UnstructuredGrid or PolyData file")
    points = _array(piece.find("Points/DataArray"), path)
    # Cells (.vtu), Lines or Verts (.vtp): gembem writes one kind of cell per file.
    for tag in ("Cells", "Lines", "Polys", "Verts"):
        cells = piece.find(tag)
        if cells is not None:
            arrays = _arrays(cells, path)
            conn, offs = arrays["connectivity"], arrays["offsets"]
            break
    else:
        conn = offs = np.empty(0, dtype=np.int64)
    return Mesh(path, points, conn, offs, _arrays(piece.find("PointData"), path), _arrays(piece.find("CellData"), path))


def read_pvd(path):
    """A .pvd collection as a list of (timestep, absolute file path), in the file's order."""
    path = os.fspath(path)
    base = os.path.dirname(os.path.abspath(path))
    root = ET.parse(path).getroot()
    return [(float(d.get("timestep")), os.path.join(base, d.get("file"))) for d in root.iter("DataSet")]
