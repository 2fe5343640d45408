"""Small edits of gmsh 4 ASCII meshes (.msh, format 4.1), without the gmsh module.

Only what the checks need: the nodes of a physical curve group, and a copy of a mesh with
the line elements of one group at one node removed (a no-slip wall that must leave a corner
node to the neighbouring boundary: tests/regression/extrusion/limits.py).
"""
import math


def _section(lines, name):
    return lines.index("$" + name)


def _curve_entities(lines, group):
    """The physical tag of a 1-D group and the curve entities that carry it."""
    i = _section(lines, "PhysicalNames")
    tag = None
    for line in lines[i + 2:i + 2 + int(lines[i + 1])]:
        dim, ptag, name = line.split(maxsplit=2)
        if int(dim) == 1 and name.strip().strip('"') == group:
            tag = int(ptag)
    i = _section(lines, "Entities")
    npoints, ncurves = map(int, lines[i + 1].split()[:2])
    curves = set()
    for line in lines[i + 2 + npoints:i + 2 + npoints + ncurves]:
        v = line.split()
        if tag in map(int, v[8:8 + int(v[7])]):
            curves.add(int(v[0]))
    return tag, curves


def node_coordinates(text):
    """Node tag -> (x, y)."""
    lines = text.splitlines()
    i = _section(lines, "Nodes")
    j, coords = i + 2, {}
    for _ in range(int(lines[i + 1].split()[0])):
        n = int(lines[j].split()[3])
        for t, xyz in zip(lines[j + 1:j + 1 + n], lines[j + 1 + n:j + 1 + 2 * n]):
            x, y = map(float, xyz.split()[:2])
            coords[int(t)] = (x, y)
        j += 1 + 2 * n
    return coords


def group_nodes(text, group):
    """The node tags of the line elements of a physical curve group."""
    lines = text.splitlines()
    _, curves = _curve_entities(lines, group)
    i = _section(lines, "Elements")
    nblocks = int(lines[i + 1].split()[0])
    j, nodes = i + 2, set()
    for _ in range(nblocks):
        dim, etag, _, n = map(int, lines[j].split())
        if dim == 1 and etag in curves:
            for e in lines[j + 1:j + 1 + n]:
                nodes.update(map(int, e.split()[1:]))
        j += 1 + n
    return nodes


def shared_point(text, group_a, group_b):
    """The (x, y) of the one node two curve groups share (e.g. the ram corner)."""
    common = group_nodes(text, group_a) & group_nodes(text, group_b)
    if len(common) != 1:
        raise RuntimeError(f"mesh: groups '{group_a}' and '{group_b}' share {len(common)} nodes, expected 1")
    return node_coordinates(text)[common.pop()]


def without_corner_segment(text, group, corner):
    """The mesh with the line element of `group` at the node at `corner` (x, y) removed.

    E.g. the ram and the container share the ram corner node; a no-slip (0, 0) container
    there contradicts the ram's (1, 0) (an input error). Dropping that one segment from the
    group leaves the corner to the ram, on the identical mesh otherwise.
    """
    lines = text.splitlines()
    tag, curves = _curve_entities(lines, group)
    corner_tag = None
    for t, (x, y) in node_coordinates(text).items():
        if math.hypot(x - corner[0], y - corner[1]) < 1e-9:
            corner_tag = t
    if tag is None or not curves or corner_tag is None:
        raise RuntimeError(f"mesh: no group '{group}' or no node at {corner}")
    i = _section(lines, "Elements")
    nblocks, nelems, lo, hi = map(int, lines[i + 1].split())
    j, body, removed = i + 2, [], 0
    for _ in range(nblocks):
        dim, etag, etype, n = map(int, lines[j].split())
        elems = lines[j + 1:j + 1 + n]
        if dim == 1 and etag in curves:
            kept = [e for e in elems if corner_tag not in map(int, e.split()[1:])]
            removed, elems = removed + n - len(kept), kept
        body += [f"{dim} {etag} {etype} {len(elems)}"] + elems
        j += 1 + n
    if removed != 1:
        raise RuntimeError(f"mesh: expected one '{group}' segment at {corner}, found {removed}")
    return "\n".join(lines[:i + 1] + [f"{nblocks} {nelems - removed} {lo} {hi}"] + body + lines[j:]) + "\n"
