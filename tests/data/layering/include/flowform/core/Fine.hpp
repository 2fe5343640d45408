#pragma once
#include "flowform/core/Other.hpp"  // same stage: allowed
