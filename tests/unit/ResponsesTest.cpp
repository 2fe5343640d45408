// The response registry (responses/ResponseRegistry.hpp): every registered type has a
// description and a validator on every number it reads, the sublist's "Type" offers exactly the
// registered types, an unknown Type or a missing group is an InputError naming what is allowed;
// and the wall's upstream end (ContactWall::firstNodeIsUpstream), the one answer the responses use.
#include <stdexcept>

#include <Teuchos_UnitTestHarness.hpp>

#include "flowform/contact/ContactWall.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/responses/ResponseRegistry.hpp"
#include "flowform/responses/Responses.hpp"

#include "BottomMesh.hpp"

namespace {

using namespace flowform;

/// bottomMesh() with a group "right" that meets the wall's last node (1,0).
Mesh squareMesh() {
  Mesh m = bottomMesh();
  m.boundaries.push_back({"right", {{2, 3}}});
  return m;
}

TEUCHOS_UNIT_TEST(Responses, EveryTypeIsDocumentedAndEveryNumberValidated) {
  const auto& types = responseTypes();
  Teuchos::ParameterList beyond;  // one index past the list is no type
  TEST_THROW(declareResponseParameters(static_cast<int>(types.size()), beyond), std::out_of_range);
  const Teuchos::ParameterList& valid = *validResponseParameters();
  for (size_t i = 0; i < types.size(); ++i) {
    TEST_ASSERT(!types[i].name.empty());
    TEST_ASSERT(types[i].description.size() > 20);
    TEST_EQUALITY(responseTypeIndex(types[i].name), static_cast<int>(i));
    // An adaptivity target is linear in the reactions; a wall response names a group.
    if (types[i].adaptivityTarget) TEST_ASSERT(types[i].reactionBased && types[i].differentiable);
    if (types[i].needsWall) TEST_ASSERT(types[i].needsBoundary);
    Teuchos::ParameterList own;
    declareResponseParameters(static_cast<int>(i), own);
    for (auto it = own.begin(); it != own.end(); ++it) {
      const std::string& name = own.name(it);
      const Teuchos::ParameterEntry& entry = own.entry(it);
      out << types[i].name << " / " << name << "\n";
      TEST_ASSERT(!entry.docString().empty());
      if (entry.isType<double>() || entry.isType<int>()) TEST_ASSERT(!entry.validator().is_null());
      // The sublist's entry is this one (same default), its doc names this type and its use.
      TEST_ASSERT(valid.isParameter(name));
      TEST_ASSERT(valid.getEntry(name).getAny() == entry.getAny());
      const std::string doc = valid.getEntry(name).docString();
      TEST_ASSERT(doc.find(types[i].name) != std::string::npos && doc.find(entry.docString()) != std::string::npos);
    }
  }
  // "Type" offers exactly the registered names, the first the default.
  TEST_EQUALITY(valid.get<std::string>("Type"), types.front().name);
  const auto typeValidator = valid.getEntry("Type").validator();
  TEST_ASSERT(!typeValidator.is_null());
  const auto allowed = typeValidator->validStringValues();
  TEST_ASSERT(!allowed.is_null());
  TEST_EQUALITY(allowed->size(), types.size());
  for (size_t i = 0; i < types.size(); ++i) TEST_EQUALITY((*allowed)[i], types[i].name);
  TEST_EQUALITY(responseTypeNames(&ResponseTypeInfo::adaptivityTarget, " or "), "Boundary Force or Mean Pressure");
}

TEUCHOS_UNIT_TEST(Responses, UnknownTypeNamesTheAllowedOnes) {
  Teuchos::ParameterList list;
  list.sublist("force").set("Type", "Boundary Forse");
  list.sublist("force").set("Boundary", "bottom");
  try {
    Responses(list, squareMesh());
    TEST_ASSERT(false);  // not reached
  } catch (const InputError& e) {
    const std::string what = e.what();
    out << what << "\n";
    TEST_ASSERT(what.find("Responses/force") != std::string::npos);
    TEST_ASSERT(what.find("Boundary Forse") != std::string::npos);
    for (const ResponseTypeInfo& t : responseTypes()) TEST_ASSERT(what.find(t.name) != std::string::npos);
  }
}

TEUCHOS_UNIT_TEST(Responses, MissingGroupAndMissingWallAreInputErrors) {
  Teuchos::ParameterList list;
  list.sublist("force").set("Type", "Boundary Force");
  list.sublist("force").set("Boundary", "top");
  TEST_THROW(Responses(list, squareMesh()), InputError);
  // A wall response on a group that is no Contact Wall: refused by checkWalls, naming the type.
  Teuchos::ParameterList walls;
  walls.sublist("length").set("Type", "Contact Length");
  walls.sublist("length").set("Boundary", "bottom");
  const Responses responses(walls, squareMesh());
  TEST_EQUALITY(responses.names().size(), 1u);
  try {
    responses.checkWalls({});
    TEST_ASSERT(false);
  } catch (const InputError& e) {
    TEST_ASSERT(std::string(e.what()).find("not a Contact Wall (a Contact Length") != std::string::npos);
  }
  // A number out of its range: the validator's words.
  Teuchos::ParameterList dead;
  dead.sublist("dz").set("Type", "Dead Zone");
  dead.sublist("dz").set("Reference Speed", -1.0);
  TEST_THROW(Responses(dead, squareMesh()), InputError);
}

TEUCHOS_UNIT_TEST(Responses, WallUpstreamEndIsTheEndOnItsStartGroup) {
  Teuchos::ParameterList p;
  p.set("Type", "Contact Wall");
  {
    const ContactWall wall("bottom", p, squareMesh(), Geometry::PlaneStrain);
    TEST_ASSERT(wall.firstNodeIsUpstream());  // no Start Group: from the first node
    TEST_EQUALITY(wall.downstreamEnd(), wall.numNodes() - 1);
  }
  p.set("Start Group", "right");  // meets the last node (1,0)
  const ContactWall wall("bottom", p, squareMesh(), Geometry::PlaneStrain);
  TEST_EQUALITY(wall.curve().nodes.back(), GO(2));
  TEST_ASSERT(!wall.firstNodeIsUpstream());
  TEST_EQUALITY(wall.downstreamEnd(), 0);
  const CurveEnds ends = endsOn(wall.curve(), squareMesh().boundary("right"));
  TEST_ASSERT(!ends.first && ends.last);
}

}  // namespace
