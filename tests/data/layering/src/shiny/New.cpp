#include "flowform/core/Fine.hpp"  // a folder not in the stage table: a violation
