"""solution.h5 of a run (opened in ParaView through solution.xdmf; docs/theory.md §5).

Layout: /mesh/coordinates (nodes × 3), /mesh/topology (cells × 3 or 4, 0-based node
indices), /fields/<name>: nodal (velocity nodes × 3, pressure, contact status, du_d<h>,
dp_d<h>, ...) or cell values (strain_rate, viscosity, equivalent stress at the centroid).
Needs h5py and numpy.
"""
import os


def path(outdir):
    return os.path.join(outdir, "solution.h5")


class Solution:
    """The mesh and the fields of one solution.h5 (read at once)."""

    def __init__(self, outdir, fields=None):
        import h5py
        import numpy as np
        with h5py.File(path(outdir), "r") as f:
            self.coordinates = np.asarray(f["mesh/coordinates"])
            self.topology = np.asarray(f["mesh/topology"], dtype=np.int64)
            names = list(f["fields"]) if fields is None else fields
            self.fields = {name: np.asarray(f["fields/" + name]) for name in names}

    @property
    def xy(self):
        """Node coordinates in the plane (nodes × 2)."""
        return self.coordinates[:, :2]

    @property
    def nodes_per_cell(self):
        return self.topology.shape[1]


def read(outdir, fields=None):
    """A Solution with every field, or only the named ones."""
    return Solution(outdir, fields)


def field_names(outdir):
    """The names under /fields."""
    import h5py
    with h5py.File(path(outdir), "r") as f:
        return list(f["fields"])


def nodal_map(outdir, field, components=2):
    """(x, y) -> tuple of the field's first components at that node (to compare runs whose
    node numbering differs, e.g. serial vs parallel)."""
    s = read(outdir, [field])
    values = s.fields[field]
    if values.ndim == 1:
        values = values[:, None]
    return dict(zip((tuple(p) for p in s.xy), (tuple(v[:components]) for v in values)))
