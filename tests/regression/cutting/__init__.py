"""The cutting scene's theory, beside the checks that assert it (tests/regression/cutting_checks.py)
and read by its benchmark (bench/cutting_sweep.py); importable as `cutting` through the
PYTHONPATH that ctest and scripts/python set (tests/regression/ is an import root):

  shear_plane   the thin shear plane's equilibrium at any φ (Ernst & Merchant), and the
                cutting run's primary shear band read off its solution.h5 (angle, p/k)
  rules         the rules that pick φ at α = 0: Merchant's minimum power, Lee & Shaffer's
                slip-line field (t/t_c, F_c/(k t), their ν derivatives)

The tests of both: tests/unit/python/test_cutting_theory.py.
"""
