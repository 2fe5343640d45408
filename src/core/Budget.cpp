#include "flowform/core/Budget.hpp"

#include <chrono>
#include <iomanip>
#include <sstream>
#include <vector>

#include <Teuchos_CommHelpers.hpp>

namespace flowform {

namespace {

using Clock = std::chrono::steady_clock;

struct Frame {
  std::string loop;
  std::function<std::string()> progress;
};

struct State {
  bool started = false;
  Clock::time_point start;
  double limit = 0.0;
  bool spent = false;
  std::string message;
  Teuchos::RCP<const Teuchos::Comm<int>> comm;
  std::vector<Frame> stack;
};

State& state() {
  static State s;
  return s;
}

}  // namespace

void budgetMarkStart() {
  State& s = state();
  if (!s.started) {
    s.started = true;
    s.start = Clock::now();
  }
}

double budgetElapsed() {
  budgetMarkStart();
  return std::chrono::duration<double>(Clock::now() - state().start).count();
}

void startBudget(double seconds, const Teuchos::RCP<const Teuchos::Comm<int>>& comm) {
  budgetMarkStart();
  State& s = state();
  s.limit = seconds > 0.0 ? seconds : 0.0;
  s.comm = comm;
  s.spent = false;
  s.message.clear();
}

bool budgetWasSpent() { return state().spent; }

const std::string& budgetMessage() { return state().message; }

bool budgetSpent() {
  State& s = state();
  if (s.spent) return true;
  if (s.limit <= 0.0) return false;
  int over = budgetElapsed() > s.limit ? 1 : 0;
  // Rank 0's clock decides for every rank: they all leave the same loop at the same point.
  if (!s.comm.is_null() && s.comm->getSize() > 1) Teuchos::broadcast(*s.comm, 0, &over);
  if (!over) return false;
  s.spent = true;
  std::ostringstream os;
  os << std::setprecision(3);
  os << "wall-clock budget of " << s.limit << " s (Solver/Time Limit) spent";
  if (s.stack.empty()) {
    os << " after " << budgetElapsed() << " s";
  } else {
    // Innermost loop first, then the loops it runs in.
    for (size_t i = s.stack.size(); i-- > 0;) {
      const Frame& f = s.stack[i];
      os << (i + 1 == s.stack.size() ? " in " : "; within ") << f.loop;
      const std::string done = f.progress ? f.progress() : std::string();
      if (!done.empty()) os << ", after " << done;
    }
  }
  os << " (" << budgetElapsed() << " s since the start); the results are those of the last state";
  s.message = os.str();
  return true;
}

BudgetScope::BudgetScope(std::string loop, std::function<std::string()> progress) {
  state().stack.push_back({std::move(loop), std::move(progress)});
}

BudgetScope::~BudgetScope() { state().stack.pop_back(); }

}  // namespace flowform
