#!/usr/bin/env python3
"""The layering rule of flowform's source tree, checked.

The data path reads straight off the folders (../shared STYLE, README "Layout"):

    core < mesh < discretization < physics < bc < contact < assembly < responses
         < solvers < freesurface < problem < sensitivity < estimation < io < drivers

A file of include/flowform/<stage>/ or src/<stage>/ may include "flowform/<other>/..." only
when <other> is the same stage or an earlier one in STAGES below; src/main.cpp is the driver
stage. The mesher program (src/mesher/, include/flowform/mesher/) is an island: it links gmsh
alone, so it may include core and mesh only (and itself). A folder that is not in the table
is an error too: a new folder is placed in STAGES (one line) when it is made.

A header that an earlier stage needs is moved down, not whitelisted: there is no exception list.

Usage: check_layering.py [ROOT]   (ROOT holds include/ and src/; default: this repository)
Exit status 0 when the tree keeps the rule, 1 with one line per violation otherwise.
"""
import os
import re
import sys

# The stage order, earliest first. Folders on one line are one stage (they may include each
# other); each later line may include every earlier one.
STAGES = [
    ["core"],                 # types, logging, budgets, input errors, file helpers
    ["mesh"],                 # the mesh, its reading, partition, boundary curves, size fields
    ["discretization"],       # shape functions, element layout, dof map, solution transfer
    ["physics"],              # the constitutive law and the flow residual (templated kernels)
    ["bc"],                   # boundary conditions
    ["contact"],              # contact walls, friction laws, wall states
    ["assembly"],             # the assembler, evaluation types, sensitivity parameters
    ["responses"],            # the responses (functionals) of a solution
    ["solvers"],              # linear solvers, the model, Newton, the contact-status loop
    ["freesurface"],          # free surfaces, mesh motion, the free-surface loop, its linearization
    ["problem"],              # the state of one solve (Problem) and its solve
    ["sensitivity"],          # DDM, the total shape derivative, the finite-difference check
    ["estimation"],           # the two-level error estimate, adaptivity
    ["io"],                   # writers and readers of files
    ["optimization"],         # design and inverse problems on ROL: runs of the case at designs
    ["drivers"],              # the case, the run (Simulation), main.cpp
]
# The mesher program: gmsh only, no Trilinos; it shares plain data with the library.
ISLANDS = {"mesher": {"mesher", "core", "mesh"}}

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]flowform/([A-Za-z0-9_]+)/([^">]+)[">]')


def stage_of(folder):
    for rank, stages in enumerate(STAGES):
        if folder in stages:
            return rank
    return None


def folder_of(rel):
    """The stage folder of a file given relative to ROOT (include/flowform/x/... or src/x/...)."""
    parts = rel.split(os.sep)
    if parts[0] == "include" and len(parts) >= 4 and parts[1] == "flowform":
        return parts[2]
    if parts[0] == "src":
        if len(parts) == 2:  # src/main.cpp: the command-line driver
            return "drivers"
        return parts[1]
    return None


def check(root):
    violations = []
    for top in ("include", "src"):
        for dirpath, dirs, files in os.walk(os.path.join(root, top)):
            dirs.sort()  # a stable report
            for name in sorted(files):
                if not name.endswith((".hpp", ".cpp", ".h", ".cc")):
                    continue
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, root)
                folder = folder_of(rel)
                if folder is None:
                    continue
                own = stage_of(folder)
                if own is None and folder not in ISLANDS:
                    violations.append(f"{rel}: folder '{folder}' is not in the stage table (scripts/check_layering.py)")
                    continue
                with open(path, encoding="utf-8", errors="replace") as f:
                    for line_no, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        target = m.group(1)
                        header = f"flowform/{target}/{m.group(2)}"
                        if folder in ISLANDS:
                            if target not in ISLANDS[folder]:
                                violations.append(f"{rel}:{line_no}: includes {header}: the {folder} program "
                                                  f"may include only {sorted(ISLANDS[folder])}")
                            continue
                        if target in ISLANDS:
                            violations.append(f"{rel}:{line_no}: includes {header}: the {target} program's own code")
                            continue
                        theirs = stage_of(target)
                        if theirs is None:
                            violations.append(f"{rel}:{line_no}: includes {header}: folder '{target}' is not in "
                                              f"the stage table")
                        elif theirs > own:
                            violations.append(f"{rel}:{line_no}: includes {header}: '{target}' is a later stage "
                                              f"than '{folder}'")
    return violations


def main(argv):
    root = argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    if not os.path.isdir(os.path.join(root, "include")) or not os.path.isdir(os.path.join(root, "src")):
        print(f"check_layering: {root} has no include/ and src/", file=sys.stderr)
        return 2
    violations = check(root)
    for v in violations:
        print(v)
    print(f"{len(violations)} layering violation(s) in {os.path.abspath(root)}")
    return 1 if violations else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
