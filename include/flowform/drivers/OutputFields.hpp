// The fields a run writes (solution.h5/.xdmf, boundary CSVs), gathered to rank 0 from the
// pieces that own them: nodal u and p from the solution, the contact status from the walls,
// du/dh and dp/dh from the sensitivity and its check, the cell values from the assembler's
// cellStates (the same centroid evaluation the contact scales use, not a second copy of the
// physics).
#pragma once

#include <string>
#include <vector>

#include <Teuchos_Array.hpp>

#include "flowform/assembly/Assembler.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/core/TpetraTypes.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/io/FieldSet.hpp"
#include "flowform/sensitivity/FiniteDifferenceCheck.hpp"
#include "flowform/sensitivity/Sensitivity.hpp"

namespace flowform {

/// The cell fields a case may ask for (Output/Cell Fields).
const std::vector<std::string>& cellFieldNames();

/// Nodal velocity and pressure, the contact status when there are walls, the sensitivity
/// fields when they were computed (and the check's, when `fdCheck` is given), and the cell
/// fields named in `cellFields`, on rank 0 (other ranks get empty arrays). Collective.
FieldSet gatherOutputFields(const Assembler& assembler, const Vector& solution, const std::vector<ContactWall>& walls,
                            const Sensitivity& sensitivity, const FiniteDifferenceCheck* fdCheck,
                            const Teuchos::Array<std::string>& cellFields);

}  // namespace flowform
