#include "flowform/io/CaseFile.hpp"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include <Teuchos_StringInputSource.hpp>
#include <Teuchos_XMLObject.hpp>
#include <Teuchos_XMLParameterListCoreHelpers.hpp>

#include "flowform/core/Files.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/Strings.hpp"

namespace flowform {

namespace {

const char* const kDoubleForm = "a finite decimal number such as 5, -0.5 or 1e-3";
const char* const kIntForm = "a decimal integer such as 0, 3 or -2";
const char* const kBoolForm = "true or false (also yes/no, 1/0, any case)";

/// [+-]digits[.digits][e[+-]digits], at least one digit before the exponent: the decimal
/// notation that Teuchos' stream and std::strtod read alike (no hex, no inf/nan).
bool isDecimalNumber(const std::string& s) {
  size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  size_t digits = 0;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    size_t expDigits = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++expDigits;
    if (expDigits == 0) return false;
  }
  return i == s.size();
}

/// Whether strtod reads all of `s` as a non-finite value (inf, nan, 1e400): a number, but not
/// a finite one.
bool isNonFiniteNumber(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && !std::isfinite(v);
}

/// The line (1-based) of every <Parameter> and <ParameterList> start tag of `text`, in document
/// order, comments, CDATA and processing instructions skipped: the same order as a pre-order
/// walk of the parsed tree, so the k-th such element of the tree is on lines[k].
std::vector<int> startTagLines(const std::string& text) {
  std::vector<int> lines;
  int line = 1;
  size_t i = 0;
  auto advanceTo = [&](size_t j) {
    for (; i < j && i < text.size(); ++i)
      if (text[i] == '\n') ++line;
  };
  while (i < text.size()) {
    if (text[i] == '\n') { ++line; ++i; continue; }
    if (text[i] != '<') { ++i; continue; }
    if (text.compare(i, 4, "<!--") == 0) { advanceTo(text.find("-->", i) == std::string::npos ? text.size() : text.find("-->", i) + 3); continue; }
    if (text.compare(i, 9, "<![CDATA[") == 0) { advanceTo(text.find("]]>", i) == std::string::npos ? text.size() : text.find("]]>", i) + 3); continue; }
    if (text.compare(i, 2, "<?") == 0) { advanceTo(text.find("?>", i) == std::string::npos ? text.size() : text.find("?>", i) + 2); continue; }
    size_t j = i + 1;
    while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_' || text[j] == ':' || text[j] == '-' || text[j] == '.')) ++j;
    const std::string tag = text.substr(i + 1, j - i - 1);
    if (tag == "Parameter" || tag == "ParameterList") lines.push_back(line);
    ++i;
  }
  return lines;
}

/// Walks the parsed XML tree of a case: duplicates and value syntax.
class CaseChecker {
 public:
  CaseChecker(const std::string& source, const std::string& text) : m_source(source), m_lines(startTagLines(text)) {}

  void check(const Teuchos::XMLObject& root) {
    // The line numbers hold if the tree has as many elements as the text has start tags.
    m_haveLines = countElements(root) == m_lines.size();
    m_next = 0;
    visit(root, "", true);
  }

 private:
  size_t countElements(const Teuchos::XMLObject& node) const {
    size_t n = isEntry(node) ? 1 : 0;
    for (int i = 0; i < node.numChildren(); ++i) n += countElements(node.getChild(i));
    return n;
  }
  static bool isEntry(const Teuchos::XMLObject& node) {
    return node.getTag() == "Parameter" || node.getTag() == "ParameterList";
  }
  std::string where(size_t index) const {
    std::string s = "in case file '" + m_source + "'";
    if (m_haveLines) s += " (line " + std::to_string(m_lines[index]) + ")";
    return s;
  }

