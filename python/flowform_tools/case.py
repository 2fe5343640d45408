"""What a script needs to know about a scene, read from its case XML (or from the "parameters"
of a run's summary.json), so that no script hard-codes group or response names.

    scene = case.Case("xml/extrusion.xml")
    scene.contact_walls()            # ['container', 'die_face', 'die_land'] (in file order)
    scene.tool_force()               # 'ram_force': the first Boundary Force response
    scene.tool_boundary()            # 'ram': the boundary that force is measured on
    scene.response("Mean Pressure", boundary="ram")   # 'ram_pressure'
    scene.groups("Traction")         # ['outlet']
    case.Case("xml/channel.xml").loaded_groups()      # ['inlet']: a non-zero traction
    scene.axisymmetric               # False

    scene = case.Scene.from_summary(run.summary)      # the same questions about a finished run

Case also edits: Case.variant(path, edit) writes a copy of the XML changed by edit(root), with
Mesh/File made absolute so that the copy may live anywhere.

Values are typed as the XML declares them (double -> float, int -> int, bool -> bool, other
types as the text). A summary's parameters are sorted by name, a case file's are in file
order: where order matters (walls in flow order) use the case file, or order by geometry.
"""
import os
import xml.etree.ElementTree as ET

# The case's own mesh, solved once: the extrusion scenes adapt their mesh by default (their
# Adaptivity sublist); scripts that measure or reproduce numbers on a given mesh add this.
FIXED_MESH = ["Adaptivity/Enabled=false"]


def _value(elem):
    kind, text = elem.get("type", "string"), elem.get("value", "")
    try:
        if kind == "double":
            return float(text)
        if kind == "int":
            return int(text)
        if kind == "bool":
            return text.strip().lower() in ("true", "1", "yes")
    except ValueError:
        pass
    return text


def _to_dict(elem):
    out = {}
    for e in elem:
        if e.tag == "ParameterList":
            out[e.get("name")] = _to_dict(e)
        elif e.tag == "Parameter":
            out[e.get("name")] = _value(e)
    return out


class Scene:
    """Questions about a parameter list held as nested dicts."""

    def __init__(self, params):
        self.params = params

    @classmethod
    def from_summary(cls, summary):
        return cls(summary.get("parameters") or {})

    def sublist(self, *names):
        node = self.params
        for n in names:
            node = (node or {}).get(n) or {}
        return node

    # --- boundary conditions ------------------------------------------------------------------

    def groups(self, kind=None):
        """Names of the Boundary Conditions groups, those of Type == kind if given."""
        bc = self.sublist("Boundary Conditions")
        return [g for g, entries in bc.items() if isinstance(entries, dict)
                and (kind is None or entries.get("Type") == kind)]

    def contact_walls(self):
        """The Contact Wall groups."""
        return self.groups("Contact Wall")

    def group(self, name):
        return self.sublist("Boundary Conditions", name)

    def loaded_groups(self):
        """The groups with a non-zero prescribed traction component (e.g. the channel's inlet,
        where the driving pressure acts)."""
        return [g for g in self.groups()
                if any(isinstance(self.group(g).get(k), float) and self.group(g)[k] != 0.0
                       for k in ("Traction X", "Traction Y"))]

    # --- responses -----------------------------------------------------------------------------

    def responses(self):
        """Response name -> its entries (Type, Boundary, ...), in list order."""
        return {k: v for k, v in self.sublist("Responses").items() if isinstance(v, dict)}

    def response(self, kind, boundary=None, required=True):
        """The first response of Type kind (on that Boundary if given)."""
        for name, entries in self.responses().items():
            if entries.get("Type") == kind and (boundary is None or entries.get("Boundary") == boundary):
                return name
        if required:
            where = f" on '{boundary}'" if boundary else ""
            raise KeyError(f"the case has no '{kind}' response{where}")
        return None

    def tool_force(self):
        """The first Boundary Force response (the tool's reaction, e.g. the ram force)."""
        return self.response("Boundary Force")

    def tool_boundary(self):
        """The boundary group of tool_force() (e.g. the ram)."""
        return self.responses()[self.tool_force()]["Boundary"]

    # --- problem -------------------------------------------------------------------------------

    @property
    def geometry(self):
        return self.sublist("Problem").get("Geometry", "Plane Strain")

    @property
    def axisymmetric(self):
        return self.geometry == "Axisymmetric"


class Case(Scene):
    """A case XML file: a Scene plus the element tree, for writing variants."""

    def __init__(self, path):
        self.path = os.path.abspath(path)
        self.tree = ET.parse(self.path)
        super().__init__(_to_dict(self.tree.getroot()))

    @property
    def directory(self):
        return os.path.dirname(self.path)

    def mesh_file(self):
        """Mesh/File as an absolute path (relative ones are relative to the case file)."""
        return os.path.normpath(os.path.join(self.directory, self.sublist("Mesh")["File"]))

    def variant(self, path, edit):
        """Writes the case edited by edit(root) (an ElementTree root) to path; Mesh/File is made
        absolute first. Returns path. The case itself is not changed."""
        tree = ET.parse(self.path)
        root = tree.getroot()
        param(sublist(root, "Mesh"), "File").set("value", self.mesh_file())
        edit(root)
        tree.write(path, encoding="utf-8", xml_declaration=True)
        return path


# --- editing an element tree (for Case.variant) ---------------------------------------------------


def sublist(elem, name):
    """The ParameterList child called name."""
    for e in elem:
        if e.tag == "ParameterList" and e.get("name") == name:
            return e
    raise KeyError(name)


def param(elem, name):
    """The Parameter child called name."""
    for e in elem:
        if e.tag == "Parameter" and e.get("name") == name:
            return e
    raise KeyError(name)


def set_group(root, group, entries):
    """Replaces Boundary Conditions/<group> by the given (name, type, value) entries."""
    g = sublist(sublist(root, "Boundary Conditions"), group)
    for e in list(g):
        g.remove(e)
    for name, typ, value in entries:
        ET.SubElement(g, "Parameter", name=name, type=typ, value=value)
