// Reading the case file: the one path from the XML on disk to the parameter list.
//
// Teuchos' XML reader is lenient where flowform must not be: a parameter given twice keeps one
// of them, a double or int value is read with a stream (atof, istringstream), so "abc" is 0 and
// "5,5" is 5, "inf" and "nan" are read as numbers, and a UTF-8 byte-order mark makes the parser
// fail. readCaseFile checks the XML tree first and throws InputError (exit 2) naming the file,
// the parameter path, the line and what is allowed; only then is the list built by Teuchos.
#pragma once

#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace flowform {

/// The parameter list of the case file `path`. Throws InputError when the file cannot be read,
/// is not a valid XML parameter list, gives a parameter or sublist twice in one list, or has a
/// bool, int or double value (or an element of an Array(int) / Array(double)) that is not
/// exactly one value of that type: a double must be a finite decimal number ([+-]digits
/// [.digits][e[+-]digits]; no inf, nan, hex, overflow), an int a decimal integer in range, a
/// bool one of true/false/yes/no/1/0 (any case, as Teuchos reads them). A leading UTF-8
/// byte-order mark is skipped.
/// A root entry `Base Case` (a path relative to this file) names a case this one changes: that file
/// is read first (its own Base Case too) and this one's entries laid over it, a sublist merging
/// into the base's sublist of that name, or replacing it whole when it has `Replace Base = true`
/// (a wall's other friction law); relative paths (Mesh/File) then count from this file's folder,
/// so a base and the cases that change it live in one folder.
Teuchos::RCP<Teuchos::ParameterList> readCaseFile(const std::string& path);

/// The same for a case given as text; `source` names it in messages (a file name).
Teuchos::RCP<Teuchos::ParameterList> readCaseText(const std::string& text, const std::string& source);

/// Whether `text` (blanks around it allowed) is exactly one finite double in decimal notation
/// (the form Teuchos and std::strtod read the same way); the value in `value`.
bool parseFiniteDouble(const std::string& text, double& value);

/// Whether `text` (blanks around it allowed) is exactly one decimal int in range.
bool parseStrictInt(const std::string& text, int& value);

}  // namespace flowform