  /// Pre-order, counting the Parameter/ParameterList elements as startTagLines does.
  void visit(const Teuchos::XMLObject& node, const std::string& path, bool isRoot) {
    const bool entry = isEntry(node);
    const size_t index = entry ? m_next++ : 0;
    if (entry && node.getTag() == "Parameter" && !isRoot) checkValue(node, path, index);
    std::map<std::string, size_t> seen;  // name -> element index, among this list's entries
    for (int i = 0; i < node.numChildren(); ++i) {
      const Teuchos::XMLObject& child = node.getChild(i);
      std::string childPath = path;
      if (isEntry(child) && node.getTag() == "ParameterList" && child.hasAttribute("name")) {
        const std::string& name = child.getAttribute("name");
        childPath = path.empty() ? name : path + "/" + name;
        // m_next is child i's element index: the earlier children's subtrees have been visited.
        const auto [it, inserted] = seen.emplace(name, m_next);
        if (!inserted) duplicate(child, childPath, it->second, m_next);
      }
      visit(child, childPath, false);
    }
  }
  [[noreturn]] void duplicate(const Teuchos::XMLObject& child, const std::string& path, size_t first,
                              size_t second) const {
    std::string msg = (child.getTag() == "ParameterList" ? "the sublist " : "") + path + " is given twice in case file '" +
                      m_source + "'";
    if (m_haveLines)
      msg += " (lines " + std::to_string(m_lines[first]) + " and " + std::to_string(m_lines[second]) + ")";
    msg += "; give each parameter and sublist once (which one was meant cannot be known)";
    throw InputError(msg);
  }

  void checkValue(const Teuchos::XMLObject& node, const std::string& path, size_t index) const {
    if (!node.hasAttribute("type") || !node.hasAttribute("value")) return;  // Teuchos says what is missing
    const std::string& type = node.getAttribute("type");
    const std::string& value = node.getAttribute("value");
    if (type == "double" || type == "int" || type == "bool") {
      checkScalar(type, value, path, index, "");
    } else if (type == "Array(double)" || type == "Array(int)") {
      const std::string element = type == "Array(double)" ? "double" : "int";
      const std::string t = trim(value);
      if (t.size() < 2 || t.front() != '{' || t.back() != '}')
        throw InputError(path + " " + where(index) + ": '" + value + "' is not an " + type + "; write it {a, b, ...}");
      const std::string inner = trim(t.substr(1, t.size() - 2));
      if (inner.empty()) return;
      std::istringstream is(inner);
      std::string item;
      int k = 0;
      while (std::getline(is, item, ','))
        checkScalar(element, trim(item), path, index, " (element " + std::to_string(k++) + ")");
      if (inner.back() == ',') checkScalar(element, "", path, index, " (element " + std::to_string(k) + ")");
    }
  }

  void checkScalar(const std::string& type, const std::string& value, const std::string& path, size_t index,
                   const std::string& element) const {
    const std::string head = path + element + " " + where(index) + ": '" + value + "' ";
    if (type == "double") {
      double v;
      if (parseFiniteDouble(value, v)) return;
      if (isNonFiniteNumber(trim(value)))
        throw InputError(head + "is not a finite number (inf, nan and magnitudes beyond 1.8e308 are not allowed); a "
                         "double is " + kDoubleForm);
      throw InputError(head + "is not a double; a double is " + kDoubleForm);
    } else if (type == "int") {
      int v;
      if (parseStrictInt(value, v)) return;
      throw InputError(head + "is not an int; an int is " + kIntForm + ", from " + std::to_string(INT_MIN) + " to " +
                       std::to_string(INT_MAX));
    } else if (type == "bool") {
      // Teuchos' XMLObject::getRequiredBool: the value in capitals, exactly one of these.
      std::string caps = value;
      for (char& c : caps) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      if (caps == "TRUE" || caps == "YES" || caps == "1" || caps == "FALSE" || caps == "NO" || caps == "0") return;
      throw InputError(head + "is not a bool; a bool is " + kBoolForm);
    }
  }

  std::string m_source;
  std::vector<int> m_lines;
  bool m_haveLines = false;
  size_t m_next = 0;
};

}  // namespace

bool parseFiniteDouble(const std::string& text, double& value) {
  const std::string s = trim(text);
  if (!isDecimalNumber(s)) return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(value);
}

