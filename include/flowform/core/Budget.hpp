// The run-wide wall-clock budget (Solver/Time Limit, seconds; 0 = none). Every outer loop — Newton
// iterations, continuation stages, the contact-status loop, the free-surface loop, the adaptivity
// cycles, the finite-difference runs — asks budgetSpent() once per iteration; the first ask after
// the limit records where the run was (the loops open a BudgetScope with their name and a count),
// and from then on every loop stops at once: the run ends not converged (exit 3), the last state
// written, summary.json "message" = budgetMessage().
//
// budgetSpent() is collective when a limit is set (every rank asks at the same points, and rank 0's
// clock decides for all), so all ranks leave the same loop at the same iteration.
#pragma once

#include <functional>
#include <string>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

namespace flowform {

/// Starts the budget: `seconds` from the process start (budgetMarkStart), 0 = no limit.
void startBudget(double seconds, const Teuchos::RCP<const Teuchos::Comm<int>>& comm);
/// The process start, the budget's origin (called first thing in main; otherwise at the first use).
void budgetMarkStart();
/// Whether the budget is spent (sticky). Collective while a limit is set.
bool budgetSpent();
/// Whether an earlier budgetSpent() found it spent (local, no communication).
bool budgetWasSpent();
/// "wall-clock budget of X s (Solver/Time Limit) spent in <loop>, after <n> ...; within ...".
const std::string& budgetMessage();
/// Seconds since the process start.
double budgetElapsed();

/// One loop on the stack of running loops: its name ("the contact-status loop") and what it has
/// done so far ("12 status change(s)"), read when the budget is found spent.
class BudgetScope {
 public:
  BudgetScope(std::string loop, std::function<std::string()> progress);
  ~BudgetScope();
  BudgetScope(const BudgetScope&) = delete;
  BudgetScope& operator=(const BudgetScope&) = delete;
};

}  // namespace flowform
