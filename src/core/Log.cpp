#include "flowform/core/Log.hpp"

#include <iostream>

namespace flowform {

namespace {

struct NullBuffer : std::streambuf {
  int overflow(int c) override { return c; }
};

NullBuffer g_nullBuffer;
std::ostream g_nullStream(&g_nullBuffer);
bool g_enabled = true;
int g_rank = 0;

}  // namespace

std::ostream& log() { return (g_enabled && g_rank == 0) ? std::cout : g_nullStream; }
std::ostream& warn() {
  if (g_rank != 0) return g_nullStream;
  return std::cerr << "flowform: warning: ";
}
void setLogEnabled(bool enabled) { g_enabled = enabled; }
void setLogRank(int rank) { g_rank = rank; }

}  // namespace flowform