bool parseStrictInt(const std::string& text, int& value) {
  const std::string s = trim(text);
  size_t i = (!s.empty() && (s[0] == '+' || s[0] == '-')) ? 1 : 0;
  if (i == s.size()) return false;
  for (size_t k = i; k < s.size(); ++k)
    if (!std::isdigit(static_cast<unsigned char>(s[k]))) return false;
  errno = 0;
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (errno == ERANGE || v < INT_MIN || v > INT_MAX) return false;
  value = static_cast<int>(v);
  return true;
}

Teuchos::RCP<Teuchos::ParameterList> readCaseText(const std::string& input, const std::string& source) {
  // A UTF-8 byte-order mark (editors on some systems write one): Teuchos' parser refuses it.
  std::string text = input;
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
  Teuchos::XMLObject root;
  try {
    root = Teuchos::StringInputSource(text).getObject();
  } catch (const std::exception& e) {
    throw InputError("case file '" + source + "' is not a valid XML parameter list: " + e.what());
  }
  if (root.getTag() != "ParameterList")
    throw InputError("case file '" + source + "' is not a valid XML parameter list: its root element is <" +
                     root.getTag() + ">, not <ParameterList>");
  CaseChecker(source, text).check(root);
  try {
    return Teuchos::getParametersFromXmlString(text);
  } catch (const std::exception& e) {
    throw InputError("case file '" + source + "' is not a valid XML parameter list: " + e.what());
  }
}

namespace {

constexpr const char* kReplaceBase = "Replace Base";

/// `derived` over `base`: an entry of `derived` replaces the base's, a sublist merges into the
/// base's sublist of that name — or replaces it whole when it has `Replace Base = true`.
void overlay(Teuchos::ParameterList& base, const Teuchos::ParameterList& derived) {
  for (auto it = derived.begin(); it != derived.end(); ++it) {
    const std::string& name = derived.name(it);
    if (derived.isSublist(name)) {
      Teuchos::ParameterList own = derived.sublist(name);
      const bool replace = own.isType<bool>(kReplaceBase) && own.get<bool>(kReplaceBase);
      own.remove(kReplaceBase, false);
      if (replace || !base.isSublist(name)) {
        if (base.isParameter(name)) base.remove(name);
        base.set(name, own);
      } else {
        overlay(base.sublist(name), own);
      }
    } else {
      base.setEntry(name, derived.entry(it));
    }
  }
}

Teuchos::RCP<Teuchos::ParameterList> readCaseFileFrom(const std::string& path, std::vector<std::string>& chain) {
  std::string bytes;
  if (!readWholeFile(path, bytes)) throw InputError("case file '" + path + "' cannot be read");
  Teuchos::RCP<Teuchos::ParameterList> params = readCaseText(bytes, path);
  if (!params->isParameter("Base Case")) return params;
  if (!params->isType<std::string>("Base Case"))
    throw InputError("case file '" + path + "': 'Base Case' must be a string (the case file this one changes)");
  const std::filesystem::path base =
      (std::filesystem::path(path).parent_path() / params->get<std::string>("Base Case")).lexically_normal();
  for (const std::string& seen : chain)
    if (seen == base.string()) throw InputError("case file '" + path + "': 'Base Case' '" + base.string() +
                                                "' includes itself (through " + chain.front() + ")");
  if (!std::filesystem::path(base).has_parent_path() || !std::filesystem::exists(base))
    throw InputError("case file '" + path + "': its Base Case '" + base.string() + "' does not exist");
  chain.push_back(base.string());
  Teuchos::RCP<Teuchos::ParameterList> merged = readCaseFileFrom(base.string(), chain);
  params->remove("Base Case");
  overlay(*merged, *params);
  return merged;
}

}  // namespace

Teuchos::RCP<Teuchos::ParameterList> readCaseFile(const std::string& path) {
  std::vector<std::string> chain{std::filesystem::path(path).lexically_normal().string()};
  return readCaseFileFrom(path, chain);
}

}  // namespace flowform
