// What a .geo file may ask of gmsh. A case and its .geo are data a user may receive from
// someone else, and gmsh's .geo language can run shell commands (SystemCall), write files
// (Save, Print, Printf > "file"), start programs (OnelabRun, the Solver options) and read any
// file (Include, Merge). flowform hands gmsh only .geo scripts that describe geometry and mesh:
// checkGeoScript reads the file (and every file it Includes) before gmsh does and refuses
// the commands that reach outside the meshing.
//
// The rule (README "What a .geo may do"):
//   - refused anywhere: SystemCall, NonBlockingSystemCall, System, OnelabRun, Save, Print,
//     Plugin, CreateDir, DeleteFile, RenameFile, Exit, and assignments to the option
//     categories General., Print., Solver. (file names, programs, the session file);
//   - Printf/Sprintf with an output redirection (`> "file"`, `>> "file"`) is refused; Printf
//     to the terminal is allowed;
//   - Include, Merge, MergeWithBoundingBox and ShapeFromFile must name a string literal inside
//     the folder of the file that says it (a sub-folder is fine; no "..", no absolute path
//     elsewhere, no computed name); Included .geo files are checked by the same rule.
// Comments and the insides of string literals are not commands and are skipped.
#pragma once

#include <string>

namespace flowform {

/// Throws InputError naming the file, the line and the command when `path` (or a file it
/// Includes) uses a command the rule above refuses, or cannot be read.
void checkGeoScript(const std::string& path);

}  // namespace flowform
