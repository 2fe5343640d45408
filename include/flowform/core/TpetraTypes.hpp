// Tpetra types at the one instantiation Debian ships: <double, int, long long, Serial>.
#pragma once

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_FECrsGraph.hpp>
#include <Tpetra_FECrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "flowform/core/Types.hpp"

namespace flowform {

using Node = Tpetra::Map<LO, GO>::node_type;
using Map = Tpetra::Map<LO, GO, Node>;
using Vector = Tpetra::Vector<double, LO, GO, Node>;
using MultiVector = Tpetra::MultiVector<double, LO, GO, Node>;
using CrsMatrix = Tpetra::CrsMatrix<double, LO, GO, Node>;
using CrsGraph = Tpetra::CrsGraph<LO, GO, Node>;
using FECrsGraph = Tpetra::FECrsGraph<LO, GO, Node>;
using FECrsMatrix = Tpetra::FECrsMatrix<double, LO, GO, Node>;
using Import = Tpetra::Import<LO, GO, Node>;
using Export = Tpetra::Export<LO, GO, Node>;
using Comm = Teuchos::Comm<int>;

}  // namespace flowform
