"""The extrusion verification checks run by tests/regression/extrusion_checks.py, one module
per group of checks (docs/extrusion_verification.md):

  common        reporting (Checks), running flowform on the scene (Runner, ExtrusionRun) and
                quantities computed from the output files
  contact       contact criteria after the status loop                (subcommand contact)
  power         power balance                                         (power)
  convergence   mesh convergence of the ram force, die-lip leak       (convergence)
  penalty       insensitivity to the penalty factors                  (penalty-normal, penalty-tangential)
  limits        ν = 0, large ν and monotonicity in ν                  (frictionless, sticking, monotone)
  theory        frictionless extrusion against slip-line theory       (theory)

Each check module has a COMMANDS dict: subcommand name -> function(runner, args, checks).
"""
