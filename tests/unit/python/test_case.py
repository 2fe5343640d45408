"""flowform_tools.case: what scripts ask of a case XML (walls, responses, the tool, geometry),
typed values, and a variant written to a new file with an absolute mesh path."""
import os
import tempfile
import unittest
import xml.etree.ElementTree as ET

from flowform_tools import case

CASE = """<ParameterList name="flowform">
  <ParameterList name="Problem">
    <Parameter name="Geometry" type="string" value="Axisymmetric"/>
  </ParameterList>
  <ParameterList name="Mesh">
    <Parameter name="File" type="string" value="meshes/square.msh"/>
  </ParameterList>
  <ParameterList name="Boundary Conditions">
    <ParameterList name="ram">
      <Parameter name="Type" type="string" value="Velocity"/>
      <Parameter name="Velocity X" type="double" value="1.0"/>
    </ParameterList>
    <ParameterList name="container">
      <Parameter name="Type" type="string" value="Contact Wall"/>
    </ParameterList>
    <ParameterList name="die">
      <Parameter name="Type" type="string" value="Contact Wall"/>
    </ParameterList>
    <ParameterList name="inlet">
      <Parameter name="Type" type="string" value="Traction"/>
      <Parameter name="Traction X" type="double" value="-2.0"/>
      <Parameter name="Traction Y" type="double" value="0.0"/>
    </ParameterList>
    <ParameterList name="outlet">
      <Parameter name="Type" type="string" value="Traction"/>
      <Parameter name="Traction X" type="double" value="0.0"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Responses">
    <ParameterList name="ram_pressure">
      <Parameter name="Type" type="string" value="Mean Pressure"/>
      <Parameter name="Boundary" type="string" value="ram"/>
    </ParameterList>
    <ParameterList name="ram_force">
      <Parameter name="Type" type="string" value="Boundary Force"/>
      <Parameter name="Boundary" type="string" value="ram"/>
    </ParameterList>
    <ParameterList name="die_force">
      <Parameter name="Type" type="string" value="Boundary Force"/>
      <Parameter name="Boundary" type="string" value="die"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Maximum Iterations" type="int" value="25"/>
    <Parameter name="Verbose" type="bool" value="TRUE"/>
    <Parameter name="Quiet" type="bool" value="false"/>
    <Parameter name="Tolerance" type="double" value="not a number"/>
    <Parameter name="Name" type="string" value="Klu2"/>
  </ParameterList>
</ParameterList>
"""


class CaseFile(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.path = os.path.join(self.tmp.name, "scene.xml")
        with open(self.path, "w") as f:
            f.write(CASE)
        self.case = case.Case(self.path)

    def tearDown(self):
        self.tmp.cleanup()

    def test_groups_in_file_order(self):
        self.assertEqual(self.case.groups(), ["ram", "container", "die", "inlet", "outlet"])
        self.assertEqual(self.case.contact_walls(), ["container", "die"])
        self.assertEqual(self.case.groups("Traction"), ["inlet", "outlet"])
        self.assertEqual(self.case.groups("Symmetry"), [])

    def test_loaded_groups_are_the_nonzero_tractions(self):
        self.assertEqual(self.case.loaded_groups(), ["inlet"])

    def test_responses_and_the_tool(self):
        self.assertEqual(list(self.case.responses()), ["ram_pressure", "ram_force", "die_force"])
        self.assertEqual(self.case.tool_force(), "ram_force")  # the first Boundary Force
        self.assertEqual(self.case.tool_boundary(), "ram")
        self.assertEqual(self.case.response("Boundary Force", boundary="die"), "die_force")
        self.assertEqual(self.case.response("Mean Pressure", boundary="ram"), "ram_pressure")
        with self.assertRaises(KeyError):
            self.case.response("Mean Pressure", boundary="die")
        self.assertIsNone(self.case.response("Dead Zone", required=False))

    def test_values_typed_as_declared(self):
        solver = self.case.sublist("Solver")
        self.assertEqual(solver["Maximum Iterations"], 25)
        self.assertIsInstance(solver["Maximum Iterations"], int)
        self.assertIs(solver["Verbose"], True)
        self.assertIs(solver["Quiet"], False)
        self.assertEqual(solver["Tolerance"], "not a number")  # unparsable: kept as the text
        self.assertEqual(self.case.group("ram")["Velocity X"], 1.0)
        self.assertEqual(self.case.sublist("No", "Such", "List"), {})

    def test_geometry(self):
        self.assertEqual(self.case.geometry, "Axisymmetric")
        self.assertTrue(self.case.axisymmetric)
        plane = case.Scene({"Problem": {}})
        self.assertEqual(plane.geometry, "Plane Strain")
        self.assertFalse(plane.axisymmetric)

    def test_mesh_file_relative_to_the_case(self):
        self.assertEqual(self.case.mesh_file(), os.path.join(self.tmp.name, "meshes", "square.msh"))

    def test_variant(self):
        other = os.path.join(self.tmp.name, "elsewhere")
        os.mkdir(other)
        out = os.path.join(other, "variant.xml")

        def edit(root):
            case.set_group(root, "die", [("Type", "string", "Velocity"), ("Velocity X", "double", "0.0")])
            case.param(case.sublist(root, "Solver"), "Maximum Iterations").set("value", "40")

        self.assertEqual(self.case.variant(out, edit), out)
        v = case.Case(out)
        self.assertEqual(v.contact_walls(), ["container"])
        self.assertEqual(v.group("die"), {"Type": "Velocity", "Velocity X": 0.0})
        self.assertEqual(v.sublist("Solver")["Maximum Iterations"], 40)
        # the mesh is the original's, now absolute, so the copy may live anywhere
        self.assertEqual(v.sublist("Mesh")["File"], self.case.mesh_file())
        self.assertEqual(v.mesh_file(), self.case.mesh_file())
        # the case itself is unchanged
        self.assertEqual(case.Case(self.path).contact_walls(), ["container", "die"])
        with open(self.path) as f:
            self.assertEqual(f.read(), CASE)

    def test_editing_helpers_name_what_is_missing(self):
        root = ET.fromstring(CASE)
        with self.assertRaises(KeyError):
            case.sublist(root, "Adaptivity")
        with self.assertRaises(KeyError):
            case.param(case.sublist(root, "Solver"), "Maximum Steps")


class FromSummary(unittest.TestCase):
    def test_same_questions_about_a_run(self):
        params = {"Boundary Conditions": {"wall": {"Type": "Contact Wall"}, "Note": "not a group"},
                  "Responses": {"F": {"Type": "Boundary Force", "Boundary": "tool"}}}
        scene = case.Scene.from_summary({"parameters": params})
        self.assertEqual(scene.contact_walls(), ["wall"])
        self.assertEqual(scene.tool_boundary(), "tool")
        self.assertEqual(case.Scene.from_summary({}).groups(), [])


if __name__ == "__main__":
    unittest.main()
