// Progress output: rank 0 writes, other ranks stay quiet. Quiet mode (tests) drops it all.
#pragma once

#include <ostream>

namespace flowform {

/// The stream for progress messages (Newton norms, continuation, contact changes).
std::ostream& log();
/// The stream for warnings (an input entry the case ignores, ...): stderr on rank 0, "flowform:
/// warning: " first; shown in quiet mode too (they are not progress).
std::ostream& warn();
/// Turn progress output on or off (default on, on rank 0 only).
void setLogEnabled(bool enabled);
/// Tell the logger which rank this process is (called once by the driver).
void setLogRank(int rank);

}  // namespace flowform
