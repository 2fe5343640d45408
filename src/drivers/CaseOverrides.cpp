#include "flowform/drivers/CaseOverrides.hpp"

#include <sstream>
#include <vector>

#include "flowform/core/InputError.hpp"
#include "flowform/core/Strings.hpp"
#include "flowform/io/CaseFile.hpp"

namespace flowform {

namespace {

std::vector<std::string> splitPath(const std::string& path) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream is(path);
  while (std::getline(is, part, '/')) parts.push_back(part);
  return parts;
}

template <typename T>
bool parseExactly(const std::string& text, T& value) {
  std::istringstream is(text);
  is >> value;
  return !is.fail() && is.eof();
}

/// A double written as in the case file (io/CaseFile.hpp): a finite decimal number, no inf/nan.
bool parseExactly(const std::string& text, double& value) {
  return parseFiniteDouble(text, value);
}

bool parseBool(const std::string& text, bool& value) {
  if (text == "true" || text == "True" || text == "1") { value = true; return true; }
  if (text == "false" || text == "False" || text == "0") { value = false; return true; }
  return false;
}

/// "{a, b, c}" or "a, b, c" (braces optional) as an array of trimmed strings; "{}" is empty.
Teuchos::Array<std::string> parseStringArray(std::string text) {
  text = trim(text);
  if (text.size() >= 2 && text.front() == '{' && text.back() == '}') text = text.substr(1, text.size() - 2);
  Teuchos::Array<std::string> items;
  std::string item;
  std::istringstream is(text);
  while (std::getline(is, item, ','))
    if (!trim(item).empty()) items.push_back(trim(item));
  return items;
}

/// The entry `name` of the list reached by `path` in `list`, or nullptr.
const Teuchos::ParameterEntry* findEntry(const Teuchos::ParameterList& list, const std::vector<std::string>& path,
                                         const std::string& name) {
  const Teuchos::ParameterList* current = &list;
  for (const auto& p : path) {
    if (!current->isSublist(p)) return nullptr;
    current = &current->sublist(p);
  }
  return current->getEntryPtr(name);
}

}  // namespace

void applyOverride(Teuchos::ParameterList& params, const std::string& assignment,
                   const Teuchos::ParameterList& valid) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set '" + assignment + "': expected Path/To/Param=value");
  std::vector<std::string> path = splitPath(assignment.substr(0, eq));
  const std::string value = assignment.substr(eq + 1);
  const std::string name = path.back();
  path.pop_back();

  const Teuchos::ParameterEntry* like = findEntry(params, path, name);
  if (!like) like = findEntry(valid, path, name);
  if (!like && !path.empty()) {
    // A free-form sublist (a boundary group, a response): its template "<... name>" in the
    // valid list has the entry types.
    std::vector<std::string> templatePath(path.begin(), path.end() - 1);
    const Teuchos::ParameterList* parent = &valid;
    for (const auto& p : templatePath) parent = parent && parent->isSublist(p) ? &parent->sublist(p) : nullptr;
    if (parent)
      for (auto it = parent->begin(); it != parent->end() && !like; ++it)
        if (parent->name(it).rfind("<", 0) == 0 && parent->isSublist(parent->name(it)))
          like = parent->sublist(parent->name(it)).getEntryPtr(name);
  }

  Teuchos::ParameterList* target = &params;
  for (const auto& p : path) target = &target->sublist(p);

  auto fail = [&](const std::string& type) {
    throw InputError("--set '" + assignment + "': '" + value + "' is not a valid " + type + " for " +
                     assignment.substr(0, eq));
  };
  if (like && like->isType<int>()) {
    int v; if (!parseExactly(value, v)) fail("int");
    target->set(name, v);
  } else if (like && like->isType<double>()) {
    double v; if (!parseExactly(value, v)) fail("double (a finite decimal number)");
    target->set(name, v);
  } else if (like && like->isType<bool>()) {
    bool v; if (!parseBool(value, v)) fail("bool (true or false)");
    target->set(name, v);
  } else if (like && like->isType<std::string>()) {
    target->set(name, value);
  } else if (like && like->isType<Teuchos::Array<std::string>>()) {
    target->set(name, parseStringArray(value));
  } else if (like && like->isType<Teuchos::Array<double>>()) {  // "{0.1, 2}": each a finite number
    Teuchos::Array<double> numbers;
    for (const std::string& item : parseStringArray(value)) {
      double v;
      if (!parseExactly(item, v)) fail("list of doubles (finite decimal numbers)");
      numbers.push_back(v);
    }
    target->set(name, numbers);
  } else if (like) {
    throw InputError("--set '" + assignment + "': parameter of type " + like->getAny().typeName() +
                     " cannot be set from the command line");
  } else {
    int i; double d; bool b;
    if (parseExactly(value, i)) target->set(name, i);
    else if (parseExactly(value, d)) target->set(name, d);
    else if (parseBool(value, b)) target->set(name, b);
    else target->set(name, value);
  }
}

}  // namespace flowform
