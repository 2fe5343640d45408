// Reading the case file (io/CaseFile.hpp) and the parameter ranges (core/NumberRange.hpp):
// every silent wrong value the XML can carry is an InputError naming the parameter, and a clean
// case reads to the same list as Teuchos' own reader gives.
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <Teuchos_XMLParameterListCoreHelpers.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"
#include "flowform/drivers/CaseParameters.hpp"
#include "flowform/core/Files.hpp"
#include "flowform/io/CaseFile.hpp"

namespace {

using namespace flowform;
namespace fs = std::filesystem;

// ctest runs the unit tests in tests/ of the source tree.
const char* const kChannel = "regression/bad_input/channel_small.xml";

std::string readText(const std::string& path) {
  std::string text;
  flowform::readWholeFile(path, text);
  return text;
}

/// A tiny case: Material with `material` inside, then a Solver list.
std::string caseWith(const std::string& material) {
  return "<ParameterList name=\"flowform\">\n"
         "  <ParameterList name=\"Material\">\n" +
         material +
         "  </ParameterList>\n"
         "  <ParameterList name=\"Solver\">\n"
         "    <Parameter name=\"Max Newton Iterations\" type=\"int\" value=\"40\"/>\n"
         "  </ParameterList>\n"
         "</ParameterList>\n";
}

std::string entry(const std::string& name, const std::string& type, const std::string& value) {
  return "    <Parameter name=\"" + name + "\" type=\"" + type + "\" value=\"" + value + "\"/>\n";
}

/// The InputError message readCaseText throws for `text`, or "" when it reads.
std::string errorOf(const std::string& text) {
  try {
    readCaseText(text, "case.xml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEUCHOS_UNIT_TEST(CaseFile, CleanFileReadsAsTeuchosReadsIt) {
  const auto ours = readCaseFile(kChannel);
  const auto teuchos = Teuchos::getParametersFromXmlFile(kChannel);
  TEST_ASSERT(Teuchos::haveSameValues(*ours, *teuchos));
  TEST_EQUALITY(ours->sublist("Material").get<double>("Rate Exponent"), 5.0);
  TEST_EQUALITY(ours->sublist("Material").get<double>("Strain Rate Cutoff"), 1e-3);
  TEST_EQUALITY(ours->sublist("Mesh").get<int>("Uniform Refinements"), 0);
}

TEUCHOS_UNIT_TEST(CaseFile, BaseCaseIsLaidUnder) {
  // xml/drawing_identify_friction.xml changes xml/drawing.xml: the base's sublists with the
  // derived file's entries over them, no Base Case entry left.
  const auto derived = readCaseFile("../xml/drawing_identify_friction.xml");
  const auto base = readCaseFile("../xml/drawing.xml");
  TEST_ASSERT(!derived->isParameter("Base Case"));
  TEST_ASSERT(Teuchos::haveSameValues(derived->sublist("Mesh"), base->sublist("Mesh")));
  TEST_ASSERT(Teuchos::haveSameValues(derived->sublist("Responses"), base->sublist("Responses")));
  TEST_ASSERT(derived->isSublist("Optimization") && !base->isSublist("Optimization"));
  const auto parameters = derived->sublist("Sensitivity").get<Teuchos::Array<std::string>>("Parameters");
  TEST_EQUALITY(parameters.size(), 1u);
  // A sublist with Replace Base = true replaces the base's whole (xml/drawing_optimal_angle.xml's
  // Tresca walls carry no Coulomb Friction Coefficient), and the entry itself is gone.
  const auto angle = readCaseFile("../xml/drawing_optimal_angle.xml");
  const auto& cone = angle->sublist("Boundary Conditions").sublist("die_cone");
  TEST_ASSERT(!cone.isParameter("Friction Coefficient") && !cone.isParameter("Replace Base"));
  TEST_EQUALITY(cone.get<std::string>("Friction Law"), "Tresca");
  TEST_ASSERT(angle->sublist("Boundary Conditions").isSublist("wire_surface"));  // the others merged
  // A chain that comes back to itself is refused.
  const fs::path dir = fs::temp_directory_path() / "flowform_base_case_test";
  fs::create_directories(dir);
  for (const auto& [name, other] : {std::pair<std::string, std::string>{"a.xml", "b.xml"}, {"b.xml", "a.xml"}}) {
    std::ofstream out(dir / name);
    out << "<ParameterList name=\"flowform\"><Parameter name=\"Base Case\" type=\"string\" value=\"" << other
        << "\"/></ParameterList>\n";
  }
  std::string error;
  try {
    readCaseFile((dir / "a.xml").string());
  } catch (const InputError& e) {
    error = e.what();
  }
  TEST_ASSERT(has(error, "includes itself"));
  fs::remove_all(dir);
}

TEUCHOS_UNIT_TEST(CaseFile, EveryShippedCaseReads) {
  // All but the bad-input fixtures made to be refused (their first comment says "Bad input:").
  int n = 0;
  for (const char* dir : {"../xml", "regression"})
    for (const auto& f : fs::recursive_directory_iterator(dir)) {
      if (f.path().extension() != ".xml") continue;
      const std::string text = readText(f.path().string());
      if (text.substr(0, 200).find("Bad input:") != std::string::npos) continue;
      std::string error;
      try {
        const auto ours = readCaseFile(f.path().string());
        // Teuchos cannot read a file with a byte-order mark: compare with the rest. A case with
        // a Base Case is that case changed (BaseCaseIsLaidUnder): not Teuchos' reading of it.
        const bool bom = text.compare(0, 3, "\xEF\xBB\xBF") == 0;
        const auto teuchos = Teuchos::getParametersFromXmlString(bom ? text.substr(3) : text);
        if (!teuchos->isParameter("Base Case")) TEST_ASSERT(Teuchos::haveSameValues(*ours, *teuchos));
      } catch (const InputError& e) {
        error = e.what();
      }
      TEST_EQUALITY(error, "");
      ++n;
    }
  TEST_ASSERT(n >= 10);
}

TEUCHOS_UNIT_TEST(CaseFile, ByteOrderMarkIsSkipped) {
  const std::string text = readText(kChannel);
  const auto withBom = readCaseText("\xEF\xBB\xBF" + text, "bom.xml");
  TEST_ASSERT(Teuchos::haveSameValues(*withBom, *Teuchos::getParametersFromXmlString(text)));
}

TEUCHOS_UNIT_TEST(CaseFile, DuplicateParameterNamesPathAndLines) {
  const std::string e = errorOf(caseWith(entry("Yield Stress", "double", "0.5") + entry("Yield Stress", "double", "0.7")));
  TEST_ASSERT(has(e, "Material/Yield Stress is given twice"));
  TEST_ASSERT(has(e, "case.xml"));
  TEST_ASSERT(has(e, "lines 3 and 4"));
  // Same name, different types: still one name given twice.
  TEST_ASSERT(has(errorOf(caseWith(entry("Yield Stress", "double", "0.5") + entry("Yield Stress", "string", "x"))),
                  "given twice"));
}

TEUCHOS_UNIT_TEST(CaseFile, DuplicateSublist) {
  std::string text = caseWith(entry("Yield Stress", "double", "0.5"));
  text.insert(text.rfind("</ParameterList>"), "  <ParameterList name=\"Material\">\n  </ParameterList>\n");
  const std::string e = errorOf(text);
  TEST_ASSERT(has(e, "sublist Material is given twice"));
  TEST_ASSERT(has(e, "lines 2 and 8"));
  // The same name in two different lists is not a duplicate.
  TEST_EQUALITY(errorOf(caseWith(entry("Max Newton Iterations", "int", "3"))), "");
}

TEUCHOS_UNIT_TEST(CaseFile, IllTypedValues) {
  for (const char* value : {"abc", "5,5", "5.5.5", "", " ", "1e", "0x10", "5 5", "1.0d0"}) {
    const std::string e = errorOf(caseWith(entry("Rate Exponent", "double", value)));
    TEST_ASSERT(has(e, "Material/Rate Exponent") && has(e, "'" + std::string(value) + "'") && has(e, "not a double"));
    out << value << ": " << e << "\n";
  }
  for (const char* value : {"2.5", "abc", "1e3", "99999999999", ""}) {
    const std::string e = errorOf(caseWith(entry("Uniform Refinements", "int", value)));
    TEST_ASSERT(has(e, "Material/Uniform Refinements") && has(e, "not an int"));
  }
  for (const char* value : {"maybe", "2", "t", ""}) {
    const std::string e = errorOf(caseWith(entry("Verbose", "bool", value)));
    TEST_ASSERT(has(e, "Material/Verbose") && has(e, "not a bool"));
  }
  const std::string e = errorOf(caseWith(entry("Weights", "Array(double)", "{1, abc}")));
  TEST_ASSERT(has(e, "Material/Weights (element 1)") && has(e, "'abc'"));
  TEST_ASSERT(has(errorOf(caseWith(entry("Weights", "Array(int)", "1, 2"))), "{a, b, ...}"));
}

TEUCHOS_UNIT_TEST(CaseFile, NonFiniteValues) {
  for (const char* value : {"inf", "-inf", "Infinity", "nan", "NaN", "-nan(0x1)", "1e400", "-1e309"}) {
    const std::string e = errorOf(caseWith(entry("Strain Rate Cutoff", "double", value)));
    TEST_ASSERT(has(e, "Material/Strain Rate Cutoff") && has(e, "not a finite number"));
    out << value << ": " << e << "\n";
  }
}

TEUCHOS_UNIT_TEST(CaseFile, ValidValuesRead) {
  const std::string text = caseWith(entry("A", "double", " 5 ") + entry("B", "double", "-.5e-3") +
                                    entry("C", "double", "+2.") + entry("D", "int", "-7") +
                                    entry("E", "bool", "TRUE") + entry("F", "bool", "no") +
                                    entry("G", "Array(double)", "{1.5, -2, 3e2}") + entry("H", "Array(int)", "{}") +
                                    entry("I", "string", "inf"));
  TEST_EQUALITY(errorOf(text), "");
  const auto p = readCaseText(text, "case.xml");
  const Teuchos::ParameterList& m = p->sublist("Material");
  TEST_EQUALITY(m.get<double>("A"), 5.0);
  TEST_EQUALITY(m.get<double>("B"), -0.5e-3);
  TEST_EQUALITY(m.get<double>("C"), 2.0);
  TEST_EQUALITY(m.get<int>("D"), -7);
  TEST_EQUALITY(m.get<bool>("E"), true);
  TEST_EQUALITY(m.get<bool>("F"), false);
  TEST_EQUALITY(m.get<Teuchos::Array<double>>("G")[2], 300.0);
}

TEUCHOS_UNIT_TEST(CaseFile, MalformedAndMissing) {
  TEST_ASSERT(has(errorOf("<ParameterList name=\"x\"><Parameter name=\"a\" type=\"int\" value=\"1\">"),
                  "not a valid XML parameter list"));
  TEST_THROW(readCaseFile("no/such/case.xml"), InputError);
}

TEUCHOS_UNIT_TEST(NumberRange, OpenAndClosedBoundsAndNonFinite) {
  Teuchos::ParameterList valid("flowform");
  valid.sublist("Solver").sublist("Continuation").set("Start Exponent", 1.0, "n", positive());
  valid.sublist("Solver").set("Fraction", 0.5, "f", inRange(0.0, 1.0, true, false));
  valid.sublist("Solver").set("Count", 1, "c", intAtLeast(1));
  valid.sublist("Solver").set("Any", 0.0, "a", finiteNumber());
  auto check = [&](const std::string& name, auto value) {
    Teuchos::ParameterList p("flowform");
    if (name == "Start Exponent") p.sublist("Solver").sublist("Continuation").set(name, value);
    else p.sublist("Solver").set(name, value);
    try {
      p.sublist("Solver").validateParameters(valid.sublist("Solver"));
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string e = check("Start Exponent", 0.0);
  TEST_ASSERT(has(e, "Solver/Continuation/Start Exponent = 0") && has(e, "> 0"));
  TEST_EQUALITY(check("Start Exponent", 1e-300), "");
  TEST_ASSERT(has(check("Start Exponent", std::numeric_limits<double>::infinity()), "finite"));
  TEST_ASSERT(has(check("Fraction", 0.0), "in (0, 1]"));
  TEST_EQUALITY(check("Fraction", 1.0), "");
  TEST_ASSERT(has(check("Fraction", std::nan("")), "Fraction = nan"));
  TEST_ASSERT(has(check("Count", 0), ">= 1"));
  TEST_EQUALITY(check("Any", -1e300), "");
  TEST_ASSERT(has(check("Any", std::nan("")), "a finite number"));
}

TEUCHOS_UNIT_TEST(NumberRange, EveryNumberOfTheCaseListHasARange) {
  // The audit, kept: every double and int of the valid case list (free-form templates included)
  // carries a validator, so no number runs unchecked. Mesh's list is its own (mesh/MeshOptions).
  std::string missing;
  std::function<void(const Teuchos::ParameterList&, const std::string&)> walk = [&](const Teuchos::ParameterList& l,
                                                                                  const std::string& path) {
    for (auto it = l.begin(); it != l.end(); ++it) {
      const std::string name = path + "/" + l.name(it);
      const Teuchos::ParameterEntry& entry = l.entry(it);
      if (entry.isList()) walk(l.sublist(l.name(it)), name);
      else if ((entry.isType<double>() || entry.isType<int>()) && entry.validator().is_null()) missing += name + "; ";
    }
  };
  walk(*validCaseParameters(), "");
  TEST_EQUALITY(missing, "");
}

}  // namespace
