"""flowform_tools.msh on tests/data/unit_square_tri.msh (gmsh 4.1: corners 1-4, midsides 5-8,
centre 9; curve groups bottom, right, top, left with two segments each)."""
import os
import unittest

from flowform_tools import msh

MESH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data", "unit_square_tri.msh")


class GmshText(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(MESH) as f:
            cls.text = f.read()

    def test_node_coordinates(self):
        xy = msh.node_coordinates(self.text)
        self.assertEqual(len(xy), 10)
        self.assertEqual(xy[2], (1.0, 0.0))
        self.assertEqual(xy[9], (0.5, 0.5))
        self.assertEqual(xy[10], (2.0, 2.0))  # the unused point is a node all the same

    def test_group_nodes(self):
        self.assertEqual(msh.group_nodes(self.text, "bottom"), {1, 2, 5})
        self.assertEqual(msh.group_nodes(self.text, "right"), {2, 3, 6})
        self.assertEqual(msh.group_nodes(self.text, "body"), set())  # a 2-D group has no line elements

    def test_shared_point(self):
        self.assertEqual(msh.shared_point(self.text, "bottom", "right"), (1.0, 0.0))
        self.assertEqual(msh.shared_point(self.text, "left", "bottom"), (0.0, 0.0))
        with self.assertRaises(RuntimeError):
            msh.shared_point(self.text, "bottom", "top")

    def test_without_corner_segment(self):
        out = msh.without_corner_segment(self.text, "bottom", (1.0, 0.0))
        self.assertEqual(msh.group_nodes(out, "bottom"), {1, 5})
        self.assertEqual(msh.group_nodes(out, "right"), {2, 3, 6})
        # one element fewer in the $Elements header (blocks, elements, min tag, max tag)
        before = self.text.splitlines()[self.text.splitlines().index("$Elements") + 1].split()
        after = out.splitlines()[out.splitlines().index("$Elements") + 1].split()
        self.assertEqual(int(after[1]), int(before[1]) - 1)
        self.assertEqual(after[0], before[0])
        # the rest of the mesh is the same: nodes and the other sections
        self.assertEqual(msh.node_coordinates(out), msh.node_coordinates(self.text))
        self.assertEqual(len(out.splitlines()), len(self.text.splitlines()) - 1)

    def test_without_corner_segment_refuses_a_point_off_the_group(self):
        with self.assertRaises(RuntimeError):
            msh.without_corner_segment(self.text, "bottom", (0.5, 0.5))  # a node, not on bottom
        with self.assertRaises(RuntimeError):
            msh.without_corner_segment(self.text, "bottom", (0.3, 0.0))  # no node there
        with self.assertRaises(RuntimeError):
            msh.without_corner_segment(self.text, "nonexistent", (1.0, 0.0))


if __name__ == "__main__":
    unittest.main()
