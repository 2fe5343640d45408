// What a .geo may do (mesh/GeoScript): the commands refused, where they are not commands
// (comments, strings, member names), and Include inside and outside the .geo's folder.
#include <Teuchos_UnitTestHarness.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "flowform/core/InputError.hpp"
#include "flowform/mesh/GeoScript.hpp"

namespace {

namespace fs = std::filesystem;

/// A scratch folder with files written into it; removed at the end.
struct Folder {
  fs::path dir;
  Folder() {
    dir = fs::temp_directory_path() / ("flowform_geoscript_" + std::to_string(::getpid()));
    fs::create_directories(dir / "sub");
  }
  ~Folder() { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  }
};

/// The InputError's message for `text` as a .geo, or "" when it is accepted.
std::string verdict(const Folder& f, const std::string& text) {
  try {
    flowform::checkGeoScript(f.write("case.geo", text));
    return "";
  } catch (const flowform::InputError& e) {
    return e.what();
  }
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEUCHOS_UNIT_TEST(GeoScript, RefusesCommandsThatReachOutside) {
  Folder f;
  const char* refused[] = {"SystemCall \"ls\";", "NonBlockingSystemCall \"ls\";", "OnelabRun \"x\";",
                           "Save \"out.msh\";", "Print \"out.png\";", "Plugin(Integrate).Run;",
                           "CreateDir \"d\";", "DeleteFile \"f\";", "RenameFile \"a\", \"b\";", "Exit;",
                           "General.SessionFileName = \"x\";", "Solver.Executable0 = \"/bin/sh\";",
                           "Print.Width = 10;", "Printf(\"%g\", 1) > \"f.txt\";", "Printf(\"x\") >> \"f.txt\";",
                           "Include \"/etc/passwd\";", "Include \"../x.geo\";", "Merge \"../../a.msh\";",
                           "Include StrCat(\"a\", \".geo\");"};
  for (const char* line : refused) {
    const std::string v = verdict(f, "Point(1) = {0, 0, 0};\n" + std::string(line) + "\n");
    TEST_ASSERT(contains(v, "line 2"));
    TEST_ASSERT(contains(v, "case.geo"));
    out << line << " -> " << v << "\n";
  }
}

TEUCHOS_UNIT_TEST(GeoScript, AcceptsGeometryCommentsAndStrings) {
  Folder f;
  f.write("sub/part.geo", "Point(7) = {1, 1, 0};\n");
  const std::string ok =
      "// SystemCall \"rm -rf /\"; in a comment\n"
      "/* Save \"x\";\n   Exit; */\n"
      "DefineConstant[ h = {0.1, Min 1e-4, Max 1, Name \"Parameters/h\", Label \"SystemCall\"} ];\n"
      "Printf(\"h = %g > 0\", h);\n"
      "Mesh.SaveAll = 0; Mesh.Algorithm = 6; Geometry.Tolerance = 1e-9;\n"
      "Include \"sub/part.geo\";\n"
      "Point(1) = {0, 0, 0, h};\n";
  TEST_EQUALITY(verdict(f, ok), "");
}

TEUCHOS_UNIT_TEST(GeoScript, ChecksIncludedFiles) {
  Folder f;
  f.write("sub/bad.geo", "x = 1;\nSystemCall \"ls\";\n");
  const std::string v = verdict(f, "Include \"sub/bad.geo\";\n");
  TEST_ASSERT(contains(v, "bad.geo"));
  TEST_ASSERT(contains(v, "line 2"));
  f.write("sub/loop.geo", "Include \"loop.geo\";\n");
  TEST_ASSERT(contains(verdict(f, "Include \"sub/loop.geo\";\n"), "includes itself"));
  TEST_ASSERT(contains(verdict(f, "Include \"sub/none.geo\";\n"), "no such file"));
}

}  // namespace
