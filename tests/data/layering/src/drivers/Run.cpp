#include "flowform/mesh/Bad.hpp"  // the last stage includes anything
#include <flowform/io/Writer.hpp>
