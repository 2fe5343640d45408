"""flowform_tools.h5io: a solution.h5 in flowform's layout (written here with h5py) read back:
the mesh, nodal and cell fields, and the position-keyed nodal map."""
import os
import tempfile
import unittest

import h5py
import numpy as np

from flowform_tools import h5io

# The unit square as two triangles; nodes 0..3 counter-clockwise from the origin.
COORDINATES = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]]
TOPOLOGY = [[0, 1, 2], [0, 2, 3]]
VELOCITY = [[1.0, 2.0, 0.0], [3.0, 4.0, 0.0], [5.0, 6.0, 0.0], [7.0, 8.0, 0.0]]
PRESSURE = [0.5, -0.5, 1.5, 2.5]
STRAIN_RATE = [0.25, 0.75]


class SolutionFile(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        with h5py.File(h5io.path(self.dir), "w") as f:
            f["mesh/coordinates"] = np.array(COORDINATES)
            f["mesh/topology"] = np.array(TOPOLOGY, dtype=np.int32)
            f["fields/velocity"] = np.array(VELOCITY)
            f["fields/pressure"] = np.array(PRESSURE)
            f["fields/strain_rate"] = np.array(STRAIN_RATE)

    def tearDown(self):
        self.tmp.cleanup()

    def test_path(self):
        self.assertEqual(h5io.path("out"), os.path.join("out", "solution.h5"))

    def test_mesh(self):
        s = h5io.read(self.dir)
        self.assertEqual(s.xy.tolist(), [c[:2] for c in COORDINATES])
        self.assertEqual(s.topology.tolist(), TOPOLOGY)
        self.assertEqual(s.topology.dtype, np.int64)  # indices usable as numpy indices anywhere
        self.assertEqual(s.nodes_per_cell, 3)

    def test_fields_all_or_named(self):
        s = h5io.read(self.dir)
        self.assertEqual(sorted(s.fields), ["pressure", "strain_rate", "velocity"])
        self.assertEqual(s.fields["velocity"].tolist(), VELOCITY)
        only = h5io.read(self.dir, ["strain_rate"])
        self.assertEqual(list(only.fields), ["strain_rate"])
        self.assertEqual(only.fields["strain_rate"].tolist(), STRAIN_RATE)
        with self.assertRaises(KeyError):
            h5io.read(self.dir, ["temperature"])

    def test_field_names(self):
        self.assertEqual(sorted(h5io.field_names(self.dir)), ["pressure", "strain_rate", "velocity"])

    def test_nodal_map_by_position(self):
        v = h5io.nodal_map(self.dir, "velocity")
        self.assertEqual(v[(1.0, 1.0)], (5.0, 6.0))
        self.assertEqual(v[(0.0, 1.0)], (7.0, 8.0))
        self.assertEqual(len(v), 4)
        p = h5io.nodal_map(self.dir, "pressure", components=1)
        self.assertEqual(p[(1.0, 0.0)], (-0.5,))

    def test_missing_file(self):
        with self.assertRaises(OSError):
            h5io.read(os.path.join(self.dir, "nothing"))


if __name__ == "__main__":
    unittest.main()
