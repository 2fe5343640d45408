"""flowform_tools: what the regression checks, benchmarks and plot scripts share.

One place to run the flowform executable and read what it writes, so that the scripts in
tests/regression/, bench/ and scripts/ do not each carry their own launcher and readers.

  launcher   run flowform (case, output directory, --set overrides, mpirun -np, timeout,
             log file, peak memory by /usr/bin/time -v) and get its exit status, summary and
             log; run_command() for any other command line
  summary    summary.json: load it, dotted-key access ("linear_solver.factorizations"), the
             totals over an adaptive loop's cycles (adaptive_totals)
  case       a case XML (or the "parameters" of a summary.json): contact walls, responses,
             the tool boundary, geometry; variants of a case written to a new file
  csvio      boundary_<group>.csv: rows, columns, integrals along the curve
  h5io       solution.h5: mesh and nodal/cell fields (needs h5py and numpy)
  sweep      sweep values ("0,0.1" or "0:0.5:0.1") and sweep.csv (with the estimate and
             derivative columns)
  numerics   observed order of convergence, Richardson extrapolation, relative difference
  machine    machine and binary information printed with benchmark results
  msh        small edits of gmsh 4 ASCII meshes
  tables     markdown tables of the benchmarks' reports
  plotting   matplotlib (Agg) helpers shared by the plot scripts (needs matplotlib): values
             with their error bars and DDM tangents, the tool walls in flow order
  checks     the whole-run checks' one line per check and verdict (tests/regression/)
  benchmark  the benchmarks' channel sizes and one timed run (bench/)
  rolling_theory   the slab method of flat rolling (docs/rolling_theory.md; numpy)
  rolling_compare  a rolling run against the slab method at its own pass, the roll pressure
             along the arc (numpy, h5py; scripts/rolling_study.py, rolling_slab_checks.py)

A scene's own theory lives beside the checks that assert it, not here: tests/regression/
extrusion/ (slip-line values), tests/regression/cutting/ (the shear plane). The tests of this
package are tests/unit/python/ (ctest -L unit).

The package is found through PYTHONPATH, one way for every caller, with no sys.path edits in
the scripts: ctest sets it for every test (tests/CMakeLists.txt), and the scripts are run
through the launcher that sets the same path (python/ and tests/regression/):

    scripts/python scripts/plot_extrusion.py --sweep out/sweep
    scripts/python bench/channel_bench.py --quick

Only the standard library is imported here and by launcher, summary, case, csvio, sweep,
numerics, machine, msh and tables; h5io and plotting import numpy, h5py and matplotlib (Debian's
/usr/bin/python3 has them: python3-numpy, python3-h5py, python3-matplotlib).
"""
import os

#: The repository's root directory (the parent of python/).
REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def repo_path(*parts):
    """A path inside the repository, e.g. repo_path("xml", "channel.xml")."""
    return os.path.join(REPO, *parts)


def default_flowform():
    """build/flowform of this repository (scripts/build puts it there)."""
    return repo_path("build", "flowform")
